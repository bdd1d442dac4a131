// SPDX-License-Identifier: GPL-3.0-or-later
// DICOM import on series written here with DCMTK: grouping, slice order by
// position, spacing, gantry tilt, missing slices, mixed sizes, multi-frame,
// every transfer syntax DCMTK can encode, JPEG 2000 refusal, memory refusal,
// progress and cancel on a 256 x 256 x 200 series, no patient data in messages.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "DicomTestUtil.h"
#include "vv/core/Error.h"
#include "vv/core/Log.h"
#include "vv/core/ProcessMemory.h"
#include "vv/dicom/Dicom.h"
#include "vv/scene/Volume.h"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;
using vv::dicom::DicomWarning;
using vv::test::TestSlice;

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(VV_TEST_TMP) / "dicom" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// Stored value of voxel (i, j) of slice k: distinct per slice, signed range.
std::int32_t pattern(int i, int j, int k) {
    return ((i * 7 + j * 13 + k * 31) % 2000) - 1000;
}

TestSlice sliceAt(const std::string& study, const std::string& series, int k, glm::dvec3 position,
                  int rows = 16, int columns = 16) {
    TestSlice s;
    s.rows = rows;
    s.columns = columns;
    s.studyUid = study;
    s.seriesUid = series;
    s.position = position;
    s.instanceNumber = 100 - k;  // deliberately the reverse of the position order
    s.slope = 1.0;
    s.intercept = -24.0;
    s.stored.resize(static_cast<std::size_t>(rows * columns));
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) {
            s.stored[static_cast<std::size_t>(j * columns + i)] = pattern(i, j, k);
        }
    }
    return s;
}

/// Writes slices k = 0..n-1 at z positions zs[k], under shuffled file names.
void writeSeries(const fs::path& dir, const std::string& study, const std::string& series,
                 const std::vector<glm::dvec3>& positions, int rows = 16, int columns = 16) {
    std::vector<int> names(positions.size());
    for (std::size_t i = 0; i < names.size(); ++i) {
        names[i] = static_cast<int>(i);
    }
    std::mt19937 rng(42);
    std::shuffle(names.begin(), names.end(), rng);
    for (std::size_t k = 0; k < positions.size(); ++k) {
        vv::test::writeSlice(
            dir / ("img" + std::to_string(names[k]) + ".dcm"),
            sliceAt(study, series, static_cast<int>(k), positions[k], rows, columns));
    }
}

std::vector<glm::dvec3> zPositions(std::vector<double> zs) {
    std::vector<glm::dvec3> out;
    for (const double z : zs) {
        out.emplace_back(-10.0, 20.0, z);
    }
    return out;
}

bool hasWarning(const vv::dicom::DicomVolume& v, DicomWarning::Kind kind) {
    return std::any_of(v.warnings.begin(), v.warnings.end(),
                       [&](const DicomWarning& w) { return w.kind == kind; });
}

void expectNoPatientData(const std::string& text) {
    EXPECT_THAT(text, Not(HasSubstr("Secretname")));
    EXPECT_THAT(text, Not(HasSubstr("PID-SECRET")));
}

// ---------------------------------------------------------------------------

TEST(DicomVolume, VoxelAccessGeometryAndInt16Rounding) {
    vv::scene::Volume v(glm::ivec3(3, 2, 4), vv::scene::VoxelType::Int16);
    EXPECT_EQ(v.voxelCount(), 24U);
    EXPECT_EQ(v.byteSize(), 48U);
    v.setValueAt(v.index(2, 1, 3), 12.6F);
    EXPECT_FLOAT_EQ(v.value(2, 1, 3), 13.0F);
    v.setValueAt(0, 1e6F);
    EXPECT_FLOAT_EQ(v.valueAt(0), 32767.0F);
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(0.5, 0, 0, 0);
    m[1] = glm::dvec4(0, 0.75, 0, 0);
    m[2] = glm::dvec4(0, 0.2, 2.0, 0);  // sheared slice step
    m[3] = glm::dvec4(10, 20, 30, 1);
    v.setIndexToWorld(m);
    EXPECT_NEAR(v.spacing().x, 0.5, 1e-12);
    EXPECT_NEAR(v.spacing().y, 0.75, 1e-12);
    EXPECT_NEAR(v.spacing().z, 2.0, 1e-12);
    EXPECT_TRUE(v.sheared());
    const glm::dvec3 p = v.worldPosition({2, 1, 3});
    EXPECT_NEAR(p.x, 11.0, 1e-12);
    EXPECT_NEAR(p.y, 20.75 + 0.6, 1e-12);
    EXPECT_NEAR(p.z, 36.0, 1e-12);
    const glm::dvec4 back = v.worldToIndex() * glm::dvec4(p, 1.0);
    EXPECT_NEAR(back.z, 3.0, 1e-9);
    EXPECT_EQ(vv::scene::Volume::byteSize(1ULL << 40, 1ULL << 40, 1ULL << 40,
                                          vv::scene::VoxelType::Int16),
              UINT64_MAX);
    EXPECT_THROW(vv::scene::Volume(glm::ivec3(0, 1, 1), vv::scene::VoxelType::Float32),
                 vv::InvalidArgumentError);
}

