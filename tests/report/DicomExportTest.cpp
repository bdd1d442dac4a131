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
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "ReportTestUtil.h"
#include "vv/core/Error.h"
#include "vv/report/DicomExport.h"
#include "vv/report/DicomSource.h"
#include "vv/report/PdfReport.h"

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

/// The attributes of DICOM PS3.15 Table E.1-1 (Basic Application Level
/// Confidentiality Profile) that an export could carry: identifiers, dates and
/// times, people, places, devices, free text and UIDs. After an anonymised
/// export each must be absent or empty, except the UIDs, which must be new.
struct ProfileAttribute {
    DcmTagKey tag;
    bool uid = false;  ///< action U: replaced by a new UID
};

std::vector<ProfileAttribute> basicProfile() {
    std::vector<ProfileAttribute> list;
    const auto blank = [&](Uint16 g, Uint16 e) { list.push_back({DcmTagKey(g, e), false}); };
    const auto fresh = [&](Uint16 g, Uint16 e) { list.push_back({DcmTagKey(g, e), true}); };
    // Dates and times of the study, series, acquisition, content and instance.
    for (const Uint16 e : {0x0012, 0x0013, 0x0020, 0x0021, 0x0022, 0x0023, 0x0024, 0x0025, 0x002A,
                           0x0030, 0x0031, 0x0032, 0x0033, 0x0034, 0x0035, 0x0201}) {
        blank(0x0008, e);
    }
    // Accession, institution, referring physician, station, descriptions, staff.
    for (const Uint16 e : {0x0050, 0x0080, 0x0081, 0x0082, 0x0090, 0x0092, 0x0094, 0x0096,
                           0x1010, 0x1030, 0x1040, 0x1048, 0x1049, 0x1050, 0x1052, 0x1060,
                           0x1062, 0x1070, 0x1072, 0x1080, 0x1084, 0x2111, 0x4000}) {
        blank(0x0008, e);
    }
    // Patient module and patient study: names, IDs, dates, contacts, history.
    for (const Uint16 e : {0x0010, 0x0020, 0x0021, 0x0022, 0x0030, 0x0032, 0x0040, 0x0050, 0x1000,
                           0x1001, 0x1002, 0x1005, 0x1010, 0x1020, 0x1030, 0x1040, 0x1060, 0x1080,
                           0x1081, 0x1090, 0x2000, 0x2110, 0x2150, 0x2152, 0x2154, 0x2160, 0x2180,
                           0x21A0, 0x21B0, 0x21C0, 0x21D0, 0x21F0, 0x2203, 0x4000}) {
        blank(0x0010, e);
    }
    blank(0x0018, 0x1000);  // Device Serial Number
    blank(0x0018, 0x1030);  // Protocol Name
    blank(0x0018, 0x700A);  // Detector ID
    blank(0x0020, 0x0010);  // Study ID
    blank(0x0020, 0x4000);  // Image Comments
    blank(0x0032, 0x1032);  // Requesting Physician
    blank(0x0032, 0x1060);  // Requested Procedure Description
    blank(0x0032, 0x4000);  // Study Comments
    blank(0x0038, 0x0010);  // Admission ID
    blank(0x0038, 0x0300);  // Current Patient Location
    blank(0x0038, 0x0400);  // Patient's Institution Residence
    blank(0x0040, 0x0006);  // Scheduled Performing Physician's Name
    blank(0x0040, 0x0244);  // Performed Procedure Step Start Date
    blank(0x0040, 0x0253);  // Performed Procedure Step ID
    blank(0x0040, 0x1001);  // Requested Procedure ID
    blank(0x0040, 0xA730);  // Content Sequence
    blank(0x0400, 0x0561);  // Original Attributes Sequence
    fresh(0x0008, 0x0014);  // Instance Creator UID
    fresh(0x0008, 0x0018);  // SOP Instance UID
    fresh(0x0008, 0x1155);  // Referenced SOP Instance UID
    fresh(0x0020, 0x000D);  // Study Instance UID
    fresh(0x0020, 0x000E);  // Series Instance UID
    fresh(0x0020, 0x0052);  // Frame of Reference UID
    fresh(0x0020, 0x0200);  // Synchronization Frame of Reference UID
    fresh(0x0040, 0xA124);  // UID
    fresh(0x0088, 0x0140);  // Storage Media File-set UID
    return list;
}

