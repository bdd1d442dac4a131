// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/report/DicomExport.h"

#include <QByteArray>
#include <QCryptographicHash>
#include <QLocale>
#include <QPainter>
#include <array>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <string_view>

#include "vv/Version.h"
#include "vv/core/Error.h"
#include "vv/dicom/ExportObjects.h"
#include "vv/dicom/Uid.h"

namespace vv::report {

namespace {

std::string dicomDate(const QDateTime& t) {
    return QLocale::c().toString(t, QStringLiteral("yyyyMMdd")).toStdString();
}
std::string dicomTime(const QDateTime& t) {
    return QLocale::c().toString(t, QStringLiteral("HHmmss")).toStdString();
}

/// The study as the dicom module writes it: the source study's date when it
/// has one, a pseudonymous UID when anonymising.
dicom::ExportStudy exportStudy(const DicomStudy& study) {
    dicom::ExportStudy out;
    const bool anonymise = study.patient && study.patient->anonymise;
    out.studyInstanceUid =
        anonymise ? anonymisedUid(study.studyInstanceUid) : study.studyInstanceUid;
    out.studyId = study.studyId;
    const bool sourceDate = !study.studyDate.empty();
    out.studyDate = sourceDate ? study.studyDate : dicomDate(study.studyDateTime);
    out.studyTime = sourceDate ? study.studyTime : dicomTime(study.studyDateTime);
    if (study.patient) {
        const ReportPatient& p = *study.patient;
        out.patient = dicom::ExportPatient{
            p.name, p.id, p.birthDate, p.sex, p.accession, p.referringPhysician, p.anonymise};
    }
    return out;
}

dicom::ExportSeries exportSeries(const DicomSeries& series) {
    dicom::ExportSeries out;
    out.description = series.description;
    out.seriesNumber = series.seriesNumber;
    out.contentDate = dicomDate(series.contentDateTime);
    out.contentTime = dicomTime(series.contentDateTime);
    const QDateTime now = QDateTime::currentDateTime();
    out.creationDate = dicomDate(now);
    out.creationTime = dicomTime(now);
    out.softwareVersion = std::string(vv::kVersion);
    return out;
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
    return dicom::newUid();
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
    dicom::RgbImage pixels;
    pixels.width = rgb.width();
    pixels.height = rgb.height();
    const auto rowBytes = static_cast<std::size_t>(rgb.width()) * 3;
    pixels.pixels.resize(rowBytes * static_cast<std::size_t>(rgb.height()));
    for (int y = 0; y < rgb.height(); ++y) {
        std::memcpy(pixels.pixels.data() + static_cast<std::size_t>(y) * rowBytes,
                    rgb.constScanLine(y), rowBytes);
    }
    return dicom::writeSecondaryCapture(path, pixels, exportStudy(study), exportSeries(series));
}

std::string writeEncapsulatedPdf(const std::filesystem::path& path, const QByteArray& pdf,
                                 const std::string& title, const DicomStudy& study,
                                 const DicomSeries& series) {
    return dicom::writeEncapsulatedPdf(
        path, std::string_view(pdf.constData(), static_cast<std::size_t>(pdf.size())), title,
        exportStudy(study), exportSeries(series));
}

std::string writeMeasurementSr(const std::filesystem::path& path,
                               const dicom::MeasurementReportContent& content,
                               const DicomStudy& study, const DicomSeries& series) {
    return dicom::writeMeasurementReport(path, content, exportStudy(study), exportSeries(series));
}

}  // namespace vv::report