TEST(DicomScan, GroupsSeriesAndSkipsNonImages) {
    const fs::path dir = freshDir("scan");
    const std::string study = vv::test::newUid();
    const std::string a = vv::test::newUid();
    const std::string b = vv::test::newUid();
    fs::create_directories(dir / "sub" / "deeper");
    writeSeries(dir, study, a, zPositions({0, 1, 2, 3}));
    writeSeries(dir / "sub" / "deeper", study, b, zPositions({5, 7.5}), 8, 12);
    std::ofstream(dir / "notes.txt") << "not DICOM\n";
    // A structured report: no pixel data.
    {
        DcmFileFormat ff;
        DcmDataset* d = ff.getDataset();
        d->putAndInsertString(DCM_SOPClassUID, UID_BasicTextSRStorage);
        d->putAndInsertString(DCM_SOPInstanceUID, vv::test::newUid().c_str());
        d->putAndInsertString(DCM_Modality, "SR");
        d->putAndInsertString(DCM_PatientName, vv::test::kPatientName);
        ASSERT_TRUE(
            ff.saveFile((dir / "sub" / "report.dcm").c_str(), EXS_LittleEndianExplicit).good());
    }
    std::vector<double> fractions;
    const vv::Progress progress([&](double f, std::string_view) { fractions.push_back(f); }, {});
    const auto scan = vv::dicom::scanDicom(dir, progress);
    EXPECT_EQ(scan.filesExamined, 8U);
    ASSERT_EQ(scan.patients.size(), 1U);
    EXPECT_EQ(scan.patients[0].id, vv::test::kPatientId);
    ASSERT_EQ(scan.patients[0].studies.size(), 1U);
    ASSERT_EQ(scan.allSeries().size(), 2U);
    const auto* sa = scan.findSeries(a);
    const auto* sb = scan.findSeries(b);
    ASSERT_NE(sa, nullptr);
    ASSERT_NE(sb, nullptr);
    EXPECT_EQ(sa->imageCount, 4U);
    EXPECT_EQ(sa->modality, "CT");
    EXPECT_EQ(sa->description, "test series");
    EXPECT_EQ(sa->rows, 16);
    ASSERT_TRUE(sa->pixelSpacing.has_value());
    EXPECT_DOUBLE_EQ(sa->pixelSpacing->x, 0.75);  // column spacing
    EXPECT_DOUBLE_EQ(sa->pixelSpacing->y, 0.5);   // row spacing
    ASSERT_TRUE(sa->sliceSpacing.has_value());
    EXPECT_NEAR(*sa->sliceSpacing, 1.0, 1e-9);
    EXPECT_EQ(sb->rows, 8);
    EXPECT_EQ(sb->columns, 12);
    EXPECT_NEAR(sb->sliceSpacing.value_or(0), 2.5, 1e-9);
    ASSERT_EQ(scan.skipped.size(), 2U);
    for (const auto& s : scan.skipped) {
        EXPECT_FALSE(s.reason.empty());
        expectNoPatientData(s.reason);
    }
    const auto report = std::find_if(scan.skipped.begin(), scan.skipped.end(), [](const auto& s) {
        return s.file.filename() == "report.dcm";
    });
    ASSERT_NE(report, scan.skipped.end());
    EXPECT_THAT(report->reason, HasSubstr("structured report"));
    ASSERT_FALSE(fractions.empty());
    EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_THROW((void)vv::dicom::scanDicom(dir / "missing"), vv::IoError);
}

TEST(DicomLoad, SortsByPositionNotByInstanceOrNameAndAppliesRescale) {
    const fs::path dir = freshDir("sorted");
    const std::string series = vv::test::newUid();
    // Oblique orientation: positions along its normal, written out of order.
    const std::array<double, 6> o = {0.8, 0.6, 0.0, 0.0, 0.0, -1.0};
    const glm::dvec3 r(o[0], o[1], o[2]);
    const glm::dvec3 c(o[3], o[4], o[5]);
    const glm::dvec3 n = glm::cross(r, c);
    const glm::dvec3 origin(5, -7, 11);
    std::vector<int> names = {3, 0, 4, 1, 2};
    for (int k = 0; k < 5; ++k) {
        TestSlice s = sliceAt("1.2.3", series, k, origin + 1.25 * k * n);
        s.orientation = o;
        vv::test::writeSlice(dir / ("f" + std::to_string(names[static_cast<std::size_t>(k)])), s);
    }
    const auto v = vv::dicom::loadDicomVolume(dir);
    EXPECT_TRUE(v.warnings.empty()) << v.warnings.front().message;
    EXPECT_EQ(v.seriesInstanceUid, series);
    const auto& vol = v.volume;
    ASSERT_EQ(vol.dims(), glm::ivec3(16, 16, 5));
    EXPECT_EQ(vol.voxelType(), vv::scene::VoxelType::Int16);
    EXPECT_EQ(vol.unit(), "HU");
    for (int k = 0; k < 5; ++k) {
        for (int j = 0; j < 16; j += 5) {
            for (int i = 0; i < 16; i += 3) {
                ASSERT_FLOAT_EQ(vol.value(i, j, k), static_cast<float>(pattern(i, j, k) - 24))
                    << i << "," << j << "," << k;
            }
        }
    }
    EXPECT_NEAR(vol.spacing().x, 0.75, 1e-9);
    EXPECT_NEAR(vol.spacing().y, 0.5, 1e-9);
    EXPECT_NEAR(vol.spacing().z, 1.25, 1e-6);
    EXPECT_FALSE(vol.sheared());
    const glm::dvec3 p = vol.worldPosition({2, 3, 4});
    const glm::dvec3 expected = origin + 2 * 0.75 * r + 3 * 0.5 * c + 4 * 1.25 * n;
    EXPECT_NEAR(glm::length(p - expected), 0.0, 1e-6);
}

