// SPDX-License-Identifier: GPL-3.0-or-later
// The measurements as a TID 1500 Structured Report: read back by DCMTK's
// dsrdump and dcmdata, checked by dciodvfy (dicom3tools; scripts/setup-deps).
#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcitem.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "RunTool.h"
#include "vv/core/Error.h"
#include "vv/dicom/MeasurementReport.h"
#include "vv/dicom/Uid.h"

namespace vv::dicom {
namespace {

namespace fs = std::filesystem;

fs::path testDir(const std::string& name) {
    fs::path dir = fs::path(VV_TEST_TMP) / "dicom" / (name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string text(DcmItem& data, const DcmTagKey& tag) {
    OFString value;
    data.findAndGetOFStringArray(tag, value);
    return value;
}

/// dciodvfy reports no error (its warnings are the profile's notes).
void expectValid(const fs::path& file) {
    std::string output;
    test::runTool("dciodvfy '" + file.string() + "'", output);
    EXPECT_EQ(output.find("Error"), std::string::npos)
        << "dciodvfy (package dicom3tools, scripts/setup-deps):\n"
        << output;
    EXPECT_EQ(output.find("not found"), std::string::npos) << output;
}

/// An aortic neck's sizes and two lengths, as the planning report makes them.
MeasurementReportContent content() {
    MeasurementReportContent c;
    c.sourceModality = "CT";
    c.sourceSeriesUid = "1.2.826.0.1.3680043.10.1234.1";
    c.sourceInstances = {{UID_CTImageStorage, "1.2.826.0.1.3680043.10.1234.1.1"},
                         {UID_CTImageStorage, "1.2.826.0.1.3680043.10.1234.1.2"}};
    SrGroup neck;
    neck.trackingId = "Neck at the lowest renal artery";
    neck.findingSite = SrCode{"7832008", "SCT", "Abdominal aorta"};
    neck.numbers = {
        {sr::diameter(), std::nullopt, 22.5, sr::millimetre(),
         "Equivalent diameter, 2 sqrt(area / pi)"},
        {sr::diameter(), sr::minimum(), 21.25, sr::millimetre(),
         "Minimum Feret (caliper) diameter"},
        {sr::diameter(), sr::maximum(), 24.0, sr::millimetre(), "Maximum Feret (caliper) diameter"},
        {sr::area(), std::nullopt, 397.6, sr::squareMillimetre(), ""},
    };
    SrGroup sizing;
    sizing.trackingId = "Aortic sizing";
    sizing.numbers = {
        {sr::pathLength(), std::nullopt, 25.125, sr::millimetre(),
         "Neck length along the centreline"},
        {sr::angle(), std::nullopt, 35.0, sr::degree(), "Neck angulation beta"},
    };
    c.groups = {neck, sizing};
    return c;
}

ExportStudy study(bool anonymise) {
    ExportStudy s;
    s.studyInstanceUid = "1.2.826.0.1.3680043.10.1234";
    s.studyDate = "20261205";
    s.studyTime = "101500";
    ExportPatient p;
    p.name = "Doe^Jane";
    p.id = "PID-7";
    p.birthDate = "19600102";
    p.sex = "F";
    p.anonymise = anonymise;
    s.patient = p;
    return s;
}

ExportSeries series() {
    ExportSeries s;
    s.description = "VesselView measurements";
    s.seriesNumber = 901;
    s.contentDate = "20261205";
    s.contentTime = "120000";
    s.creationDate = "20261205";
    s.creationTime = "120001";
    s.softwareVersion = "test";
    return s;
}

TEST(MeasurementReport, IsAValidEnhancedSrThatReadsBackItsValues) {
    const fs::path file = testDir("sr") / "measurements.dcm";
    const std::string uid = writeMeasurementReport(file, content(), study(false), series());
    ASSERT_TRUE(fs::exists(file));
    expectValid(file);

    DcmFileFormat read;
    ASSERT_TRUE(read.loadFile(file.c_str()).good());
    DcmDataset& data = *read.getDataset();
    EXPECT_EQ(text(data, DCM_SOPClassUID), UID_EnhancedSRStorage);
    EXPECT_EQ(text(data, DCM_SOPInstanceUID), uid);
    EXPECT_EQ(text(data, DCM_Modality), "SR");
    EXPECT_EQ(text(data, DCM_StudyInstanceUID), "1.2.826.0.1.3680043.10.1234");
    EXPECT_EQ(text(data, DCM_PatientName), "Doe^Jane");
    EXPECT_EQ(text(data, DCM_CompletionFlag), "COMPLETE");
    EXPECT_EQ(text(data, DCM_SeriesNumber), "901");
    EXPECT_NE(text(data, DCM_SeriesInstanceUID), content().sourceSeriesUid);
    // The source series' instances are the evidence.
    DcmItem* study = nullptr;
    DcmItem* series = nullptr;
    DcmItem* instance = nullptr;
    ASSERT_TRUE(
        data.findAndGetSequenceItem(DCM_CurrentRequestedProcedureEvidenceSequence, study).good());
    ASSERT_TRUE(study->findAndGetSequenceItem(DCM_ReferencedSeriesSequence, series).good());
    EXPECT_EQ(text(*series, DCM_SeriesInstanceUID), content().sourceSeriesUid);
    ASSERT_TRUE(series->findAndGetSequenceItem(DCM_ReferencedSOPSequence, instance, 1).good());
    EXPECT_EQ(text(*instance, DCM_ReferencedSOPInstanceUID), "1.2.826.0.1.3680043.10.1234.1.2");

    // DCMTK's own reader finds the template, the groups and the values with
    // their units and derivations.
    std::string dump;
    ASSERT_EQ(test::runTool("dsrdump +Pl '" + file.string() + "'", dump), 0) << dump;
    for (const char* expected :
         {"Imaging Measurement Report", "Neck at the lowest renal artery", "Aortic sizing",
          "Abdominal aorta", R"("22.500" (mm,UCUM,"millimeter"))",
          R"("21.250" (mm,UCUM,"millimeter"))", "Minimum", "Maximum",
          R"("397.600" (mm2,UCUM,"square millimeter"))", "Path length",
          R"("35.000" (deg,UCUM,"degree"))", "Equivalent diameter, 2 sqrt(area / pi)",
          "VesselView"}) {
        EXPECT_NE(dump.find(expected), std::string::npos) << expected << "\n" << dump;
    }
}

TEST(MeasurementReport, AnonymisedKeepsNoIdentityAndStaysValid) {
    const fs::path file = testDir("sr-anonymous") / "measurements.dcm";
    writeMeasurementReport(file, content(), study(true), series());
    expectValid(file);
    DcmFileFormat read;
    ASSERT_TRUE(read.loadFile(file.c_str()).good());
    DcmDataset& data = *read.getDataset();
    EXPECT_EQ(text(data, DCM_PatientName), "");
    EXPECT_EQ(text(data, DCM_PatientID), "");
    EXPECT_EQ(text(data, DCM_PatientIdentityRemoved), "YES");
    EXPECT_EQ(text(data, DCM_StudyDate), "");
    EXPECT_FALSE(data.tagExists(DCM_InstanceCreationDate));
    EXPECT_NE(text(data, DCM_ContentDate), "20261205");
}

TEST(MeasurementReport, WithoutDatesTheDocumentsOwnAreWritten) {
    const fs::path file = testDir("sr-no-dates") / "measurements.dcm";
    writeMeasurementReport(file, content(), study(false), ExportSeries{});
    expectValid(file);  // Content Date / Time are type 1
    DcmFileFormat read;
    ASSERT_TRUE(read.loadFile(file.c_str()).good());
    EXPECT_EQ(text(*read.getDataset(), DCM_ContentDate).size(), 8U);
}

TEST(MeasurementReport, AMeshWithoutADicomSourceListsNoEvidence) {
    const fs::path file = testDir("sr-mesh") / "measurements.dcm";
    MeasurementReportContent c = content();
    c.sourceModality.clear();
    c.sourceSeriesUid.clear();
    c.sourceInstances.clear();
    ExportStudy s = study(false);
    s.studyInstanceUid = newUid();
    writeMeasurementReport(file, c, s, series());
    expectValid(file);
    DcmFileFormat read;
    ASSERT_TRUE(read.loadFile(file.c_str()).good());
    EXPECT_FALSE(read.getDataset()->tagExists(DCM_CurrentRequestedProcedureEvidenceSequence));
}

TEST(MeasurementReport, BadContentIsAClearErrorAndWritesNothing) {
    const fs::path dir = testDir("sr-bad");
    const auto fails = [&](const MeasurementReportContent& c, const std::string& words) {
        const fs::path file = dir / "bad.dcm";
        try {
            writeMeasurementReport(file, c, study(false), series());
            ADD_FAILURE() << "no error for: " << words;
        } catch (const InvalidArgumentError& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("bad.dcm"), std::string::npos) << e.what();
        }
        EXPECT_FALSE(fs::exists(file));
    };
    MeasurementReportContent none = content();
    none.groups.clear();
    fails(none, "no measurements");
    MeasurementReportContent twice = content();
    twice.groups[1].trackingId = twice.groups[0].trackingId;
    fails(twice, "used twice");
    MeasurementReportContent nan = content();
    nan.groups[0].numbers[1].value = std::nan("");
    fails(nan, "not a number");
    MeasurementReportContent empty = content();
    empty.groups[1].numbers.clear();
    fails(empty, "has no measurements");
    MeasurementReportContent longId = content();
    longId.groups[0].trackingId = std::string(65, 'x');
    fails(longId, "1 to 64 characters");
    MeasurementReportContent noCode = content();
    noCode.groups[0].numbers[0].unit = SrCode{};
    fails(noCode, "a code is empty");
    // An unwritable place: an IoError naming it.
    EXPECT_THROW(writeMeasurementReport(dir / "no-such-folder" / "sr.dcm", content(), study(false),
                                        series()),
                 IoError);
}

}  // namespace
}  // namespace vv::dicom
