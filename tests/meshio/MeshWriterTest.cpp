// SPDX-License-Identifier: GPL-3.0-or-later
// Writing VTP: round trips through the loader, atomic writes, failures.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "vv/core/Error.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/meshio/MeshWriter.h"

namespace mesh_writer_test {

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using vv::scene::DataArray;
using vv::scene::Mesh;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

class MeshWriterTest : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::path(VV_TEST_TMP) / "io-writer" /
               (std::string(info->test_suite_name()) + "." + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }

    /// Names of everything in the test folder.
    [[nodiscard]] std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_)) {
            names.push_back(entry.path().filename().string());
        }
        std::sort(names.begin(), names.end());
        return names;
    }

    fs::path dir_;
};

/// An octahedron (6 vertices, 8 triangles) with arrays of every kind.
Mesh sampleMesh() {
    Mesh m;
    m.name = "sample";
    m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 2, 0}, {0, -2, 0}, {0, 0, 3}, {0, 0, -3}};
    m.indices = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    vv::scene::computeNormals(m);

    DataArray pressure;
    pressure.name = "pressure";
    pressure.unit = "mmHg";
    pressure.values = {80.5F, 81.25F, kNaN, 90.0F, -3.5F, 1e6F};
    DataArray velocity;
    velocity.name = "velocity";
    velocity.unit = "m/s";
    velocity.components = 3;
    for (int i = 0; i < 6; ++i) {
        velocity.values.insert(velocity.values.end(), {static_cast<float>(i), 0.5F, -1.0F});
    }
    DataArray segment;
    segment.name = "segment_id";
    segment.integer = true;
    segment.values = {0, 1, 1, 2, 3, 70000};
    m.pointArrays = {pressure, velocity, segment};

    DataArray label;
    label.name = "label";
    label.integer = true;
    label.values = {1, 1, 2, 2, 3, 3, 4, 4};
    DataArray area;
    area.name = "area";
    area.unit = "mm^2";
    area.values = {0.5F, 1.5F, 2.5F, kNaN, 4.5F, 5.5F, 6.5F, 7.5F};
    m.cellArrays = {label, area};
    return m;
}

void expectSameArray(const DataArray& a, const DataArray& b) {
    SCOPED_TRACE(a.name);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.unit, b.unit);
    EXPECT_EQ(a.components, b.components);
    EXPECT_EQ(a.integer, b.integer);
    EXPECT_EQ(a.fromCells, b.fromCells);
    ASSERT_EQ(a.values.size(), b.values.size());
    for (std::size_t i = 0; i < a.values.size(); ++i) {
        if (std::isnan(a.values[i])) {
            EXPECT_TRUE(std::isnan(b.values[i])) << "value " << i;
        } else {
            EXPECT_EQ(a.values[i], b.values[i]) << "value " << i;
        }
    }
    EXPECT_EQ(a.nonFiniteCount(), b.nonFiniteCount());
    EXPECT_EQ(a.finiteRange(), b.finiteRange());
}

TEST_F(MeshWriterTest, RoundTripKeepsEverything) {
    const Mesh original = sampleMesh();
    const auto file = dir_ / "sample.vtp";
    vv::meshio::writeVtp(original, file);

    vv::meshio::MeshLoadOptions options;
    options.cellArraysToPoints = false;
    const Mesh loaded = vv::meshio::loadMesh(file, options);
    EXPECT_EQ(loaded.vertexCount(), original.vertexCount());
    EXPECT_EQ(loaded.triangleCount(), original.triangleCount());
    EXPECT_EQ(loaded.positions, original.positions);
    EXPECT_EQ(loaded.indices, original.indices);
    ASSERT_EQ(loaded.normals.size(), original.normals.size());
    for (std::size_t i = 0; i < loaded.normals.size(); ++i) {
        EXPECT_NEAR(glm::length(loaded.normals[i] - original.normals[i]), 0.0F, 1e-6F);
    }
    ASSERT_EQ(loaded.pointArrays.size(), original.pointArrays.size());
    for (std::size_t i = 0; i < loaded.pointArrays.size(); ++i) {
        expectSameArray(original.pointArrays[i], loaded.pointArrays[i]);
    }
    ASSERT_EQ(loaded.cellArrays.size(), original.cellArrays.size());
    for (std::size_t i = 0; i < loaded.cellArrays.size(); ++i) {
        expectSameArray(original.cellArrays[i], loaded.cellArrays[i]);
    }
    EXPECT_EQ(loaded.name, "sample");
}

TEST_F(MeshWriterTest, ConvertedArraysAreNotWrittenTwice) {
    const auto first = dir_ / "first.vtp";
    vv::meshio::writeVtp(sampleMesh(), first);
    const Mesh loaded = vv::meshio::loadMesh(first);  // adds label and area as point arrays
    ASSERT_EQ(loaded.pointArrays.size(), 5U);
    EXPECT_TRUE(loaded.pointArrays[3].fromCells);

    const auto second = dir_ / "second.vtp";
    vv::meshio::writeVtp(loaded, second);
    const Mesh again = vv::meshio::loadMesh(second);
    ASSERT_EQ(again.pointArrays.size(), loaded.pointArrays.size());
    for (std::size_t i = 0; i < again.pointArrays.size(); ++i) {
        expectSameArray(loaded.pointArrays[i], again.pointArrays[i]);
    }
    ASSERT_EQ(again.cellArrays.size(), loaded.cellArrays.size());
}