TEST(DicomLoad, FloatVoxelsForFractionalRescale) {
    const fs::path dir = freshDir("float");
    const std::string series = vv::test::newUid();
    for (int k = 0; k < 3; ++k) {
        TestSlice s = sliceAt("1.2.3", series, k, {0, 0, 2.0 * k});
        s.slope = 0.5;
        s.intercept = 1.25;
        s.modality = "MR";
        s.sopClass = UID_MRImageStorage;
        vv::test::writeSlice(dir / ("s" + std::to_string(k)), s);
    }
    const auto v = vv::dicom::loadDicomVolume(dir);
    EXPECT_EQ(v.volume.voxelType(), vv::scene::VoxelType::Float32);
    EXPECT_FLOAT_EQ(v.volume.value(3, 4, 2), static_cast<float>(pattern(3, 4, 2) * 0.5 + 1.25));
    EXPECT_TRUE(v.volume.unit().empty());
    vv::dicom::DicomLoadOptions floats;
    floats.allowInt16 = false;
    EXPECT_EQ(vv::dicom::loadDicomVolume(dir, {}, floats).volume.voxelType(),
              vv::scene::VoxelType::Float32);
}

TEST(DicomLoad, MissingSliceIsReportedAndInterpolated) {
    const fs::path dir = freshDir("missing");
    const std::string series = vv::test::newUid();
    writeSeries(dir, "1.2.3", series, zPositions({0, 2, 4, 8, 10}));  // 6 is missing
    const auto v = vv::dicom::loadDicomVolume(dir);
    EXPECT_TRUE(hasWarning(v, DicomWarning::Kind::MissingSlices));
    EXPECT_FALSE(hasWarning(v, DicomWarning::Kind::NonUniformSpacing));
    ASSERT_EQ(v.volume.dims().z, 6);
    EXPECT_NEAR(v.volume.spacing().z, 2.0, 1e-9);
    // Slice 3 (z = 6) lies halfway between the written slices 2 and 3.
    EXPECT_NEAR(v.volume.value(1, 1, 3),
                std::nearbyint(0.5 * (pattern(1, 1, 2) + pattern(1, 1, 3)) - 24), 0.51);
    EXPECT_FLOAT_EQ(v.volume.value(1, 1, 4), static_cast<float>(pattern(1, 1, 3) - 24));
    for (const auto& w : v.warnings) {
        EXPECT_THAT(w.message, HasSubstr(series));
        expectNoPatientData(w.message);
    }
}

TEST(DicomLoad, NonUniformSpacingIsReportedAndResampled) {
    const fs::path dir = freshDir("nonuniform");
    writeSeries(dir, "1.2.3", vv::test::newUid(), zPositions({0, 1, 2.3, 3, 4}));
    const auto v = vv::dicom::loadDicomVolume(dir);
    EXPECT_TRUE(hasWarning(v, DicomWarning::Kind::NonUniformSpacing));
    EXPECT_EQ(v.volume.dims().z, 5);
    EXPECT_NEAR(v.volume.spacing().z, 1.0, 1e-9);
    // z = 2 lies between the slices at 1 and 2.3: weight 1/1.3.
    const double t = 1.0 / 1.3;
    EXPECT_NEAR(v.volume.value(0, 0, 2), (1 - t) * pattern(0, 0, 1) + t * pattern(0, 0, 2) - 24,
                0.51);
}

TEST(DicomLoad, GantryTiltIsReportedAndKeptAsShear) {
    const fs::path dir = freshDir("tilt");
    std::vector<glm::dvec3> positions;
    const double tilt = 15.0 * 3.14159265358979323846 / 180.0;
    for (int k = 0; k < 6; ++k) {
        positions.emplace_back(0.0, 2.0 * k * std::tan(tilt), 2.0 * k);
    }
    writeSeries(dir, "1.2.3", vv::test::newUid(), positions);
    const auto v = vv::dicom::loadDicomVolume(dir);
    EXPECT_TRUE(hasWarning(v, DicomWarning::Kind::GantryTilt));
    EXPECT_TRUE(v.volume.sheared());
    EXPECT_NEAR(v.volume.spacing().z, 2.0, 1e-9);
    const glm::dvec3 last = v.volume.worldPosition({0, 0, 5});
    EXPECT_NEAR(glm::length(last - positions.back()), 0.0, 1e-6);
    const auto it = std::find_if(v.warnings.begin(), v.warnings.end(), [](const DicomWarning& w) {
        return w.kind == DicomWarning::Kind::GantryTilt;
    });
    EXPECT_THAT(it->message, HasSubstr("15 degrees"));
}

