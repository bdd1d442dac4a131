// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/dicom/MeasurementReport.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmsr/cmr/init.h>
#include <dcmtk/dcmsr/cmr/tid1500.h>
#include <dcmtk/dcmsr/codes/dcm.h>
#include <dcmtk/dcmsr/dsrdoc.h>

#include <cmath>
#include <mutex>
#include <set>
#include <string>

#include "ExportModules.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/dicom/Uid.h"

namespace vv::dicom {

namespace sr {
SrCode diameter() {
    return {"81827009", "SCT", "Diameter"};
}
SrCode area() {
    return {"42798000", "SCT", "Area"};
}
SrCode pathLength() {
    return {"121211", "DCM", "Path length"};
}
SrCode distance() {
    return {"121206", "DCM", "Distance"};
}
SrCode angle() {
    return {"110859", "DCM", "Angle"};
}
SrCode minimum() {
    return {"255605001", "SCT", "Minimum"};
}
SrCode maximum() {
    return {"56851009", "SCT", "Maximum"};
}
SrCode millimetre() {
    return {"mm", "UCUM", "millimeter"};
}
SrCode squareMillimetre() {
    return {"mm2", "UCUM", "square millimeter"};
}
SrCode degree() {
    return {"deg", "UCUM", "degree"};
}
}  // namespace sr

namespace {

using detail::put;

/// The Content Mapping Resource's code lists are built on first use, which
/// is not thread-safe: built once, up front.
void initialiseCodeLists() {
    static std::once_flag once;
    std::call_once(once, [] { CMR_ContentMappingResource::initializeAllContextGroups(); });
}

DSRCodedEntryValue coded(const SrCode& code, const std::filesystem::path& path) {
    if (code.value.empty() || code.scheme.empty() || code.meaning.empty()) {
        throw InvalidArgumentError(path, "measurement report: a code is empty (\"" + code.value +
                                             "\", \"" + code.scheme + "\", \"" + code.meaning +
                                             "\")");
    }
    return {code.value, code.scheme, code.meaning};
}

void check(const OFCondition& status, const std::filesystem::path& path, const std::string& what) {
    if (status.bad()) {
        throw IoError(path, "measurement report: cannot " + what + ": " + status.text());
    }
}

void validate(const MeasurementReportContent& content, const std::filesystem::path& path) {
    if (content.groups.empty()) {
        throw InvalidArgumentError(path, "measurement report: there are no measurements");
    }
    std::set<std::string> ids;
    for (const SrGroup& group : content.groups) {
        if (group.trackingId.empty() || group.trackingId.size() > 64) {
            throw InvalidArgumentError(path,
                                       "measurement report: a group's tracking identifier must "
                                       "have 1 to 64 characters, not " +
                                           std::to_string(group.trackingId.size()));
        }
        if (!ids.insert(group.trackingId).second) {
            throw InvalidArgumentError(path, "measurement report: the tracking identifier \"" +
                                                 group.trackingId + "\" is used twice");
        }
        if (group.numbers.empty()) {
            throw InvalidArgumentError(
                path, "measurement report: \"" + group.trackingId + "\" has no measurements");
        }
        for (const SrNumber& number : group.numbers) {
            if (!std::isfinite(number.value)) {
                throw InvalidArgumentError(path, "measurement report: a value of \"" +
                                                     group.trackingId + "\" is not a number");
            }
        }
    }
}

/// A DS value (at most 16 characters): three decimals, fewer for large values.
std::string decimalString(double value) {
    for (int digits = 3; digits >= 0; --digits) {
        std::string text = fixedText(value, digits);
        if (text.size() <= 16) {
            return text;
        }
    }
    return fixedText(value, 0).substr(0, 16);
}

CID100_QuantitativeDiagnosticImagingProcedures procedureFor(const std::string& modality) {
    if (modality == "CT") {
        return CMR_CID100::CTUnspecifiedBodyRegion;
    }
    if (modality == "MR") {
        return CMR_CID100::MRIUnspecifiedBodyRegion;
    }
    return CMR_CID100::ImagingProcedure;
}

void addGroup(TID1500_MeasurementReport& report, const SrGroup& group, bool first,
              const std::filesystem::path& path) {
    if (!first) {
        check(report.addIndividualMeasurements(), path, "add a measurement group");
    }
    auto& measurements = report.getIndividualMeasurements();
    check(measurements.setTrackingIdentifier(group.trackingId), path,
          "set the tracking identifier \"" + group.trackingId + "\"");
    check(measurements.setTrackingUniqueIdentifier(newUid()), path, "set a tracking UID");
    if (group.findingSite) {
        check(measurements.addFindingSite(coded(*group.findingSite, path)), path,
              "set the finding site");
    }
    for (const SrNumber& number : group.numbers) {
        // The units and concepts here extend the context groups (degree is
        // not in CID 7181): extensible groups, set unchecked.
        const CMR_TID1501_in_TID1500::MeasurementValue value(
            decimalString(number.value),
            CID7181_AbstractMultiDimensionalImageModelComponentUnits(coded(number.unit, path)),
            OFFalse);
        check(measurements.addMeasurement(
                  CID7469_GenericIntensityAndSizeMeasurements(coded(number.name, path)), value,
                  OFTrue, OFFalse),
              path, "add the measurement \"" + number.name.meaning + "\"");
        auto& measurement = measurements.getMeasurement();
        if (number.derivation) {
            check(measurement.setDerivation(CID7464_GeneralRegionOfInterestMeasurementModifiers(
                                                coded(*number.derivation, path)),
                                            OFFalse),
                  path, "set a derivation");
        }
        if (!number.meaning.empty()) {
            check(measurement.setEquivalentMeaningOfConceptName(number.meaning, OFFalse), path,
                  "set a measurement's meaning");
        }
    }
}

}  // namespace

std::vector<SrSourceInstance> readSourceInstances(const std::vector<std::filesystem::path>& files) {
    std::vector<SrSourceInstance> instances;
    instances.reserve(files.size());
    for (const std::filesystem::path& file : files) {
        DcmFileFormat format;
        const OFCondition status =
            format.loadFileUntilTag(OFFilename(file.c_str()), EXS_Unknown, EGL_noChange,
                                    DCM_MaxReadLength, ERM_autoDetect, DCM_PixelData);
        if (status.bad()) {
            throw IoError(file, std::string("cannot read the DICOM header: ") + status.text());
        }
        OFString sopClass;
        OFString sopInstance;
        format.getDataset()->findAndGetOFString(DCM_SOPClassUID, sopClass);
        format.getDataset()->findAndGetOFString(DCM_SOPInstanceUID, sopInstance);
        if (sopClass.empty() || sopInstance.empty()) {
            throw FormatError(file, "the DICOM file has no SOP Class or Instance UID");
        }
        instances.push_back({sopClass, sopInstance});
    }
    return instances;
}

std::string writeMeasurementReport(const std::filesystem::path& path,
                                   const MeasurementReportContent& content,
                                   const ExportStudy& study, const ExportSeries& series) {
    validate(content, path);
    initialiseCodeLists();
    TID1500_MeasurementReport report(CMR_CID7021::ImagingMeasurementReport);
    check(report.setLanguage(CID5000_Languages::English), path, "set the language");
    check(report.getObservationContext().addDeviceObserver(newUid(), "VesselView", "VesselView",
                                                           "VesselView"),
          path, "set the observer");
    check(report.addProcedureReported(procedureFor(content.sourceModality)), path,
          "set the procedure reported");
    for (std::size_t i = 0; i < content.groups.size(); ++i) {
        addGroup(report, content.groups[i], i == 0, path);
    }
    if (!report.isValid()) {
        throw IoError(path, "measurement report: the TID 1500 content is not complete");
    }

    DSRDocument document;
    check(document.setTreeFromRootTemplate(report, OFTrue /* expanded: written out */), path,
          "set the content");
    check(document.setSpecificCharacterSet("ISO_IR 192"), path, "set the character set");
    check(document.createNewSeriesInStudy(study.studyInstanceUid), path, "set the study");
    check(document.setSeriesDescription(series.description), path, "set the series description");
    check(document.setSeriesNumber(std::to_string(series.seriesNumber)), path,
          "set the series number");
    check(document.setManufacturer("VesselView"), path, "set the manufacturer");
    check(document.setInstanceNumber("1"), path, "set the instance number");
    for (const SrSourceInstance& source : content.sourceInstances) {
        check(document.getCurrentRequestedProcedureEvidence().addItem(
                  study.studyInstanceUid, content.sourceSeriesUid, source.sopClassUid,
                  source.sopInstanceUid),
              path, "list the source instance " + source.sopInstanceUid);
    }
    check(document.completeDocument(), path, "complete the document");

    DcmFileFormat file;
    DcmDataset& data = *file.getDataset();
    check(document.write(data), path, "write the document");
    detail::putPatientAndStudy(data, path, study);
    const bool anonymise = detail::anonymised(study);
    // Content Date / Time are type 1 in an SR: the document's own (now) unless
    // given, a dummy when anonymising (the profile's D), as Instance
    // Creation's are left out (X).
    if (anonymise) {
        put(data, DCM_ContentDate, "19000101", path);
        put(data, DCM_ContentTime, "000000", path);
        data.findAndDeleteElement(DCM_InstanceCreationDate);
        data.findAndDeleteElement(DCM_InstanceCreationTime);
    } else {
        const auto putGiven = [&](const DcmTagKey& tag, const std::string& value) {
            if (!value.empty()) {
                put(data, tag, value, path);
            }
        };
        putGiven(DCM_ContentDate, series.contentDate);
        putGiven(DCM_ContentTime, series.contentTime);
        putGiven(DCM_InstanceCreationDate, series.creationDate);
        putGiven(DCM_InstanceCreationTime, series.creationTime);
        putGiven(DCM_SeriesDate, series.contentDate);
        putGiven(DCM_SeriesTime, series.contentTime);
    }
    if (!series.softwareVersion.empty()) {
        put(data, DCM_SoftwareVersions, series.softwareVersion, path);
    }
    OFString sopInstance;
    document.getSOPInstanceUID(sopInstance);
    detail::save(file, path);
    return sopInstance;
}

}  // namespace vv::dicom
