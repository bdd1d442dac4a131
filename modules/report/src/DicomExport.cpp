// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/report/DicomExport.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>

#include <QLocale>
#include <QPainter>
#include <QTimeZone>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "vv/Version.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"

namespace vv::report {

namespace {

std::string dicomDate(const QDateTime& t) {
    return QLocale::c().toString(t, QStringLiteral("yyyyMMdd")).toStdString();
}
std::string dicomTime(const QDateTime& t) {
    return QLocale::c().toString(t, QStringLiteral("HHmmss")).toStdString();
}

void put(DcmDataset& data, const DcmTagKey& tag, const std::string& value,
         const std::filesystem::path& path) {
    const OFCondition status = data.putAndInsertOFStringArray(tag, OFString(value.c_str()));
    if (status.bad()) {
        throw IoError(path, std::string("cannot set DICOM attribute ") + DcmTag(tag).getTagName() +
                                ": " + status.text());
    }
}

/// Patient, General Study, General Series (parts), General / SC Equipment and
/// SOP Common: what both instances share.
void putCommon(DcmDataset& data, const std::filesystem::path& path, const char* sopClass,
               const std::string& sopInstance, const std::string& modality, const DicomStudy& study,
               const DicomSeries& series) {
    put(data, DCM_SpecificCharacterSet, "ISO_IR 192", path);  // UTF-8
    put(data, DCM_SOPClassUID, sopClass, path);
    put(data, DCM_SOPInstanceUID, sopInstance, path);
    const QDateTime now = QDateTime::currentDateTime();
    put(data, DCM_InstanceCreationDate, dicomDate(now), path);
    put(data, DCM_InstanceCreationTime, dicomTime(now), path);

    // Patient module: type 2 attributes present, empty when not known or anonymised.
    const bool known = study.patient && !study.patient->anonymise;
    const auto field = [&](const std::string ReportPatient::*member) {
        return known ? (*study.patient).*member : std::string();
    };
    put(data, DCM_PatientName, field(&ReportPatient::name), path);
    put(data, DCM_PatientID, field(&ReportPatient::id), path);
    put(data, DCM_PatientBirthDate, field(&ReportPatient::birthDate), path);
    put(data, DCM_PatientSex, field(&ReportPatient::sex), path);
    if (study.patient && study.patient->anonymise) {
        put(data, DCM_PatientIdentityRemoved, "YES", path);
        put(data, DCM_DeidentificationMethod, "VesselView: patient identifiers removed", path);
    }

    // General Study.
    put(data, DCM_StudyInstanceUID, study.studyInstanceUid, path);
    const bool sourceDate = !study.studyDate.empty();
    put(data, DCM_StudyDate, sourceDate ? study.studyDate : dicomDate(study.studyDateTime), path);
    put(data, DCM_StudyTime, sourceDate ? study.studyTime : dicomTime(study.studyDateTime), path);
    put(data, DCM_ReferringPhysicianName, field(&ReportPatient::referringPhysician), path);
    put(data, DCM_StudyID, study.studyId, path);
    put(data, DCM_AccessionNumber, field(&ReportPatient::accession), path);

    // General Series.
    put(data, DCM_Modality, modality, path);
    put(data, DCM_SeriesInstanceUID, newDicomUid(), path);
    put(data, DCM_SeriesNumber, std::to_string(series.seriesNumber), path);
    put(data, DCM_SeriesDescription, series.description, path);
    put(data, DCM_SeriesDate, dicomDate(series.contentDateTime), path);
    put(data, DCM_SeriesTime, dicomTime(series.contentDateTime), path);

    // General Equipment and SC Equipment (WSD: workstation).
    put(data, DCM_Manufacturer, "VesselView", path);
    put(data, DCM_SoftwareVersions, std::string(vv::kVersion), path);
    put(data, DCM_ConversionType, "WSD", path);

    put(data, DCM_InstanceNumber, "1", path);
    put(data, DCM_ContentDate, dicomDate(series.contentDateTime), path);
    put(data, DCM_ContentTime, dicomTime(series.contentDateTime), path);
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

}  // namespace

std::string newDicomUid() {
    char uid[100] = {};
    dcmGenerateUniqueIdentifier(uid, SITE_INSTANCE_UID_ROOT);
    return uid;
}

DicomStudy newStudy() {
    DicomStudy study;
    study.studyInstanceUid = newDicomUid();
    study.studyDateTime = QDateTime::currentDateTime();
    return study;
}

std::string writeSecondaryCapture(const std::filesystem::path& path, const QImage& image,
                                  const DicomStudy& study, const DicomSeries& series) {
    if (image.isNull() || image.width() > 65535 || image.height() > 65535) {
        throw InvalidArgumentError(path,
                                   "Secondary Capture: the image must be 1..65535 pixels "
                                   "per side");
    }
    // Over black, as a DICOM viewer shows it.
    QImage rgb(image.size(), QImage::Format_RGB888);
    rgb.fill(Qt::black);
    {
        QPainter painter(&rgb);
        painter.drawImage(0, 0, image);
    }
    const auto width = static_cast<std::size_t>(rgb.width());
    const auto height = static_cast<std::size_t>(rgb.height());
    std::vector<Uint8> pixels(width * height * 3 + ((width * height * 3) % 2));
    for (std::size_t y = 0; y < height; ++y) {
        std::memcpy(pixels.data() + y * width * 3, rgb.constScanLine(static_cast<int>(y)),
                    width * 3);
    }

    DcmFileFormat file;
    DcmDataset& data = *file.getDataset();
    const std::string sopInstance = newDicomUid();
    putCommon(data, path, UID_SecondaryCaptureImageStorage, sopInstance, "OT", study, series);
    // General Series (Laterality: type 2C, empty: not a paired structure),
    // General Image, SC Image.
    put(data, DCM_Laterality, "", path);
    put(data, DCM_PatientOrientation, "", path);
    put(data, DCM_ImageType, "DERIVED\\SECONDARY", path);
    put(data, DCM_BurnedInAnnotation, "NO", path);
    put(data, DCM_LossyImageCompression, "00", path);
    put(data, DCM_DateOfSecondaryCapture, dicomDate(series.contentDateTime), path);
    put(data, DCM_TimeOfSecondaryCapture, dicomTime(series.contentDateTime), path);
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

std::string writeEncapsulatedPdf(const std::filesystem::path& path, const QByteArray& pdf,
                                 const std::string& title, const DicomStudy& study,
                                 const DicomSeries& series) {
    if (!pdf.startsWith("%PDF-")) {
        throw InvalidArgumentError(path, "Encapsulated PDF: the document is not a PDF");
    }
    DcmFileFormat file;
    DcmDataset& data = *file.getDataset();
    const std::string sopInstance = newDicomUid();
    putCommon(data, path, UID_EncapsulatedPDFStorage, sopInstance, "DOC", study, series);
    // Encapsulated Document module.
    put(data, DCM_AcquisitionDateTime,
        QLocale::c()
            .toString(series.contentDateTime, QStringLiteral("yyyyMMddHHmmss"))
            .toStdString(),
        path);
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

}  // namespace vv::report