TEST(DicomLoad, MixedSizesAreAClearError) {
    const fs::path dir = freshDir("mixed");
    const std::string series = vv::test::newUid();
    vv::test::writeSlice(dir / "a.dcm", sliceAt("1.2.3", series, 0, {0, 0, 0}));
    vv::test::writeSlice(dir / "b.dcm", sliceAt("1.2.3", series, 1, {0, 0, 1}, 8, 8));
    const auto scan = vv::dicom::scanDicom(dir);
    ASSERT_EQ(scan.allSeries().size(), 1U);
    EXPECT_TRUE(scan.allSeries()[0]->mixedSizes);
    try {
        (void)vv::dicom::loadDicomSeries(*scan.allSeries()[0]);
        FAIL() << "mixed sizes loaded";
    } catch (const vv::FormatError& e) {
        EXPECT_THAT(e.what(), HasSubstr("mixes image sizes"));
        EXPECT_THAT(e.what(), HasSubstr(series));
        EXPECT_THAT(e.what(), HasSubstr(".dcm"));
        expectNoPatientData(e.what());
    }
}

TEST(DicomLoad, DuplicatePositionsAndMissingPositionsAreRefused) {
    const fs::path dir = freshDir("duplicates");
    const std::string series = vv::test::newUid();
    writeSeries(dir, "1.2.3", series, zPositions({0, 1, 1, 2}));
    EXPECT_THROW((void)vv::dicom::loadDicomVolume(dir), vv::FormatError);

    const fs::path none = freshDir("nopositions");
    const std::string s2 = vv::test::newUid();
    for (int k = 0; k < 3; ++k) {
        TestSlice s = sliceAt("1.2.3", s2, k, {});
        s.position.reset();
        vv::test::writeSlice(none / ("s" + std::to_string(k)), s);
    }
    try {
        (void)vv::dicom::loadDicomVolume(none);
        FAIL() << "slices without positions loaded";
    } catch (const vv::FormatError& e) {
        EXPECT_THAT(e.what(), HasSubstr("never by instance number"));
    }
}

TEST(DicomLoad, DifferentOrientationsAreKnownFromTheScanAndRefused) {
    const fs::path dir = freshDir("localizer");
    const std::string series = vv::test::newUid();
    const std::array<std::array<double, 6>, 3> planes = {std::array<double, 6>{1, 0, 0, 0, 1, 0},
                                                         std::array<double, 6>{1, 0, 0, 0, 0, -1},
                                                         std::array<double, 6>{0, 1, 0, 0, 0, -1}};
    for (int k = 0; k < 3; ++k) {
        TestSlice s = sliceAt("1.2.3", series, k, {0, 0, 0});
        s.orientation = planes[static_cast<std::size_t>(k)];
        vv::test::writeSlice(dir / ("p" + std::to_string(k)), s);
    }
    const auto scan = vv::dicom::scanDicom(dir);
    ASSERT_EQ(scan.allSeries().size(), 1U);
    EXPECT_THAT(scan.allSeries()[0]->unsupportedReason, HasSubstr("different orientations"));
    try {
        (void)vv::dicom::loadDicomSeries(*scan.allSeries()[0]);
        FAIL() << "a localizer loaded as one volume";
    } catch (const vv::FormatError& e) {
        EXPECT_THAT(e.what(), HasSubstr("different orientations"));
        EXPECT_THAT(e.what(), HasSubstr(series));
    }
}

namespace logs {
std::vector<std::string>& collected() {
    static std::vector<std::string> messages;
    return messages;
}
void collect(vv::log::Level /*level*/, std::string_view category, std::string_view message) {
    collected().push_back(std::string(category) + ": " + std::string(message));
}
}  // namespace logs

TEST(DicomLoad, NoPatientDataInLogsWarningsOrErrors) {
    const fs::path dir = freshDir("phi");
    const std::string series = vv::test::newUid();
    writeSeries(dir, "1.2.3", series, zPositions({0, 1, 3, 4.5}));  // missing, non-uniform
    vv::test::writeSlice(dir / "other-size.dcm",
                         sliceAt("1.2.3", vv::test::newUid(), 0, {0, 0, 0}, 8, 8));
    std::ofstream(dir / "junk.bin") << "junk";
    ::setenv("VV_LOG", "debug", 1);
    logs::collected().clear();
    vv::log::setSink(&logs::collect);
    std::vector<std::string> texts;
    const auto scan = vv::dicom::scanDicom(dir);
    for (const auto* s : scan.allSeries()) {
        try {
            const auto v = vv::dicom::loadDicomSeries(*s);
            for (const auto& w : v.warnings) {
                texts.push_back(w.message);
            }
        } catch (const vv::Error& e) {
            texts.emplace_back(e.what());
        }
    }
    for (const auto& k : scan.skipped) {
        texts.push_back(k.reason);
    }
    try {
        (void)vv::dicom::loadDicomVolume(dir);
    } catch (const vv::Error& e) {
        texts.emplace_back(e.what());
    }
    vv::log::setSink(nullptr);
    ::unsetenv("VV_LOG");
    texts.insert(texts.end(), logs::collected().begin(), logs::collected().end());
    EXPECT_GE(logs::collected().size(), 3U);
    EXPECT_GE(texts.size(), 6U);
    for (const auto& t : texts) {
        expectNoPatientData(t);
    }
}