/// Every attribute an anonymised export may hold: the ones above (then empty
/// or new) and those that never carry anything of the patient's.
bool allowedInAnonymisedExport(const DcmTagKey& tag) {
    for (const ProfileAttribute& a : basicProfile()) {
        if (a.tag == tag) {
            return true;
        }
    }
    static const std::vector<DcmTagKey> fixed = {DCM_SpecificCharacterSet,
                                                 DCM_ImageType,
                                                 DCM_SOPClassUID,
                                                 DCM_Modality,
                                                 DCM_ConversionType,
                                                 DCM_Manufacturer,
                                                 DCM_SeriesDescription /* "VesselView report" */,
                                                 DCM_PatientIdentityRemoved,
                                                 DCM_DeidentificationMethod,
                                                 DCM_DeidentificationMethodCodeSequence,
                                                 DCM_SeriesNumber,
                                                 DCM_InstanceNumber,
                                                 DCM_PatientOrientation,
                                                 DCM_Laterality,
                                                 DCM_SoftwareVersions,
                                                 DCM_BurnedInAnnotation,
                                                 DCM_LossyImageCompression,
                                                 DCM_SamplesPerPixel,
                                                 DCM_PhotometricInterpretation,
                                                 DCM_PlanarConfiguration,
                                                 DCM_Rows,
                                                 DCM_Columns,
                                                 DCM_BitsAllocated,
                                                 DCM_BitsStored,
                                                 DCM_HighBit,
                                                 DCM_PixelRepresentation,
                                                 DCM_LongitudinalTemporalInformationModified,
                                                 DCM_PixelData,
                                                 DCM_ConceptNameCodeSequence,
                                                 DCM_DocumentTitle,
                                                 DCM_MIMETypeOfEncapsulatedDocument,
                                                 DCM_EncapsulatedDocumentLength,
                                                 DCM_EncapsulatedDocument};
    return std::find(fixed.begin(), fixed.end(), tag) != fixed.end();
}