TEST_F(MeshWriterTest, FileIsCompressedBinaryXmlWithUnitsInNames) {
    const auto file = dir_ / "sample.vtp";
    vv::meshio::writeVtp(sampleMesh(), file);
    std::ifstream in(file, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_THAT(text, HasSubstr("<VTKFile type=\"PolyData\""));
    EXPECT_THAT(text, HasSubstr("compressor=\"vtkZLibDataCompressor\""));
    EXPECT_THAT(text, HasSubstr("format=\"binary\""));
    EXPECT_THAT(text, ::testing::Not(HasSubstr("format=\"ascii\"")));
    EXPECT_THAT(text, HasSubstr("Name=\"pressure [mmHg]\""));
    EXPECT_THAT(text, HasSubstr("Name=\"area [mm^2]\""));
    EXPECT_THAT(text, HasSubstr("type=\"Int32\" Name=\"segment_id\""));
}

TEST_F(MeshWriterTest, IntegerArrayWithNaNIsWrittenAsFloat) {
    Mesh m = sampleMesh();
    m.pointArrays[2].values[1] = kNaN;  // segment_id: NaN cannot be an int
    const auto file = dir_ / "nan-ids.vtp";
    vv::meshio::writeVtp(m, file);
    vv::meshio::MeshLoadOptions options;
    options.cellArraysToPoints = false;
    const Mesh loaded = vv::meshio::loadMesh(file, options);
    const auto* ids = loaded.pointArray("segment_id");
    ASSERT_NE(ids, nullptr);
    EXPECT_FALSE(ids->integer);
    EXPECT_TRUE(std::isnan(ids->values[1]));
    EXPECT_EQ(ids->values[5], 70000.0F);
}

TEST_F(MeshWriterTest, OverwritesAtomicallyAndLeavesNoTemporaryFiles) {
    const auto file = dir_ / "mesh.vtp";
    { std::ofstream(file) << "old content"; }
    vv::meshio::writeVtp(sampleMesh(), file);
    vv::meshio::writeVtp(sampleMesh(), file);
    EXPECT_EQ(listing(), std::vector<std::string>{"mesh.vtp"});
    EXPECT_EQ(vv::meshio::loadMesh(file).vertexCount(), 6U);
}

TEST_F(MeshWriterTest, MissingFolderThrowsIoErrorAndLeavesNothing) {
    const auto file = dir_ / "missing" / "mesh.vtp";
    try {
        vv::meshio::writeVtp(sampleMesh(), file);
        FAIL() << "no exception";
    } catch (const vv::IoError& e) {
        EXPECT_THAT(e.what(), HasSubstr(file.string()));
        EXPECT_EQ(e.file(), file);
    }
    EXPECT_FALSE(fs::exists(dir_ / "missing"));
    EXPECT_TRUE(listing().empty());
}

TEST_F(MeshWriterTest, FolderAsTargetOrParentThrowsIoError) {
    fs::create_directories(dir_ / "taken.vtp");
    EXPECT_THROW(vv::meshio::writeVtp(sampleMesh(), dir_ / "taken.vtp"), vv::IoError);
    { std::ofstream(dir_ / "plain-file") << "x"; }
    EXPECT_THROW(vv::meshio::writeVtp(sampleMesh(), dir_ / "plain-file" / "mesh.vtp"), vv::IoError);
    EXPECT_EQ(listing(), (std::vector<std::string>{"plain-file", "taken.vtp"}));
}

TEST_F(MeshWriterTest, InconsistentMeshIsRefusedWithoutWriting) {
    const auto file = dir_ / "bad.vtp";
    Mesh outOfRange = sampleMesh();
    outOfRange.indices[4] = 6;
    EXPECT_THROW(vv::meshio::writeVtp(outOfRange, file), vv::InvalidArgumentError);
    Mesh shortArray = sampleMesh();
    shortArray.pointArrays[0].values.pop_back();
    EXPECT_THROW(vv::meshio::writeVtp(shortArray, file), vv::InvalidArgumentError);
    Mesh duplicate = sampleMesh();
    duplicate.cellArrays[1].name = "label";
    EXPECT_THROW(vv::meshio::writeVtp(duplicate, file), vv::InvalidArgumentError);
    Mesh unnamed = sampleMesh();
    unnamed.pointArrays[1].name.clear();
    EXPECT_THROW(vv::meshio::writeVtp(unnamed, file), vv::InvalidArgumentError);
    EXPECT_TRUE(listing().empty());
}

// writeMeshFile: STL and PLY (the formats 3-D printing and other tools
// read) load back with the same geometry, and none leaves a temporary file
// (VTK's PLY writer appends ".ply" to a name without it: the writer must not
// leave that one behind either, on success or failure).
TEST_F(MeshWriterTest, StlAndPlyRoundTripTheGeometryAndLeaveNoTemporaryFiles) {
    vv::meshio::MeshFileMetadata metadata;
    metadata.summary = "solid-looking header " + std::string(100, 'x');
    metadata.fields = {{"software", "VesselView test"}, {"note", "two\nlines"}};
    for (const char* name : {"mesh.stl", "mesh.ply", "MESH2.PLY", "mesh.vtp"}) {
        SCOPED_TRACE(name);
        vv::meshio::writeMeshFile(sampleMesh(), dir_ / name, metadata);
        const Mesh loaded = vv::meshio::loadMesh(dir_ / name);
        EXPECT_EQ(loaded.triangleCount(), 8U);
        EXPECT_EQ(loaded.bounds().min, glm::vec3(-1, -2, -3));
        EXPECT_EQ(loaded.bounds().max, glm::vec3(1, 2, 3));
    }
    EXPECT_EQ(listing(),
              (std::vector<std::string>{"MESH2.PLY", "mesh.ply", "mesh.stl", "mesh.vtp"}));
    // The STL header: 80 bytes at most, not "solid" (an ASCII STL's start).
    std::ifstream stl(dir_ / "mesh.stl", std::ios::binary);
    std::string header(80, '\0');
    stl.read(header.data(), 80);
    EXPECT_EQ(header.rfind("Solid-looking header xxx", 0), 0U) << header;

    EXPECT_THROW(vv::meshio::writeMeshFile(sampleMesh(), dir_ / "missing" / "m.ply", metadata),
                 vv::IoError);
    EXPECT_THROW(vv::meshio::writeMeshFile(sampleMesh(), dir_ / "mesh.obj", metadata),
                 vv::InvalidArgumentError);
    EXPECT_EQ(listing(),
              (std::vector<std::string>{"MESH2.PLY", "mesh.ply", "mesh.stl", "mesh.vtp"}));
}

TEST_F(MeshWriterTest, MeshWithoutNormalsOrArrays) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2};
    const auto file = dir_ / "plain.vtp";
    vv::meshio::writeVtp(m, file);
    const Mesh loaded = vv::meshio::loadMesh(file);
    EXPECT_EQ(loaded.triangleCount(), 1U);
    ASSERT_EQ(loaded.normals.size(), 3U);
    EXPECT_NEAR(loaded.normals[0].z, 1.0F, 1e-6F);
    EXPECT_TRUE(loaded.pointArrays.empty());
    EXPECT_TRUE(loaded.cellArrays.empty());
}

}  // namespace