TEST(DicomLoad, SeveralSeriesNeedAChoice) {
    const fs::path dir = freshDir("choice");
    const std::string a = vv::test::newUid();
    const std::string b = vv::test::newUid();
    writeSeries(dir, "1.2.3", a, zPositions({0, 1}));
    vv::test::writeSlice(dir / "other.dcm", sliceAt("1.2.3", b, 0, {0, 0, 0}));
    try {
        (void)vv::dicom::loadDicomVolume(dir);
        FAIL();
    } catch (const vv::FormatError& e) {
        EXPECT_THAT(e.what(), HasSubstr(a));
        EXPECT_THAT(e.what(), HasSubstr(b));
    }
    EXPECT_EQ(vv::dicom::loadDicomVolume(dir, b).volume.dims().z, 1);
    EXPECT_EQ(vv::dicom::loadDicomVolume(dir, a).volume.dims().z, 2);
    EXPECT_THROW((void)vv::dicom::loadDicomVolume(dir, "9.9.9"), vv::FormatError);
}

TEST(DicomLoad, EnhancedMultiFrameUsesPerFrameFunctionalGroups) {
    const fs::path dir = freshDir("enhanced");
    TestSlice s = sliceAt("1.2.3", vv::test::newUid(), 0, {0, 0, 0});
    // Frames written in reverse position order with per-frame slopes.
    std::vector<glm::dvec3> positions;
    std::vector<std::vector<std::int32_t>> frames;
    std::vector<double> slopes;
    for (int f = 0; f < 4; ++f) {
        const int k = 3 - f;
        positions.emplace_back(1.0, 2.0, -50.0 + 3.0 * k);
        frames.push_back(sliceAt("1.2.3", s.seriesUid, k, {}).stored);
        slopes.push_back(k == 2 ? 2.0 : 1.0);
    }
    vv::test::writeEnhanced(dir / "enhanced.dcm", s, positions, frames, slopes);
    const auto scan = vv::dicom::scanDicom(dir);
    ASSERT_EQ(scan.allSeries().size(), 1U);
    EXPECT_TRUE(scan.allSeries()[0]->multiFrame);
    EXPECT_EQ(scan.allSeries()[0]->imageCount, 4U);
    const auto v = vv::dicom::loadDicomVolume(dir);
    EXPECT_TRUE(v.warnings.empty());
    ASSERT_EQ(v.volume.dims(), glm::ivec3(16, 16, 4));
    EXPECT_NEAR(v.volume.spacing().z, 3.0, 1e-9);
    for (int k = 0; k < 4; ++k) {
        EXPECT_FLOAT_EQ(v.volume.value(5, 6, k),
                        static_cast<float>(pattern(5, 6, k) * (k == 2 ? 2.0 : 1.0)));
    }
    EXPECT_NEAR(v.volume.worldPosition({0, 0, 0}).z, -50.0, 1e-9);
}

TEST(DicomLoad, NuclearMedicineFramesUseDetectorGeometryAndSpacing) {
    const fs::path dir = freshDir("nm");
    const fs::path file = dir / "nm.dcm";
    DcmFileFormat ff;
    DcmDataset* d = ff.getDataset();
    TestSlice s = sliceAt("1.2.3", vv::test::newUid(), 0, {0, 0, 0});
    s.modality = "NM";
    s.sopClass = UID_NuclearMedicineImageStorage;
    s.isSigned = false;
    vv::test::putCommon(d, s);
    d->putAndInsertString(DCM_NumberOfFrames, "5");
    d->putAndInsertString(DCM_SpacingBetweenSlices, "4.5");
    d->putAndInsertString(DCM_PixelSpacing, "2\\2");
    DcmItem* detector = nullptr;
    d->findOrCreateSequenceItem(DCM_DetectorInformationSequence, detector, -2);
    detector->putAndInsertString(DCM_ImagePositionPatient, "-16\\-16\\100");
    detector->putAndInsertString(DCM_ImageOrientationPatient, "1\\0\\0\\0\\1\\0");
    std::vector<Uint16> px(16 * 16 * 5);
    for (std::size_t n = 0; n < px.size(); ++n) {
        px[n] = static_cast<Uint16>(n / 256 * 100 + n % 7);  // frame f: 100 f + ...
    }
    d->putAndInsertUint16Array(DCM_PixelData, px.data(), static_cast<unsigned long>(px.size()));
    ASSERT_TRUE(ff.saveFile(file.c_str(), EXS_LittleEndianExplicit).good());
    const auto v = vv::dicom::loadDicomVolume(file);
    EXPECT_TRUE(v.warnings.empty()) << v.warnings.front().message;
    ASSERT_EQ(v.volume.dims(), glm::ivec3(16, 16, 5));
    EXPECT_NEAR(v.volume.spacing().z, 4.5, 1e-9);
    EXPECT_NEAR(v.volume.spacing().x, 2.0, 1e-9);
    EXPECT_NEAR(v.volume.worldPosition({0, 0, 4}).z, 118.0, 1e-9);
    for (int f = 0; f < 5; ++f) {
        EXPECT_FLOAT_EQ(v.volume.value(0, 0, f),
                        static_cast<float>(px[static_cast<std::size_t>(f) * 256]));
    }
}

// ---------------------------------------------------------------------------
// Transfer syntaxes: one 12-bit CT-like image written in each.

