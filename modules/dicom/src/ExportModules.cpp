// SPDX-License-Identifier: GPL-3.0-or-later
#include "ExportModules.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcitem.h>
#include <dcmtk/dcmdata/dcxfer.h>

#include <string>

#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"

namespace vv::dicom::detail {

namespace {

/// De-identification Method Code Sequence: one item, the basic profile (DCM 113100).
void putDeidentificationCode(DcmDataset& data, const std::filesystem::path& path) {
    auto* item = new DcmItem();  // owned by the sequence once inserted
    const bool ok =
        item->putAndInsertString(DCM_CodeValue, "113100").good() &&
        item->putAndInsertString(DCM_CodingSchemeDesignator, "DCM").good() &&
        item->putAndInsertString(DCM_CodeMeaning, "Basic Application Confidentiality Profile")
            .good();
    if (!ok || data.insertSequenceItem(DCM_DeidentificationMethodCodeSequence, item).bad()) {
        delete item;  // NOLINT(cppcoreguidelines-owning-memory): not inserted
        throw IoError(path, "cannot set the de-identification method code");
    }
}

}  // namespace

void put(DcmDataset& data, const DcmTagKey& tag, const std::string& value,
         const std::filesystem::path& path) {
    const OFCondition status = data.putAndInsertOFStringArray(tag, OFString(value.c_str()));
    if (status.bad()) {
        throw IoError(path, std::string("cannot set DICOM attribute ") + DcmTag(tag).getTagName() +
                                ": " + status.text());
    }
}

bool anonymised(const ExportStudy& study) {
    return study.patient && study.patient->anonymise;
}

/// Puts `value`, or nothing when anonymising: for type 3 attributes that the
/// basic confidentiality profile removes (dates and times of the instance).
void putUnlessAnonymised(DcmDataset& data, const DcmTagKey& tag, const std::string& value,
                         const std::filesystem::path& path, const ExportStudy& study) {
    if (!anonymised(study)) {
        put(data, tag, value, path);
    }
}

/// Puts `value`, or an empty value when anonymising (type 2 attributes).
void putOrEmpty(DcmDataset& data, const DcmTagKey& tag, const std::string& value,
                const std::filesystem::path& path, const ExportStudy& study) {
    put(data, tag, anonymised(study) ? std::string() : value, path);
}

void putPatientAndStudy(DcmDataset& data, const std::filesystem::path& path,
                        const ExportStudy& study) {
    // Patient module: type 2 attributes present, empty when not known or anonymised.
    const bool known = study.patient && !study.patient->anonymise;
    const auto field = [&](const std::string ExportPatient::*member) {
        return known ? (*study.patient).*member : std::string();
    };
    put(data, DCM_PatientName, field(&ExportPatient::name), path);
    put(data, DCM_PatientID, field(&ExportPatient::id), path);
    put(data, DCM_PatientBirthDate, field(&ExportPatient::birthDate), path);
    put(data, DCM_PatientSex, field(&ExportPatient::sex), path);
    if (anonymised(study)) {
        put(data, DCM_PatientIdentityRemoved, "YES", path);
        put(data, DCM_DeidentificationMethod, "DICOM PS3.15 E.1 Basic Profile (VesselView)", path);
        putDeidentificationCode(data, path);
        put(data, DCM_LongitudinalTemporalInformationModified, "REMOVED", path);
    }

    // General Study. Anonymised: no dates, no study ID (the profile's Z and Z);
    // the caller gives a pseudonymous Study Instance UID.
    put(data, DCM_StudyInstanceUID, study.studyInstanceUid, path);
    putOrEmpty(data, DCM_StudyDate, study.studyDate, path, study);
    putOrEmpty(data, DCM_StudyTime, study.studyTime, path, study);
    put(data, DCM_ReferringPhysicianName, field(&ExportPatient::referringPhysician), path);
    putOrEmpty(data, DCM_StudyID, study.studyId, path, study);
    put(data, DCM_AccessionNumber, field(&ExportPatient::accession), path);
}

void save(DcmFileFormat& file, const std::filesystem::path& path) {
    writeAtomically(path, [&](const std::filesystem::path& temporary) {
        const OFCondition status =
            file.saveFile(OFFilename(temporary.c_str()), EXS_LittleEndianExplicit,
                          EET_ExplicitLength, EGL_recalcGL, EPD_noChange, 0, 0, EWM_fileformat);
        if (status.bad()) {
            throw IoError(path, std::string("cannot write the DICOM file: ") + status.text());
        }
    });
}

}  // namespace vv::dicom::detail