TEST_F(DicomExportTest, AnonymisedExportFollowsTheBasicConfidentialityProfile) {
    const fs::path dir = test::testDir("dicom-anon");
    // A source study with every identifying field set to a value that cannot
    // turn up by chance in what the export itself makes (fresh UIDs, binary
    // data): long, random-looking names and IDs; the time with its fraction
    // (13 characters; a UID could hold its digits only across a dot); the
    // dates (8 digits) are the shortest.
    DicomStudy study;
    study.studyInstanceUid = "1.2.826.0.1.3680043.2.1125.4242";
    study.studyId = "STUDY-QX7W4Z";
    study.studyDate = "20230102";
    study.studyTime = "101112.482913";
    ReportPatient patient;
    patient.name = "Quillfeatherby^Zenobiaxa";
    patient.id = "PID-7Q4X-9KZ2";
    patient.birthDate = "19600215";
    patient.sex = "F";
    patient.studyDate = "20230102";
    patient.accession = "ACC-Q7W3-5581";
    patient.referringPhysician = "Throgmortonix^Ignatiusz";
    patient.anonymise = true;
    study.patient = patient;
    const std::vector<std::string> identifying = {"Quillfeatherby",
                                                  "Zenobiaxa",
                                                  "PID-7Q4X-9KZ2",
                                                  "19600215",
                                                  "20230102",
                                                  "101112.482913",
                                                  "ACC-Q7W3-5581",
                                                  "Throgmortonix",
                                                  "Ignatiusz",
                                                  "STUDY-QX7W4Z",
                                                  "1.2.826.0.1.3680043.2.1125.4242"};

    // The report PDF lists a source folder named after the patient.
    ReportContent content;
    content.patient = patient;
    content.sources = {"/data/Quillfeatherby_Zenobiaxa_PID-7Q4X-9KZ2/IM0001.dcm"};
    content.view.image = test::testImage(reportImageWidth(PaperSize::A4), 400);
    content.view.caption = "Far view";
    const QByteArray pdf = renderPdf(content, PaperSize::A4);

    const fs::path sc = dir / "sc.dcm";
    const fs::path doc = dir / "doc.dcm";
    const std::string scSop = writeSecondaryCapture(sc, test::testImage(16, 8), study);
    const std::string docSop = writeEncapsulatedPdf(doc, pdf, "Vessel tree report", study);

    std::string studyUid;
    for (const fs::path& file : {sc, doc}) {
        SCOPED_TRACE(file.filename().string());
        DcmFileFormat format;
        ASSERT_TRUE(format.loadFile(OFFilename(file.c_str())).good());
        DcmDataset& data = *format.getDataset();
        for (const ProfileAttribute& a : basicProfile()) {
            const std::string name = DcmTag(a.tag).getTagName();
            if (!a.uid) {
                DcmElement* element = nullptr;
                if (data.findAndGetElement(a.tag, element).good()) {
                    EXPECT_EQ(element->getLength(), 0U) << name << " is not empty";
                }
                continue;
            }
            const std::string value = get(data, a.tag);
            EXPECT_NE(value, study.studyInstanceUid) << name;
        }
        // Nothing outside the profile's list and the known-safe attributes.
        for (unsigned long i = 0; i < data.card(); ++i) {
            const DcmTagKey tag = data.getElement(i)->getTag();
            EXPECT_TRUE(allowedInAnonymisedExport(tag))
                << DcmTag(tag).getTagName() << " " << tag.toString() << " is not known to be safe";
        }
        EXPECT_EQ(get(data, DCM_PatientIdentityRemoved), "YES");
        EXPECT_EQ(get(data, DCM_LongitudinalTemporalInformationModified), "REMOVED");
        DcmItem* code = nullptr;
        ASSERT_TRUE(
            data.findAndGetSequenceItem(DCM_DeidentificationMethodCodeSequence, code, 0).good());
        OFString codeValue;
        code->findAndGetOFString(DCM_CodeValue, codeValue);
        EXPECT_EQ(codeValue, "113100");
        // Type 2 attributes stay present (empty), as the IODs require.
        for (const DcmTagKey& tag : {DCM_PatientName, DCM_PatientID, DCM_PatientBirthDate,
                                     DCM_PatientSex, DCM_StudyDate, DCM_AccessionNumber}) {
            EXPECT_TRUE(has(data, tag)) << DcmTag(tag).getTagName();
        }
        // One pseudonymous study for both instances: a valid UID (PS3.5 B.2).
        const std::string uid = get(data, DCM_StudyInstanceUID);
        EXPECT_EQ(uid.rfind("2.25.", 0), 0U) << uid;
        EXPECT_LE(uid.size(), 64U);
        EXPECT_EQ(uid.find_first_not_of("0123456789.", 0), std::string::npos) << uid;
        if (studyUid.empty()) {
            studyUid = uid;
        }
        EXPECT_EQ(uid, studyUid);

        std::ifstream in(file, std::ios::binary);
        std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        // The compressed PDF and the pixels are binary: a short name such as
        // "Doe" turned up in them by chance (about once in 300 runs). What they
        // show is checked on their decompressed text (pdftotext below; the
        // image is a gradient), so their bytes are blanked before the search.
        for (const DcmTagKey& tag : {DCM_EncapsulatedDocument, DCM_PixelData}) {
            const Uint8* bytes = nullptr;
            unsigned long count = 0;
            if (data.findAndGetUint8Array(tag, bytes, &count).good() && count > 0) {
                const std::string value(reinterpret_cast<const char*>(bytes), count);
                const std::size_t at = raw.find(value);
                ASSERT_NE(at, std::string::npos) << DcmTag(tag).getTagName();
                std::fill_n(raw.begin() + static_cast<std::ptrdiff_t>(at), count, '\0');
            }
        }
        for (const std::string& value : identifying) {
            EXPECT_EQ(raw.find(value), std::string::npos) << value << " is in the file";
        }
        validate(file);
    }
    EXPECT_NE(scSop, docSop);

    // The encapsulated report's text names nobody either.
    const fs::path pdfFile = dir / "report.pdf";
    {
        std::ofstream out(pdfFile, std::ios::binary);
        out.write(pdf.constData(), pdf.size());
    }
    std::string text;
    ASSERT_EQ(test::runTool("pdftotext -layout '" + pdfFile.string() + "' -", text), 0) << text;
    EXPECT_NE(text.find("anonymised"), std::string::npos) << text;
    for (const std::string& value : identifying) {
        EXPECT_EQ(text.find(value), std::string::npos) << value << " is in the PDF:\n" << text;
    }
}

TEST_F(DicomExportTest, AnonymisedUidsArePseudonymsWithinOneRun) {
    const std::string a = anonymisedUid("1.2.3.4");
    EXPECT_EQ(anonymisedUid("1.2.3.4"), a);  // the report's instances share a study
    EXPECT_NE(anonymisedUid("1.2.3.5"), a);
    EXPECT_NE(a, "1.2.3.4");
    EXPECT_EQ(a.rfind("2.25.", 0), 0U);
    EXPECT_LE(a.size(), 64U);
    EXPECT_GT(a.size(), 5U + 30U);  // a 128-bit number has 30+ digits almost always
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
    dicom::DicomScanResult scan;
    dicom::DicomPatient patient;
    patient.name = "Roe^Richard";
    patient.id = "P-7";
    dicom::DicomStudy study;
    study.studyInstanceUid = "1.2.826.0.1.3680043.2.1125.77";
    study.date = "20250102";
    dicom::DicomSeries series;
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