struct SyntaxCase {
    const char* name;
    E_TransferSyntax xfer;
    int tolerance;  ///< 0 = lossless
};

class DicomTransferSyntax : public ::testing::TestWithParam<SyntaxCase> {};

TEST_P(DicomTransferSyntax, DecodesLikeTheUncompressedImage) {
    const SyntaxCase& c = GetParam();
    const fs::path dir = freshDir(std::string("xfer-") + c.name);
    TestSlice s = sliceAt("1.2.3", vv::test::newUid(), 0, {0, 0, 0}, 32, 40);
    s.isSigned = false;
    s.bitsStored = 12;
    s.intercept = -1024;
    for (std::size_t n = 0; n < s.stored.size(); ++n) {
        s.stored[n] = static_cast<std::int32_t>((n * 37) % 4096);
    }
    std::unique_ptr<DcmRepresentationParameter> param;
    if (c.xfer == EXS_JPEGProcess14SV1) {
        param = std::make_unique<DJ_RPLossless>();
    } else if (c.xfer == EXS_JPEGProcess2_4) {
        param = std::make_unique<DJ_RPLossy>(95);
    } else if (c.xfer == EXS_JPEGLSLossless) {
        param = std::make_unique<DJLSRepresentationParameter>(0, OFTrue);
    } else if (c.xfer == EXS_JPEGLSLossy) {
        param = std::make_unique<DJLSRepresentationParameter>(2, OFFalse);
    }
    if (c.xfer == EXS_JPEGProcess1) {  // baseline: 8 bits
        s.bitsAllocated = 8;
        s.bitsStored = 8;
        for (std::size_t n = 0; n < s.stored.size(); ++n) {
            s.stored[n] = static_cast<std::int32_t>((n % 40) * 6);  // smooth ramp
        }
        param = std::make_unique<DJ_RPLossy>(100);
    }
    const fs::path file = dir / "image.dcm";
    vv::test::writeSlice(file, s, c.xfer, param.get());
    const auto scan = vv::dicom::scanDicom(file);
    ASSERT_EQ(scan.allSeries().size(), 1U);
    EXPECT_EQ(scan.allSeries()[0]->transferSyntaxUid, DcmXfer(c.xfer).getXferID());
    const auto v = vv::dicom::loadDicomVolume(file);
    ASSERT_EQ(v.volume.dims(), glm::ivec3(40, 32, 1));
    int worst = 0;
    for (int j = 0; j < 32; ++j) {
        for (int i = 0; i < 40; ++i) {
            const float expected =
                static_cast<float>(s.stored[static_cast<std::size_t>(j * 40 + i)]) - 1024.0F;
            worst = std::max(worst, static_cast<int>(std::abs(v.volume.value(i, j, 0) - expected)));
        }
    }
    EXPECT_LE(worst, c.tolerance) << c.name;
}

