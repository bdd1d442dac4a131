// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/dicom/ExportObjects.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcitem.h>
#include <dcmtk/dcmdata/dcsequen.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>

#include <cstddef>
#include <string>
#include <vector>

#include "ExportModules.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/dicom/Uid.h"

namespace vv::dicom {

namespace {

using namespace detail;

/// Patient, General Study, General Series (parts), General / SC Equipment and
/// SOP Common: what both instances share.
void putCommon(DcmDataset& data, const std::filesystem::path& path, const char* sopClass,
               const std::string& sopInstance, const std::string& modality,
               const ExportStudy& study, const ExportSeries& series) {
    put(data, DCM_SpecificCharacterSet, "ISO_IR 192", path);  // UTF-8
    put(data, DCM_SOPClassUID, sopClass, path);
    put(data, DCM_SOPInstanceUID, sopInstance, path);
    putUnlessAnonymised(data, DCM_InstanceCreationDate, series.creationDate, path, study);
    putUnlessAnonymised(data, DCM_InstanceCreationTime, series.creationTime, path, study);

    putPatientAndStudy(data, path, study);

    // General Series.
    put(data, DCM_Modality, modality, path);
    put(data, DCM_SeriesInstanceUID, newUid(), path);
    put(data, DCM_SeriesNumber, std::to_string(series.seriesNumber), path);
    put(data, DCM_SeriesDescription, series.description, path);
    putUnlessAnonymised(data, DCM_SeriesDate, series.contentDate, path, study);
    putUnlessAnonymised(data, DCM_SeriesTime, series.contentTime, path, study);

    // General Equipment and SC Equipment (WSD: workstation).
    put(data, DCM_Manufacturer, "VesselView", path);
    put(data, DCM_SoftwareVersions, series.softwareVersion, path);
    put(data, DCM_ConversionType, "WSD", path);

    put(data, DCM_InstanceNumber, "1", path);
    putOrEmpty(data, DCM_ContentDate, series.contentDate, path, study);
    putOrEmpty(data, DCM_ContentTime, series.contentTime, path, study);
}

}  // namespace

std::string writeSecondaryCapture(const std::filesystem::path& path, const RgbImage& image,
                                  const ExportStudy& study, const ExportSeries& series) {
    if (image.width < 1 || image.height < 1 || image.width > 65535 || image.height > 65535) {
        throw InvalidArgumentError(path,
                                   "Secondary Capture: the image must be 1..65535 pixels "
                                   "per side");
    }
    const auto width = static_cast<std::size_t>(image.width);
    const auto height = static_cast<std::size_t>(image.height);
    if (image.pixels.size() != width * height * 3) {
        throw InvalidArgumentError(path, "Secondary Capture: the image has " +
                                             std::to_string(image.pixels.size()) +
                                             " bytes, not 3 per pixel");
    }
    // OB / OW must have an even length.
    std::vector<Uint8> pixels(image.pixels.begin(), image.pixels.end());
    if (pixels.size() % 2 != 0) {
        pixels.push_back(0);
    }

    DcmFileFormat file;
    DcmDataset& data = *file.getDataset();
    const std::string sopInstance = newUid();
    putCommon(data, path, UID_SecondaryCaptureImageStorage, sopInstance, "OT", study, series);
    // General Series (Laterality: type 2C, empty: not a paired structure),
    // General Image, SC Image.
    put(data, DCM_Laterality, "", path);
    put(data, DCM_PatientOrientation, "", path);
    put(data, DCM_ImageType, "DERIVED\\SECONDARY", path);
    put(data, DCM_BurnedInAnnotation, "NO", path);
    put(data, DCM_LossyImageCompression, "00", path);
    putUnlessAnonymised(data, DCM_DateOfSecondaryCapture, series.contentDate, path, study);
    putUnlessAnonymised(data, DCM_TimeOfSecondaryCapture, series.contentTime, path, study);
    // Image Pixel: 8-bit RGB, interleaved.
    const auto u16 = [&](const DcmTagKey& tag, unsigned value) {
        if (data.putAndInsertUint16(tag, static_cast<Uint16>(value)).bad()) {
            throw IoError(path, "cannot set the image pixel attributes");
        }
    };
    u16(DCM_SamplesPerPixel, 3);
    put(data, DCM_PhotometricInterpretation, "RGB", path);
    u16(DCM_PlanarConfiguration, 0);
    u16(DCM_Rows, static_cast<unsigned>(height));
    u16(DCM_Columns, static_cast<unsigned>(width));
    u16(DCM_BitsAllocated, 8);
    u16(DCM_BitsStored, 8);
    u16(DCM_HighBit, 7);
    u16(DCM_PixelRepresentation, 0);
    if (data.putAndInsertUint8Array(DCM_PixelData, pixels.data(),
                                    static_cast<unsigned long>(pixels.size()))
            .bad()) {
        throw IoError(path, "cannot set the pixel data");
    }
    save(file, path);
    return sopInstance;
}

std::string writeEncapsulatedPdf(const std::filesystem::path& path, std::string_view pdf,
                                 const std::string& title, const ExportStudy& study,
                                 const ExportSeries& series) {
    if (pdf.substr(0, 5) != "%PDF-") {
        throw InvalidArgumentError(path, "Encapsulated PDF: the document is not a PDF");
    }
    DcmFileFormat file;
    DcmDataset& data = *file.getDataset();
    const std::string sopInstance = newUid();
    putCommon(data, path, UID_EncapsulatedPDFStorage, sopInstance, "DOC", study, series);
    // Encapsulated Document module.
    putOrEmpty(data, DCM_AcquisitionDateTime, series.contentDate + series.contentTime, path, study);
    // The PDF shows the patient block unless there is none or it is anonymised.
    const bool identifies = study.patient && !study.patient->anonymise;
    put(data, DCM_BurnedInAnnotation, identifies ? "YES" : "NO", path);
    if (data.insertEmptyElement(DCM_ConceptNameCodeSequence).bad()) {
        throw IoError(path, "cannot set the concept name");
    }
    put(data, DCM_DocumentTitle, title, path);
    put(data, DCM_MIMETypeOfEncapsulatedDocument, "application/pdf", path);
    // OB must have an even length: pad with one NUL and record the real length.
    std::vector<Uint8> bytes(pdf.begin(), pdf.end());
    if (bytes.size() % 2 != 0) {
        bytes.push_back(0);
    }
    if (data.putAndInsertUint32(DCM_EncapsulatedDocumentLength, static_cast<Uint32>(pdf.size()))
            .bad() ||
        data.putAndInsertUint8Array(DCM_EncapsulatedDocument, bytes.data(),
                                    static_cast<unsigned long>(bytes.size()))
            .bad()) {
        throw IoError(path, "cannot set the encapsulated document");
    }
    save(file, path);
    return sopInstance;
}

}  // namespace vv::dicom
