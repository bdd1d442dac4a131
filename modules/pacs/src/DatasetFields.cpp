// SPDX-License-Identifier: GPL-3.0-or-later
#include "DatasetFields.h"

#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>

#include <system_error>

#include "vv/core/Error.h"

namespace vv::pacs::detail {

namespace {

std::string text(DcmDataset& ds, const DcmTagKey& tag) {
    OFString value;
    if (ds.findAndGetOFStringArray(tag, value).bad()) {
        return {};
    }
    return std::string(value.c_str(), value.length());
}

}  // namespace

InstanceFields fieldsOf(DcmDataset& ds) {
    InstanceFields f;
    f.sopInstanceUid = text(ds, DCM_SOPInstanceUID);
    f.studyInstanceUid = text(ds, DCM_StudyInstanceUID);
    f.seriesInstanceUid = text(ds, DCM_SeriesInstanceUID);
    f.patientName = text(ds, DCM_PatientName);
    f.patientId = text(ds, DCM_PatientID);
    f.studyDate = text(ds, DCM_StudyDate);
    f.studyDescription = text(ds, DCM_StudyDescription);
    f.accessionNumber = text(ds, DCM_AccessionNumber);
    f.modality = text(ds, DCM_Modality);
    f.seriesDescription = text(ds, DCM_SeriesDescription);
    Sint32 number = -1;
    if (ds.findAndGetSint32(DCM_SeriesNumber, number).good()) {
        f.seriesNumber = number;
    }
    return f;
}

InstanceFields fieldsOfFile(const std::filesystem::path& path, const std::string& sopInstanceUid,
                            const std::string& sopClassUid) {
    DcmFileFormat file;
    const OFCondition cond = file.loadFile(path.c_str());  // values over 4 kB stay on disk
    if (cond.bad()) {
        throw FormatError(path, std::string("not a readable DICOM dataset: ") + cond.text());
    }
    DcmDataset& dataset = *file.getDataset();
    InstanceFields fields = fieldsOf(dataset);
    if (fields.sopInstanceUid != sopInstanceUid) {
        throw FormatError(path,
                          "its SOP Instance UID is not the one its C-STORE request announced");
    }
    if (text(dataset, DCM_SOPClassUID) != sopClassUid) {
        throw FormatError(path, "its SOP Class UID is not the one its C-STORE request announced");
    }
    return fields;
}

void writeInstance(DcmDataset& dataset, const std::filesystem::path& path) {
    E_TransferSyntax xfer = dataset.getOriginalXfer();
    if (xfer == EXS_Unknown || xfer == EXS_LittleEndianImplicit) {
        xfer = EXS_LittleEndianExplicit;
    }
    DcmFileFormat file(&dataset, OFTrue);
    const OFCondition cond = file.saveFile(path.c_str(), xfer);
    if (cond.bad()) {
        std::error_code ec;
        std::filesystem::remove(path, ec);
        throw IoError(path, std::string("cannot write the received instance: ") + cond.text());
    }
    std::error_code ec;
    std::filesystem::permissions(
        path, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write,
        std::filesystem::perm_options::replace, ec);
}

const std::vector<const char*>& usableStorageClasses() {
    static const std::vector<const char*> classes = {
        UID_CTImageStorage,
        UID_EnhancedCTImageStorage,
        UID_MRImageStorage,
        UID_EnhancedMRImageStorage,
        UID_XRayAngiographicImageStorage,
        UID_SecondaryCaptureImageStorage,
        UID_EncapsulatedPDFStorage,
        UID_SegmentationStorage,
        UID_EnhancedSRStorage,  // the planning measurements (TID 1500)
    };
    return classes;
}

const std::vector<const char*>& receivableTransferSyntaxes() {
    static const std::vector<const char*> syntaxes = {
        UID_LittleEndianExplicitTransferSyntax, UID_LittleEndianImplicitTransferSyntax,
        UID_JPEGProcess14SV1TransferSyntax,     UID_JPEGLSLosslessTransferSyntax,
        UID_RLELosslessTransferSyntax,
    };
    return syntaxes;
}

}  // namespace vv::pacs::detail