INSTANTIATE_TEST_SUITE_P(All, DicomTransferSyntax,
                         ::testing::Values(SyntaxCase{"ImplicitLE", EXS_LittleEndianImplicit, 0},
                                           SyntaxCase{"ExplicitLE", EXS_LittleEndianExplicit, 0},
                                           SyntaxCase{"ExplicitBE", EXS_BigEndianExplicit, 0},
                                           SyntaxCase{"Deflated", EXS_DeflatedLittleEndianExplicit,
                                                      0},
                                           SyntaxCase{"RLE", EXS_RLELossless, 0},
                                           SyntaxCase{"JpegLossless", EXS_JPEGProcess14SV1, 0},
                                           SyntaxCase{"JpegExtended", EXS_JPEGProcess2_4, 40},
                                           SyntaxCase{"JpegBaseline", EXS_JPEGProcess1, 8},
                                           SyntaxCase{"JpegLsLossless", EXS_JPEGLSLossless, 0},
                                           SyntaxCase{"JpegLsNearLossless", EXS_JPEGLSLossy, 2}),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(DicomLoad, ConcurrentLoadsDecodeTheSame) {
    // The decoders are registered once (std::call_once) and DCMTK's codec
    // list is shared: several threads decoding at once must agree.
    const fs::path dir = freshDir("threads");
    TestSlice s = sliceAt("1.2.3", vv::test::newUid(), 0, {0, 0, 0}, 64, 64);
    DJLSRepresentationParameter lossless(0, OFTrue);
    vv::test::writeSlice(dir / "jls.dcm", s, EXS_JPEGLSLossless, &lossless);
    DJ_RPLossless jpeg;
    vv::test::writeSlice(dir / "jpeg.dcm", s, EXS_JPEGProcess14SV1, &jpeg);
    vv::test::writeSlice(dir / "rle.dcm", s, EXS_RLELossless);
    std::atomic<int> good{0};
    std::atomic<int> bad{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < 6; ++t) {
        threads.emplace_back([&, t] {
            const char* names[] = {"jls.dcm", "jpeg.dcm", "rle.dcm"};
            for (int round = 0; round < 4; ++round) {
                try {
                    const auto v = vv::dicom::loadDicomVolume(dir / names[(t + round) % 3]);
                    const bool same =
                        v.volume.value(9, 17, 0) == static_cast<float>(pattern(9, 17, 0) - 24);
                    (same ? good : bad)++;
                } catch (const std::exception&) {
                    bad++;
                }
            }
        });
    }
    for (auto& t : threads) {
        t.join();
    }
    EXPECT_EQ(good.load(), 24);
    EXPECT_EQ(bad.load(), 0);
}

TEST(DicomLoad, Jpeg2000IsRefusedWithAClearMessage) {
    const fs::path dir = freshDir("j2k");
    const fs::path file = dir / "j2k.dcm";
    {
        TestSlice s = sliceAt("1.2.3", vv::test::newUid(), 0, {0, 0, 0});
        vv::test::writeSlice(file, s);
        // Re-label as JPEG 2000 with an encapsulated (garbage) stream.
        DcmFileFormat ff;
        ASSERT_TRUE(ff.loadFile(file.c_str()).good());
        DcmDataset* d = ff.getDataset();
        d->findAndDeleteElement(DCM_PixelData);
        auto* pixel = new DcmPixelData(DCM_PixelData);
        auto* seq = new DcmPixelSequence(DcmTag(DCM_PixelData, EVR_OB));
        seq->insert(new DcmPixelItem(DcmTag(DCM_Item, EVR_OB)));  // offset table
        auto* item = new DcmPixelItem(DcmTag(DCM_Item, EVR_OB));
        const Uint8 junk[8] = {0xFF, 0x4F, 0xFF, 0x51, 0, 0, 0, 0};
        item->putUint8Array(junk, 8);
        seq->insert(item);
        pixel->putOriginalRepresentation(EXS_JPEG2000LosslessOnly, nullptr, seq);
        d->insert(pixel, true);
        ASSERT_TRUE(ff.saveFile(file.c_str(), EXS_JPEG2000LosslessOnly).good());
    }
    const auto scan = vv::dicom::scanDicom(file);
    ASSERT_EQ(scan.allSeries().size(), 1U);
    EXPECT_THAT(scan.allSeries()[0]->unsupportedReason, HasSubstr("JPEG 2000"));
    try {
        (void)vv::dicom::loadDicomVolume(file);
        FAIL() << "JPEG 2000 loaded";
    } catch (const vv::FormatError& e) {
        EXPECT_THAT(e.what(), HasSubstr("JPEG 2000 is not supported (DCMTK has no decoder)"));
        EXPECT_THAT(e.what(), HasSubstr("j2k.dcm"));
    }
}

// ---------------------------------------------------------------------------
// Memory and big series.

TEST(DicomLoad, HugeDeclaredVolumeIsRefusedBeforeAllocating) {
    const fs::path dir = freshDir("huge");
    const fs::path file = dir / "huge.dcm";
    {
        DcmFileFormat ff;
        DcmDataset* d = ff.getDataset();
        TestSlice s = sliceAt("1.2.3", vv::test::newUid(), 0, {0, 0, 0});
        s.rows = 60000;
        s.columns = 60000;
        vv::test::putCommon(d, s);
        d->putAndInsertString(DCM_NumberOfFrames, "50000");
        d->putAndInsertString(DCM_ImagePositionPatient, "0\\0\\0");
        d->putAndInsertString(DCM_ImageOrientationPatient, "1\\0\\0\\0\\1\\0");
        d->putAndInsertString(DCM_SpacingBetweenSlices, "1");
        const Uint16 px[4] = {1, 2, 3, 4};
        d->putAndInsertUint16Array(DCM_PixelData, px, 4);
        ASSERT_TRUE(ff.saveFile(file.c_str(), EXS_LittleEndianExplicit).good());
    }
    const auto scan = vv::dicom::scanDicom(file);
    ASSERT_EQ(scan.allSeries().size(), 1U);
    EXPECT_EQ(scan.allSeries()[0]->imageCount, 50000U);
    try {
        (void)vv::dicom::loadDicomVolume(file);
        FAIL() << "a 360 TB volume loaded";
    } catch (const vv::scene::MemoryError& e) {
        EXPECT_THAT(e.what(), HasSubstr("huge.dcm"));
        EXPECT_THAT(e.what(), HasSubstr("memory is available"));
        EXPECT_THAT(e.what(), HasSubstr("60000 x 60000 x 50000"));
        expectNoPatientData(e.what());
    }
    EXPECT_GT(vv::dicom::availableMemoryBytes(), 0U);
}

TEST(DicomLoad, TruncatedPixelDataIsAClearError) {
    const fs::path dir = freshDir("truncated");
    const fs::path file = dir / "short.dcm";
    DcmFileFormat ff;
    DcmDataset* d = ff.getDataset();
    TestSlice s = sliceAt("1.2.3", vv::test::newUid(), 0, {0, 0, 0});
    vv::test::putCommon(d, s);
    const Uint16 px[4] = {1, 2, 3, 4};
    d->putAndInsertUint16Array(DCM_PixelData, px, 4);
    ASSERT_TRUE(ff.saveFile(file.c_str(), EXS_LittleEndianExplicit).good());
    try {
        (void)vv::dicom::loadDicomVolume(file);
        FAIL();
    } catch (const vv::FormatError& e) {
        EXPECT_THAT(e.what(), HasSubstr("short.dcm"));
        EXPECT_THAT(e.what(), HasSubstr("truncated"));
    }
}

class DicomBigSeries : public ::testing::Test {
  protected:
    static constexpr int kSize = 256;
    static constexpr int kSlices = 200;
    static fs::path dir() { return fs::path(VV_TEST_TMP) / "dicom" / "big-256x256x200"; }
    /// Written once and kept between runs. ctest runs each test in its own
    /// process, two at a time: each writes into its own staging folder and
    /// renames it into place (atomic; the loser uses the winner's series).
    static void SetUpTestSuite() {
        if (fs::exists(dir() / "complete")) {
            return;
        }
        std::error_code ec;
        if (fs::exists(dir()) && !fs::exists(dir() / "complete")) {
            fs::remove_all(dir(), ec);  // left over from an interrupted run
        }
        const fs::path staging = dir().string() + ".staging-" + std::to_string(::getpid());
        fs::remove_all(staging);
        fs::create_directories(staging);
        const std::string series = "1.2.826.0.1.3680043.99.256200";
        std::vector<int> names(kSlices);
        for (int k = 0; k < kSlices; ++k) {
            names[static_cast<std::size_t>(k)] = k;
        }
        std::shuffle(names.begin(), names.end(), std::mt19937(7));
        TestSlice s = sliceAt("1.2.3", series, 0, {0, 0, 0}, kSize, kSize);
        for (int k = 0; k < kSlices; ++k) {
            s.position = glm::dvec3(-100.0, -120.0, -300.0 + 0.8 * k);
            s.instanceNumber = k + 1;
            for (int j = 0; j < kSize; ++j) {
                for (int i = 0; i < kSize; ++i) {
                    s.stored[static_cast<std::size_t>(j * kSize + i)] = (i + j + k) % 1500 - 200;
                }
            }
            vv::test::writeSlice(
                staging / ("CT" + std::to_string(names[static_cast<std::size_t>(k)])), s);
        }
        std::ofstream(staging / "complete") << "ok\n";
        fs::rename(staging, dir(), ec);
        if (ec) {
            fs::remove_all(staging, ec);  // another process was first
        }
    }
};

TEST_F(DicomBigSeries, LoadsWithProgressWithinMemory) {
    const auto scan = vv::dicom::scanDicom(dir());
    ASSERT_EQ(scan.allSeries().size(), 1U);
    const auto& series = *scan.allSeries()[0];
    EXPECT_EQ(series.imageCount, static_cast<std::size_t>(kSlices));
    std::vector<double> fractions;
    fractions.reserve(4096);
    const vv::Progress progress([&](double f, std::string_view) { fractions.push_back(f); }, {});
    // Peak memory: reset the high-water mark (Linux: clear_refs 5), load,
    // and compare the peak's growth with the volume's size.
    const bool peakReset = vv::resetPeakResident();
    const std::int64_t before = static_cast<std::int64_t>(vv::residentKiB().value_or(0));
    const auto v = vv::dicom::loadDicomSeries(series, {}, progress);
    const std::int64_t peak = static_cast<std::int64_t>(vv::peakResidentKiB().value_or(0));
    if (peakReset && before > 0 && peak > 0) {
        const double grownBytes = static_cast<double>(peak - before) * 1024.0;
        std::printf("peak growth %.1f MB for a %.1f MB volume\n", grownBytes / 1e6,
                    static_cast<double>(v.volume.byteSize()) / 1e6);
        EXPECT_LT(grownBytes, 2.0 * static_cast<double>(v.volume.byteSize()))
            << "peak grew by " << grownBytes / 1e6 << " MB for a "
            << static_cast<double>(v.volume.byteSize()) / 1e6 << " MB volume";
    }
    ASSERT_EQ(v.volume.dims(), glm::ivec3(kSize, kSize, kSlices));
    EXPECT_EQ(v.volume.voxelType(), vv::scene::VoxelType::Int16);
    EXPECT_EQ(v.volume.byteSize(), std::size_t{kSize} * kSize * kSlices * 2);
    EXPECT_TRUE(v.warnings.empty());
    EXPECT_NEAR(v.volume.spacing().z, 0.8, 1e-6);
    for (const int k : {0, 17, 199}) {
        EXPECT_FLOAT_EQ(v.volume.value(100, 7, k),
                        static_cast<float>((100 + 7 + k) % 1500 - 200 - 24));
    }
    EXPECT_GE(fractions.size(), static_cast<std::size_t>(kSlices));
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_DOUBLE_EQ(fractions.back(), 1.0);

    // A limit below the volume's size: refused up front.
    vv::dicom::DicomLoadOptions tight;
    tight.memoryLimitBytes = v.volume.byteSize() / 2;
    EXPECT_THROW((void)vv::dicom::loadDicomSeries(series, tight), vv::scene::MemoryError);
}

TEST_F(DicomBigSeries, CancelStopsTheLoad) {
    const auto scan = vv::dicom::scanDicom(dir());
    ASSERT_EQ(scan.allSeries().size(), 1U);
    std::stop_source stop;
    std::atomic<double> seen{0.0};
    const vv::Progress progress(
        [&](double f, std::string_view stage) {
            seen = f;
            if (stage == "Loading DICOM series" && f > 0.4) {
                stop.request_stop();
            }
        },
        stop.get_token());
    EXPECT_THROW((void)vv::dicom::loadDicomSeries(*scan.allSeries()[0], {}, progress),
                 vv::CancelledError);
    EXPECT_LT(seen.load(), 0.6);
}

}  // namespace
