// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/report/DicomExport.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcitem.h>
#include <dcmtk/dcmdata/dcsequen.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>

#include <QByteArray>
#include <QCryptographicHash>
#include <QLocale>
#include <QPainter>
#include <QTimeZone>
#include <array>
#include <cstdint>
#include <cstring>
#include <random>
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

bool anonymised(const DicomStudy& study) {
    return study.patient && study.patient->anonymise;
}

/// Puts `value`, or nothing when anonymising: for type 3 attributes that the
/// basic confidentiality profile removes (dates and times of the instance).
void putUnlessAnonymised(DcmDataset& data, const DcmTagKey& tag, const std::string& value,
                         const std::filesystem::path& path, const DicomStudy& study) {
    if (!anonymised(study)) {
        put(data, tag, value, path);
    }
}

/// Puts `value`, or an empty value when anonymising (type 2 attributes).
void putOrEmpty(DcmDataset& data, const DcmTagKey& tag, const std::string& value,
                const std::filesystem::path& path, const DicomStudy& study) {
    put(data, tag, anonymised(study) ? std::string() : value, path);
}

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

/// Patient, General Study, General Series (parts), General / SC Equipment and
/// SOP Common: what both instances share.
void putCommon(DcmDataset& data, const std::filesystem::path& path, const char* sopClass,
               const std::string& sopInstance, const std::string& modality, const DicomStudy& study,
               const DicomSeries& series) {
    put(data, DCM_SpecificCharacterSet, "ISO_IR 192", path);  // UTF-8
    put(data, DCM_SOPClassUID, sopClass, path);
    put(data, DCM_SOPInstanceUID, sopInstance, path);
    const QDateTime now = QDateTime::currentDateTime();
    putUnlessAnonymised(data, DCM_InstanceCreationDate, dicomDate(now), path, study);
    putUnlessAnonymised(data, DCM_InstanceCreationTime, dicomTime(now), path, study);

    // Patient module: type 2 attributes present, empty when not known or anonymised.
    const bool known = study.patient && !study.patient->anonymise;
    const auto field = [&](const std::string ReportPatient::*member) {
        return known ? (*study.patient).*member : std::string();
    };
    put(data, DCM_PatientName, field(&ReportPatient::name), path);
    put(data, DCM_PatientID, field(&ReportPatient::id), path);
    put(data, DCM_PatientBirthDate, field(&ReportPatient::birthDate), path);
    put(data, DCM_PatientSex, field(&ReportPatient::sex), path);
    if (anonymised(study)) {
        put(data, DCM_PatientIdentityRemoved, "YES", path);
        put(data, DCM_DeidentificationMethod, "DICOM PS3.15 E.1 Basic Profile (VesselView)", path);
        putDeidentificationCode(data, path);
        put(data, DCM_LongitudinalTemporalInformationModified, "REMOVED", path);
    }

    // General Study. Anonymised: a pseudonymous Study Instance UID, no dates,
    // no study ID (the profile's U, Z and Z).
    put(data, DCM_StudyInstanceUID,
        anonymised(study) ? anonymisedUid(study.studyInstanceUid) : study.studyInstanceUid, path);
    const bool sourceDate = !study.studyDate.empty();
    putOrEmpty(data, DCM_StudyDate, sourceDate ? study.studyDate : dicomDate(study.studyDateTime),
               path, study);
    putOrEmpty(data, DCM_StudyTime, sourceDate ? study.studyTime : dicomTime(study.studyDateTime),
               path, study);
    put(data, DCM_ReferringPhysicianName, field(&ReportPatient::referringPhysician), path);
    putOrEmpty(data, DCM_StudyID, study.studyId, path, study);
    put(data, DCM_AccessionNumber, field(&ReportPatient::accession), path);

    // General Series.
    put(data, DCM_Modality, modality, path);
    put(data, DCM_SeriesInstanceUID, newDicomUid(), path);
    put(data, DCM_SeriesNumber, std::to_string(series.seriesNumber), path);
    put(data, DCM_SeriesDescription, series.description, path);
    putUnlessAnonymised(data, DCM_SeriesDate, dicomDate(series.contentDateTime), path, study);
    putUnlessAnonymised(data, DCM_SeriesTime, dicomTime(series.contentDateTime), path, study);

    // General Equipment and SC Equipment (WSD: workstation).
    put(data, DCM_Manufacturer, "VesselView", path);
    put(data, DCM_SoftwareVersions, std::string(vv::kVersion), path);
    put(data, DCM_ConversionType, "WSD", path);

    put(data, DCM_InstanceNumber, "1", path);
    putOrEmpty(data, DCM_ContentDate, dicomDate(series.contentDateTime), path, study);
    putOrEmpty(data, DCM_ContentTime, dicomTime(series.contentDateTime), path, study);
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

std::string anonymisedUid(const std::string& uid) {
    // 16 random bytes, drawn once per process: the same source UID maps to the
    // same pseudonym within one run, and to unrelated ones in different runs.
    static const QByteArray salt = [] {
        std::random_device device;
        QByteArray bytes;
        for (int i = 0; i < 4; ++i) {
            const auto word = static_cast<std::uint32_t>(device());
            bytes.append(reinterpret_cast<const char*>(&word), sizeof word);
        }
        return bytes;
    }();
    QCryptographicHash hash(QCryptographicHash::Sha256);
    hash.addData(salt);
    hash.addData(QByteArrayView(uid.data(), static_cast<qsizetype>(uid.size())));
    const QByteArray digest = hash.result();
    // PS3.5 B.2: "2.25." followed by a 128-bit integer in decimal: the first
    // 16 bytes of the digest (big-endian) divided by 10 until nothing is left.
    std::array<unsigned, 16> number{};
    for (std::size_t i = 0; i < number.size(); ++i) {
        number[i] = static_cast<std::uint8_t>(digest[static_cast<qsizetype>(i)]);
    }
    std::string digits;
    bool zero = false;
    while (!zero) {
        unsigned remainder = 0;
        zero = true;
        for (unsigned& byte : number) {
            const unsigned current = remainder * 256U + byte;
            byte = current / 10U;
            remainder = current % 10U;
            zero = zero && byte == 0U;
        }
        digits.insert(digits.begin(), static_cast<char>('0' + remainder));
    }
    return "2.25." + digits;
}

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
    putUnlessAnonymised(data, DCM_DateOfSecondaryCapture, dicomDate(series.contentDateTime), path,
                        study);
    putUnlessAnonymised(data, DCM_TimeOfSecondaryCapture, dicomTime(series.contentDateTime), path,
                        study);
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
    putOrEmpty(data, DCM_AcquisitionDateTime,
               QLocale::c()
                   .toString(series.contentDateTime, QStringLiteral("yyyyMMddHHmmss"))
                   .toStdString(),
               path, study);
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