namespace {

// Label names travel as the field-data string array "<array>_names"
// ("<value>=<name>" entries) and come back for point and cell arrays.
TEST_F(MeshWriterTest, LabelNamesRoundTripThroughFieldData) {
    Mesh mesh = sampleMesh();
    mesh.labelNames["segment_id"] = {{2, "Left iliac"}, {70000, "Renal artery"}};
    mesh.labelNames["label"] = {{4, "Aneurysm sac"}};
    const fs::path file = dir_ / "named.vtp";
    vv::meshio::writeVtp(mesh, file);
    const Mesh back = vv::meshio::loadMesh(file);
    ASSERT_TRUE(back.labelNames.contains("segment_id"));
    EXPECT_EQ(back.labelNames.at("segment_id"), mesh.labelNames.at("segment_id"));
    // The cell array's names also name the point array made from it.
    bool cellNamed = false;
    for (const auto& [array, names] : back.labelNames) {
        cellNamed = cellNamed || (names.contains(4) && names.at(4) == "Aneurysm sac");
    }
    EXPECT_TRUE(cellNamed);
}

// A legacy VTK file as centreline tools write it: names by position
// ("Aorta" names label 0) or as "<value>=<name>" entries.
TEST_F(MeshWriterTest, LabelNamesFromLegacyFieldData) {
    const fs::path file = dir_ / "branches.vtk";
    std::ofstream(file) << "# vtk DataFile Version 3.0\nbranches\nASCII\nDATASET POLYDATA\n"
                           "FIELD FieldData 2\n"
                           "branch_names 1 2 string\nAorta\nLeft%20iliac\n"
                           "group_names 1 1 string\n200=Renal%20artery\n"
                           "POINTS 3 float\n0 0 0\n1 0 0\n0 1 0\n"
                           "POLYGONS 1 4\n3 0 1 2\n"
                           "POINT_DATA 3\nSCALARS branch int 1\nLOOKUP_TABLE default\n0\n1\n1\n"
                           "SCALARS group int 1\nLOOKUP_TABLE default\n200\n200\n5\n";
    const Mesh mesh = vv::meshio::loadMesh(file);
    ASSERT_TRUE(mesh.labelNames.contains("branch"));
    EXPECT_EQ(mesh.labelNames.at("branch").at(0), "Aorta");
    EXPECT_EQ(mesh.labelNames.at("branch").at(1), "Left iliac");
    ASSERT_TRUE(mesh.labelNames.contains("group"));
    EXPECT_EQ(mesh.labelNames.at("group").size(), 1U);
    EXPECT_EQ(mesh.labelNames.at("group").at(200), "Renal artery");
}

}  // namespace

}  // namespace mesh_writer_test
