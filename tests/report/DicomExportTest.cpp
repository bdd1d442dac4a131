// SPDX-License-Identifier: GPL-3.0-or-later
// DICOM Secondary Capture and Encapsulated PDF: read back with DCMTK, parsed
// by dcmdump (dcmtk) and checked by dciodvfy (dicom3tools; scripts/setup-deps).
#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <gtest/gtest.h>

#include <QPainter>
#include <filesystem>
#include <fstream>
#include <string>

#include "ReportTestUtil.h"
#include "vv/core/Error.h"
#include "vv/report/DicomExport.h"
#include "vv/report/DicomSource.h"

namespace vv::report {
namespace {

namespace fs = std::filesystem;

std::string get(DcmDataset& data, const DcmTagKey& tag) {
    OFString value;
    data.findAndGetOFStringArray(tag, value);
    return value.c_str();
}

bool has(DcmDataset& data, const DcmTagKey& tag) {
    return data.tagExists(tag);
}

/// dcmdump parses the file and dciodvfy reports no error.
void validate(const fs::path& file) {
    std::string output;
    EXPECT_EQ(test::runTool("dcmdump '" + file.string() + "' > /dev/null", output), 0)
        << "dcmdump (package dcmtk, scripts/setup-deps): " << output;
    test::runTool("dciodvfy '" + file.string() + "'", output);
    EXPECT_EQ(output.find("Error"), std::string::npos)
        << "dciodvfy (package dicom3tools, scripts/setup-deps):\n"
        << output;
    EXPECT_EQ(output.find("not found"), std::string::npos) << output;
}

class DicomExportTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { test::ensureGuiApplication(); }
};

TEST_F(DicomExportTest, SecondaryCaptureReadsBack) {
    const fs::path dir = test::testDir("dicom-sc");
    QImage image(7, 5, QImage::Format_RGB32);
    image.fill(qRgb(10, 20, 30));
    image.setPixel(6, 4, qRgb(200, 100, 50));
    DicomStudy study = newStudy();
    ReportPatient patient;
    patient.name = "Doe^Jane";
    patient.id = "PID-0042";
    patient.birthDate = "19600215";
    patient.sex = "F";
    patient.accession = "ACC-9";
    patient.referringPhysician = "Smith^John";
    study.patient = patient;
    const fs::path file = dir / "sc.dcm";
    const std::string sop = writeSecondaryCapture(file, image, study);

    DcmFileFormat format;
    ASSERT_TRUE(format.loadFile(OFFilename(file.c_str())).good());
    DcmDataset& data = *format.getDataset();
    EXPECT_EQ(get(data, DCM_SOPClassUID), UID_SecondaryCaptureImageStorage);
    EXPECT_EQ(get(data, DCM_SOPInstanceUID), sop);
    EXPECT_EQ(get(data, DCM_StudyInstanceUID), study.studyInstanceUid);
    EXPECT_NE(get(data, DCM_SeriesInstanceUID), study.studyInstanceUid);
    EXPECT_NE(get(data, DCM_SeriesInstanceUID), sop);
    EXPECT_EQ(get(data, DCM_Modality), "OT");
    EXPECT_EQ(get(data, DCM_ConversionType), "WSD");
    EXPECT_EQ(get(data, DCM_SeriesDescription), "VesselView report");
    EXPECT_EQ(get(data, DCM_PatientName), "Doe^Jane");
    EXPECT_EQ(get(data, DCM_PatientID), "PID-0042");
    EXPECT_EQ(get(data, DCM_AccessionNumber), "ACC-9");
    EXPECT_EQ(get(data, DCM_StudyDate).size(), 8U);
    EXPECT_EQ(get(data, DCM_PhotometricInterpretation), "RGB");
    Uint16 rows = 0;
    Uint16 columns = 0;
    data.findAndGetUint16(DCM_Rows, rows);
    data.findAndGetUint16(DCM_Columns, columns);
    EXPECT_EQ(rows, 5);
    EXPECT_EQ(columns, 7);
    const Uint8* pixels = nullptr;
    unsigned long count = 0;
    ASSERT_TRUE(data.findAndGetUint8Array(DCM_PixelData, pixels, &count).good());
    ASSERT_GE(count, 7UL * 5UL * 3UL);
    EXPECT_EQ(pixels[0], 10);
    EXPECT_EQ(pixels[1], 20);
    EXPECT_EQ(pixels[2], 30);
    const std::size_t last = (4 * 7 + 6) * 3;
    EXPECT_EQ(pixels[last], 200);
    EXPECT_EQ(pixels[last + 1], 100);
    EXPECT_EQ(pixels[last + 2], 50);
    validate(file);

    // The report PDF joins the same study in its own series.
    const QByteArray pdf("%PDF-1.4\n% minimal test body\n%%EOF\n");
    const fs::path doc = dir / "doc.dcm";
    (void)writeEncapsulatedPdf(doc, pdf, "Vessel tree report", study);
    DcmFileFormat docFormat;
    ASSERT_TRUE(docFormat.loadFile(OFFilename(doc.c_str())).good());
    EXPECT_EQ(get(*docFormat.getDataset(), DCM_StudyInstanceUID), study.studyInstanceUid);
    EXPECT_NE(get(*docFormat.getDataset(), DCM_SeriesInstanceUID),
              get(data, DCM_SeriesInstanceUID));
    EXPECT_EQ(get(*docFormat.getDataset(), DCM_BurnedInAnnotation), "YES");
}

TEST_F(DicomExportTest, EncapsulatedPdfReadsBack) {
    const fs::path dir = test::testDir("dicom-pdf");
    // An odd length, so the value is padded.
    const QByteArray pdf("%PDF-1.4\n1 0 obj << >> endobj\n%%EOF\n\n");
    ASSERT_EQ(pdf.size() % 2, 1);
    const fs::path file = dir / "doc.dcm";
    const DicomStudy study = newStudy();  // no patient: an empty patient module
    const std::string sop = writeEncapsulatedPdf(file, pdf, "Vessel tree report", study);

    DcmFileFormat format;
    ASSERT_TRUE(format.loadFile(OFFilename(file.c_str())).good());
    DcmDataset& data = *format.getDataset();
    EXPECT_EQ(get(data, DCM_SOPClassUID), UID_EncapsulatedPDFStorage);
    EXPECT_EQ(get(data, DCM_SOPInstanceUID), sop);
    EXPECT_EQ(get(data, DCM_Modality), "DOC");
    EXPECT_EQ(get(data, DCM_MIMETypeOfEncapsulatedDocument), "application/pdf");
    EXPECT_EQ(get(data, DCM_DocumentTitle), "Vessel tree report");
    EXPECT_EQ(get(data, DCM_SeriesDescription), "VesselView report");
    EXPECT_EQ(get(data, DCM_BurnedInAnnotation), "NO");
    EXPECT_TRUE(has(data, DCM_PatientName));
    EXPECT_EQ(get(data, DCM_PatientName), "");
    Uint32 length = 0;
    data.findAndGetUint32(DCM_EncapsulatedDocumentLength, length);
    EXPECT_EQ(length, static_cast<Uint32>(pdf.size()));
    const Uint8* bytes = nullptr;
    unsigned long count = 0;
    ASSERT_TRUE(data.findAndGetUint8Array(DCM_EncapsulatedDocument, bytes, &count).good());
    ASSERT_EQ(count, static_cast<unsigned long>(pdf.size() + 1));
    EXPECT_EQ(QByteArray(reinterpret_cast<const char*>(bytes), pdf.size()), pdf);
    validate(file);

    EXPECT_THROW((void)writeEncapsulatedPdf(dir / "bad.dcm", "not a pdf", "x", study),
                 InvalidArgumentError);
    EXPECT_FALSE(fs::exists(dir / "bad.dcm"));
}

TEST_F(DicomExportTest, AnonymisedExportHasNoIdentifiers) {
    const fs::path dir = test::testDir("dicom-anon");
    DicomStudy study = newStudy();
    ReportPatient patient;
    patient.name = "Doe^Jane";
    patient.id = "PID-0042";
    patient.birthDate = "19600215";
    patient.accession = "ACC-9";
    patient.referringPhysician = "Smith^John";
    patient.anonymise = true;
    study.patient = patient;
    const fs::path file = dir / "sc.dcm";
    (void)writeSecondaryCapture(file, test::testImage(16, 8), study);
    DcmFileFormat format;
    ASSERT_TRUE(format.loadFile(OFFilename(file.c_str())).good());
    DcmDataset& data = *format.getDataset();
    for (const DcmTagKey& tag : {DCM_PatientName, DCM_PatientID, DCM_PatientBirthDate,
                                 DCM_AccessionNumber, DCM_ReferringPhysicianName}) {
        EXPECT_TRUE(has(data, tag)) << DcmTag(tag).getTagName();  // type 2: present, empty
        EXPECT_EQ(get(data, tag), "") << DcmTag(tag).getTagName();
    }
    EXPECT_EQ(get(data, DCM_PatientIdentityRemoved), "YES");
    std::ifstream in(file, std::ios::binary);
    const std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(raw.find("Doe"), std::string::npos);
    EXPECT_EQ(raw.find("PID-0042"), std::string::npos);
    validate(file);
}

TEST_F(DicomExportTest, UidsAreFreshAndFailuresLeaveNoFile) {
    EXPECT_NE(newDicomUid(), newDicomUid());
    EXPECT_NE(newStudy().studyInstanceUid, newStudy().studyInstanceUid);
    const fs::path dir = test::testDir("dicom-fail");
    const fs::path blocker = dir / "file";
    std::ofstream(blocker) << "x";
    EXPECT_THROW((void)writeSecondaryCapture(blocker / "sc.dcm", test::testImage(4, 4), newStudy()),
                 IoError);
    EXPECT_THROW((void)writeSecondaryCapture(dir / "empty.dcm", QImage(), newStudy()),
                 InvalidArgumentError);
    EXPECT_EQ(test::listing(dir), "file ");
}

TEST_F(DicomExportTest, ExportsOfDicomDataJoinTheSourceStudy) {
    io::DicomScanResult scan;
    io::DicomPatient patient;
    patient.name = "Roe^Richard";
    patient.id = "P-7";
    io::DicomStudy study;
    study.studyInstanceUid = "1.2.826.0.1.3680043.2.1125.77";
    study.date = "20250102";
    io::DicomSeries series;
    series.seriesInstanceUid = "1.2.826.0.1.3680043.2.1125.77.1";
    study.series.push_back(series);
    patient.studies.push_back(study);
    scan.patients.push_back(patient);

    EXPECT_FALSE(sourceStudy(scan, "1.2.3"));
    const auto source = sourceStudy(scan, series.seriesInstanceUid);
    ASSERT_TRUE(source);
    EXPECT_EQ(source->patient.name, "Roe^Richard");
    EXPECT_EQ(source->patient.id, "P-7");
    EXPECT_EQ(source->patient.studyDate, "20250102");
    ASSERT_TRUE(source->study.patient);

    const fs::path file = test::testDir("dicom-source") / "sc.dcm";
    (void)writeSecondaryCapture(file, test::testImage(8, 8), source->study);
    DcmFileFormat format;
    ASSERT_TRUE(format.loadFile(OFFilename(file.c_str())).good());
    DcmDataset& data = *format.getDataset();
    EXPECT_EQ(get(data, DCM_StudyInstanceUID), study.studyInstanceUid);
    EXPECT_EQ(get(data, DCM_StudyDate), "20250102");
    EXPECT_EQ(get(data, DCM_PatientName), "Roe^Richard");
    EXPECT_NE(get(data, DCM_SeriesInstanceUID), series.seriesInstanceUid);  // a new series
    validate(file);
}

}  // namespace
}  // namespace vv::report
