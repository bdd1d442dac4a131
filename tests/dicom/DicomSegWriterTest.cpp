// SPDX-License-Identifier: GPL-3.0-or-later
// Writing label maps as DICOM SEG (vv/dicom/DicomSegWriter.h): read back with
// the SEG reader, the same voxels in the same places, the study given.
#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <set>
#include <string>

#include "vv/core/Error.h"
#include "vv/dicom/DicomSeg.h"
#include "vv/dicom/DicomSegWriter.h"

namespace dicom_seg_writer_test {

namespace {

namespace fs = std::filesystem;
using vv::scene::LabelMap;

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(VV_TEST_TMP) / "dicom-seg-writer" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// 20 x 16 x 12 voxels of 0.7 x 0.9 x 1.5 mm, turned 30 degrees about z,
/// away from the origin: a ball (label 1) and a slab (label 2).
LabelMap twoShapes() {
    LabelMap map;
    map.dims = {20, 16, 12};
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(-40.0, 12.5, 230.0));
    m = glm::rotate(m, std::acos(-1.0) / 6.0, glm::dvec3(0.0, 0.0, 1.0));
    map.indexToWorld = glm::scale(m, glm::dvec3(0.7, 0.9, 1.5));
    map.labels.assign(static_cast<std::size_t>(20 * 16 * 12), 0);
    for (int k = 0; k < 12; ++k) {
        for (int j = 0; j < 16; ++j) {
            for (int i = 0; i < 20; ++i) {
                const double r2 = (i - 6) * (i - 6) + (j - 8) * (j - 8) + (k - 5) * (k - 5);
                if (r2 <= 9.0) {
                    map.labels[map.index(i, j, k)] = 1;
                } else if (i >= 14 && k >= 2 && k <= 8) {
                    map.labels[map.index(i, j, k)] = 2;
                }
            }
        }
    }
    map.segmentNames = {"ball", "slab"};
    return map;
}

/// The world positions (0.01 mm grid) of the voxels labelled `label`.
std::set<std::array<long, 3>> worldVoxels(const LabelMap& map, std::uint8_t label) {
    std::set<std::array<long, 3>> points;
    for (int k = 0; k < map.dims.z; ++k) {
        for (int j = 0; j < map.dims.y; ++j) {
            for (int i = 0; i < map.dims.x; ++i) {
                if (map.labels[map.index(i, j, k)] == label) {
                    const glm::dvec4 p = map.indexToWorld * glm::dvec4(i, j, k, 1.0);
                    points.insert({std::lround(p.x * 100.0), std::lround(p.y * 100.0),
                                   std::lround(p.z * 100.0)});
                }
            }
        }
    }
    return points;
}

vv::dicom::ExportStudy study() {
    vv::dicom::ExportStudy s;
    s.studyInstanceUid = "1.2.826.0.1.3680043.8.498.4242";
    s.studyDate = "20250101";
    s.patient = vv::dicom::ExportPatient{"Doe^Jane", "VV-SEG-1", "19700101", "F", "", "", false};
    return s;
}

std::string attribute(DcmDataset& data, const DcmTagKey& tag) {
    OFString value;
    data.findAndGetOFString(tag, value);
    return value.c_str();
}

TEST(DicomSegWriter, WritesEveryLabelAsASegmentThatReadsBackInPlace) {
    const LabelMap map = twoShapes();
    const fs::path file = freshDir("two") / "seg.dcm";
    vv::dicom::ExportSeries series;
    series.description = "VesselView segmentation";
    series.seriesNumber = 901;
    const std::string sop = vv::dicom::writeDicomSeg(file, map, study(), "1.2.3.4.5", series);
    ASSERT_TRUE(vv::dicom::isDicomSegFile(file));

    const auto maps = vv::dicom::loadDicomSegLabelMaps(file);
    ASSERT_EQ(maps.size(), 2U);
    EXPECT_EQ(maps[0].segmentNames, std::vector<std::string>{"ball"});
    EXPECT_EQ(maps[1].segmentNames, std::vector<std::string>{"slab"});
    for (std::size_t s = 0; s < 2; ++s) {
        const auto written = worldVoxels(map, static_cast<std::uint8_t>(s + 1));
        ASSERT_FALSE(written.empty());
        EXPECT_EQ(worldVoxels(maps[s], 1), written) << map.segmentNames[s];
    }

    DcmFileFormat dicom;
    ASSERT_TRUE(dicom.loadFile(file.c_str()).good());
    DcmDataset& data = *dicom.getDataset();
    EXPECT_EQ(attribute(data, DCM_Modality), "SEG");
    EXPECT_EQ(attribute(data, DCM_SOPInstanceUID), sop);
    EXPECT_EQ(attribute(data, DCM_StudyInstanceUID), study().studyInstanceUid);
    EXPECT_EQ(attribute(data, DCM_FrameOfReferenceUID), "1.2.3.4.5");
    EXPECT_EQ(attribute(data, DCM_PatientID), "VV-SEG-1");
    EXPECT_EQ(attribute(data, DCM_PatientName), "Doe^Jane");
    EXPECT_EQ(attribute(data, DCM_SeriesDescription), "VesselView segmentation");
    EXPECT_EQ(attribute(data, DCM_SeriesNumber), "901");
}

TEST(DicomSegWriter, AnonymisedStudyLeavesThePatientOut) {
    vv::dicom::ExportStudy s = study();
    s.patient->anonymise = true;
    const fs::path file = freshDir("anonymised") / "seg.dcm";
    (void)vv::dicom::writeDicomSeg(file, twoShapes(), s, "", {});
    DcmFileFormat dicom;
    ASSERT_TRUE(dicom.loadFile(file.c_str()).good());
    EXPECT_EQ(attribute(*dicom.getDataset(), DCM_PatientID), "");
    EXPECT_EQ(attribute(*dicom.getDataset(), DCM_PatientName), "");
    EXPECT_FALSE(attribute(*dicom.getDataset(), DCM_FrameOfReferenceUID).empty());
}

TEST(DicomSegWriter, EmptyOrUnlabelledMapsAreRefusedAndNothingIsWritten) {
    const fs::path dir = freshDir("refused");
    LabelMap empty;
    EXPECT_THROW(vv::dicom::writeDicomSeg(dir / "a.dcm", empty, study(), "", {}),
                 vv::InvalidArgumentError);
    LabelMap blank = twoShapes();
    std::fill(blank.labels.begin(), blank.labels.end(), 0);
    EXPECT_THROW(vv::dicom::writeDicomSeg(dir / "b.dcm", blank, study(), "", {}),
                 vv::InvalidArgumentError);
    LabelMap wrong = twoShapes();
    wrong.labels.pop_back();
    EXPECT_THROW(vv::dicom::writeDicomSeg(dir / "c.dcm", wrong, study(), "", {}),
                 vv::InvalidArgumentError);
    EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace

}  // namespace dicom_seg_writer_test
