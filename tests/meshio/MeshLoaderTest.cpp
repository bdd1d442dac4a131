// SPDX-License-Identifier: GPL-3.0-or-later
// Loading meshes: every format, arrays and units, options, progress, and the
// malformed files every loader must refuse with a clear error (and without
// crashing, hanging, printing or touching the file).
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <stop_token>
#include <string>
#include <vector>

#include "GermanLocale.h"
#include "Unprivileged.h"
#include "vv/core/Error.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/meshio/MeshWriter.h"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using vv::meshio::loadMesh;
using vv::meshio::MeshLoadOptions;
using vv::scene::Mesh;

using Bytes = std::vector<unsigned char>;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// ---------------------------------------------------------------------------
// Test data: a 2 x 3 x 4 mm box, 8 corners, 12 outward triangles.

struct Tri {
    glm::vec3 a, b, c;
};

std::vector<glm::vec3> boxCorners() {
    std::vector<glm::vec3> p;
    for (int i = 0; i < 8; ++i) {
        p.emplace_back((i & 1) != 0 ? 2.0F : 0.0F, (i & 2) != 0 ? 3.0F : 0.0F,
                       (i & 4) != 0 ? 4.0F : 0.0F);
    }
    return p;
}

const std::vector<std::uint32_t>& boxIndices() {
    static const std::vector<std::uint32_t> indices = {
        0, 2, 3, 0, 3, 1,  // z = 0
        4, 5, 7, 4, 7, 6,  // z = 4
        0, 1, 5, 0, 5, 4,  // y = 0
        2, 6, 7, 2, 7, 3,  // y = 3
        0, 4, 6, 0, 6, 2,  // x = 0
        1, 3, 7, 1, 7, 5,  // x = 2
    };
    return indices;
}

std::vector<Tri> boxTriangles() {
    const auto p = boxCorners();
    const auto& idx = boxIndices();
    std::vector<Tri> tris;
    for (std::size_t t = 0; t < idx.size(); t += 3) {
        tris.push_back({p[idx[t]], p[idx[t + 1]], p[idx[t + 2]]});
    }
    return tris;
}

std::string num(float v) {
    std::ostringstream s;
    s.precision(9);
    s << v;
    return s.str();
}

std::string asciiStl(const std::vector<Tri>& tris) {
    std::string s = "solid box\n";
    for (const auto& t : tris) {
        s += "  facet normal 0 0 0\n    outer loop\n";
        for (const auto& v : {t.a, t.b, t.c}) {
            s += "      vertex " + num(v.x) + " " + num(v.y) + " " + num(v.z) + "\n";
        }
        s += "    endloop\n  endfacet\n";
    }
    s += "endsolid box\n";
    return s;
}

void putLe32(Bytes& b, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) {
        b.push_back(static_cast<unsigned char>(v >> (8 * k)));
    }
}
void putBe32(Bytes& b, std::uint32_t v) {
    for (int k = 3; k >= 0; --k) {
        b.push_back(static_cast<unsigned char>(v >> (8 * k)));
    }
}
void putLeFloat(Bytes& b, float f) {
    putLe32(b, std::bit_cast<std::uint32_t>(f));
}
void putBeFloat(Bytes& b, float f) {
    putBe32(b, std::bit_cast<std::uint32_t>(f));
}
void putText(Bytes& b, const std::string& s) {
    b.insert(b.end(), s.begin(), s.end());
}

Bytes binaryStl(const std::vector<Tri>& tris, const std::string& header = "binary box",
                std::optional<std::uint32_t> claimed = std::nullopt) {
    Bytes b(80, 0);
    std::memcpy(b.data(), header.data(), std::min<std::size_t>(header.size(), 80));
    putLe32(b, claimed.value_or(static_cast<std::uint32_t>(tris.size())));
    for (const auto& t : tris) {
        for (int k = 0; k < 3; ++k)
            putLeFloat(b, 0.0F);  // facet normal: ignored
        for (const auto& v : {t.a, t.b, t.c}) {
            putLeFloat(b, v.x);
            putLeFloat(b, v.y);
            putLeFloat(b, v.z);
        }
        b.push_back(0);
        b.push_back(0);
    }
    return b;
}

std::string boxObj(bool withNormals = false) {
    std::string s = "# box\n";
    for (const auto& p : boxCorners()) {
        s += "v " + num(p.x) + " " + num(p.y) + " " + num(p.z) + "\n";
    }
    if (withNormals) {
        s += "vn 0 0 1\n";
    }
    const auto& idx = boxIndices();
    for (std::size_t t = 0; t < idx.size(); t += 3) {
        s += "f";
        for (int k = 0; k < 3; ++k) {
            s += " " + std::to_string(idx[t + static_cast<std::size_t>(k)] + 1) +
                 (withNormals ? "//1" : "");
        }
        s += "\n";
    }
    return s;
}

/// ASCII PLY of the box with a vertex property `temp` (NaN at vertex 5) and an
/// int face property `label` (0 for the first 6 faces, 1 after).
std::string boxPlyAscii() {
    std::string s =
        "ply\nformat ascii 1.0\ncomment test box\nelement vertex 8\n"
        "property float x\nproperty float y\nproperty float z\nproperty float temp\n"
        "element face 12\nproperty list uchar int vertex_indices\nproperty int label\n"
        "end_header\n";
    const auto p = boxCorners();
    for (std::size_t i = 0; i < p.size(); ++i) {
        s += num(p[i].x) + " " + num(p[i].y) + " " + num(p[i].z) + " " +
             (i == 5 ? std::string("nan") : num(static_cast<float>(i) * 1.5F)) + "\n";
    }
    const auto& idx = boxIndices();
    for (std::size_t t = 0; t < idx.size(); t += 3) {
        s += "3 " + std::to_string(idx[t]) + " " + std::to_string(idx[t + 1]) + " " +
             std::to_string(idx[t + 2]) + " " + (t / 3 < 6 ? "0" : "1") + "\n";
    }
    return s;
}

/// Binary PLY of the box with per-vertex normals nx ny nz (all +z).
Bytes boxPlyBinary(bool bigEndian) {
    Bytes b;
    putText(b, std::string("ply\nformat ") +
                   (bigEndian ? "binary_big_endian" : "binary_little_endian") +
                   " 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float "
                   "z\nproperty float nx\nproperty float ny\nproperty float nz\nelement face 12\n"
                   "property list uchar int vertex_indices\nend_header\n");
    const auto put = [&](float f) { bigEndian ? putBeFloat(b, f) : putLeFloat(b, f); };
    for (const auto& p : boxCorners()) {
        put(p.x);
        put(p.y);
        put(p.z);
        put(0.0F);
        put(0.0F);
        put(1.0F);
    }
    const auto& idx = boxIndices();
    for (std::size_t t = 0; t < idx.size(); t += 3) {
        b.push_back(3);
        for (int k = 0; k < 3; ++k) {
            const auto v = idx[t + static_cast<std::size_t>(k)];
            bigEndian ? putBe32(b, v) : putLe32(b, v);
        }
    }
    return b;
}

/// Legacy VTK (version 3.0) ASCII polydata of the box: point scalars
/// "pressure [mmHg]" (space written as %20) and int cell scalars "label".
std::string boxLegacyAscii() {
    std::string s = "# vtk DataFile Version 3.0\nbox\nASCII\nDATASET POLYDATA\nPOINTS 8 float\n";
    for (const auto& p : boxCorners()) {
        s += num(p.x) + " " + num(p.y) + " " + num(p.z) + "\n";
    }
    const auto& idx = boxIndices();
    s += "POLYGONS 12 48\n";
    for (std::size_t t = 0; t < idx.size(); t += 3) {
        s += "3 " + std::to_string(idx[t]) + " " + std::to_string(idx[t + 1]) + " " +
             std::to_string(idx[t + 2]) + "\n";
    }
    s += "POINT_DATA 8\nSCALARS pressure%20[mmHg] float 1\nLOOKUP_TABLE default\n";
    for (int i = 0; i < 8; ++i) {
        s += std::to_string(80 + i) + "\n";
    }
    s += "CELL_DATA 12\nSCALARS label int 1\nLOOKUP_TABLE default\n";
    for (int t = 0; t < 12; ++t) {
        s += std::to_string(t % 3) + "\n";
    }
    return s;
}

/// Legacy VTK binary polydata (big-endian data) with point scalars "p" whose
/// value at vertex 2 is NaN; `pointValue` overrides one coordinate.
Bytes boxLegacyBinary(std::optional<float> firstX = std::nullopt) {
    Bytes b;
    putText(b,
            "# vtk DataFile Version 3.0\nbinary box\nBINARY\nDATASET POLYDATA\nPOINTS 8 float\n");
    bool first = true;
    for (const auto& p : boxCorners()) {
        putBeFloat(b, first && firstX ? *firstX : p.x);
        first = false;
        putBeFloat(b, p.y);
        putBeFloat(b, p.z);
    }
    putText(b, "\nPOLYGONS 12 48\n");
    const auto& idx = boxIndices();
    for (std::size_t t = 0; t < idx.size(); t += 3) {
        putBe32(b, 3);
        for (int k = 0; k < 3; ++k)
            putBe32(b, idx[t + static_cast<std::size_t>(k)]);
    }
    putText(b, "\nPOINT_DATA 8\nSCALARS p float 1\nLOOKUP_TABLE default\n");
    for (int i = 0; i < 8; ++i) {
        putBeFloat(b, i == 2 ? kNaN : static_cast<float>(i));
    }
    putText(b, "\n");
    return b;
}

/// Two tetrahedra sharing the face (1, 2, 3): 5 points, a surface of 6 triangles.
const char* kTwoTetsLegacy =
    "# vtk DataFile Version 3.0\ntets\nASCII\nDATASET UNSTRUCTURED_GRID\n"
    "POINTS 5 float\n0 0 0  1 0 0  0 1 0  0 0 1  1 1 1\n"
    "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\n"
    "CELL_TYPES 2\n10\n10\n"
    "CELL_DATA 2\nSCALARS region int 1\nLOOKUP_TABLE default\n3\n7\n";

std::string twoTetsVtu(const std::string& types = "10 10",
                       const std::string& connectivity = "0 1 2 3 1 2 3 4") {
    return "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"5\" NumberOfCells=\"2\">\n"
           "      <PointData>\n"
           "        <DataArray type=\"Float32\" Name=\"temperature [K]\" format=\"ascii\">"
           "300 301 302 303 304</DataArray>\n"
           "      </PointData>\n"
           "      <CellData>\n"
           "        <DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">3 7</DataArray>\n"
           "      </CellData>\n"
           "      <Points>\n        <DataArray type=\"Float32\" NumberOfComponents=\"3\" "
           "format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1 1 1 1</DataArray>\n      </Points>\n"
           "      <Cells>\n"
           "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" +
           connectivity +
           "</DataArray>\n"
           "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4 8</DataArray>\n"
           "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">" +
           types +
           "</DataArray>\n"
           "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

/// ASCII VTP of the box: point array "wss [Pa]" (value i; VTK's ASCII XML
/// parsing of "nan" is unreliable, NaN is tested through binary files),
/// 3-component "velocity [m/s]", int cell array "label".
std::string boxVtp(const std::string& pointsText = "", const std::string& numberOfPoints = "8") {
    std::string points = pointsText;
    if (points.empty()) {
        for (const auto& p : boxCorners()) {
            points += num(p.x) + " " + num(p.y) + " " + num(p.z) + " ";
        }
    }
    std::string connectivity;
    std::string offsets;
    const auto& idx = boxIndices();
    for (std::size_t t = 0; t < idx.size(); t += 3) {
        connectivity += std::to_string(idx[t]) + " " + std::to_string(idx[t + 1]) + " " +
                        std::to_string(idx[t + 2]) + " ";
        offsets += std::to_string(t + 3) + " ";
    }
    std::string wss;
    std::string velocity;
    for (int i = 0; i < 8; ++i) {
        wss += std::to_string(i) + " ";
        velocity += "0 0 " + std::to_string(i) + " ";
    }
    std::string label;
    for (int t = 0; t < 12; ++t) {
        label += std::to_string(t / 4) + " ";
    }
    return "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <PolyData>\n    <Piece NumberOfPoints=\"" +
           numberOfPoints +
           "\" NumberOfPolys=\"12\">\n"
           "      <PointData>\n"
           "        <DataArray type=\"Float32\" Name=\"wss [Pa]\" format=\"ascii\">" +
           wss +
           "</DataArray>\n"
           "        <DataArray type=\"Float32\" Name=\"velocity [m/s]\" NumberOfComponents=\"3\" "
           "format=\"ascii\">" +
           velocity +
           "</DataArray>\n"
           "      </PointData>\n"
           "      <CellData>\n"
           "        <DataArray type=\"Int32\" Name=\"label\" format=\"ascii\">" +
           label +
           "</DataArray>\n"
           "      </CellData>\n"
           "      <Points>\n        <DataArray type=\"Float32\" NumberOfComponents=\"3\" "
           "format=\"ascii\">" +
           points +
           "</DataArray>\n      </Points>\n"
           "      <Polys>\n"
           "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" +
           connectivity +
           "</DataArray>\n"
           "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" +
           offsets +
           "</DataArray>\n"
           "      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

/// The first bytes of a real PNG file (signature, IHDR, start of IDAT).
Bytes pngBytes() {
    Bytes b = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    putBe32(b, 13);
    putText(b, "IHDR");
    putBe32(b, 64);
    putBe32(b, 64);
    b.insert(b.end(), {8, 6, 0, 0, 0});
    putBe32(b, 0x5C6DA3F1U);  // CRC
    putBe32(b, 300);
    putText(b, "IDAT");
    for (int i = 0; i < 300; ++i) {
        b.push_back(static_cast<unsigned char>((i * 97 + 13) ^ 0xA5));
    }
    putBe32(b, 0);
    putText(b, "IEND");
    putBe32(b, 0xAE426082U);
    return b;
}

// ---------------------------------------------------------------------------
// Fixture

class MeshLoaderTest : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::path(VV_TEST_TMP) / "io-loader" /
               (std::string(info->test_suite_name()) + "." + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }

    [[nodiscard]] fs::path path(const std::string& name) const { return dir_ / name; }

    fs::path write(const std::string& name, const std::string& text) const {
        const auto file = path(name);
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }
    fs::path write(const std::string& name, const Bytes& bytes) const {
        const auto file = path(name);
        std::ofstream out(file, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
        return file;
    }
    static Bytes read(const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        return Bytes(std::istreambuf_iterator<char>(in), {});
    }

    fs::path dir_;
};

/// Loading `file` throws exactly `E` whose message names the file (and holds
/// `fragment`), prints nothing, and leaves the file's bytes as they were.
template <typename E>
void expectRefused(const fs::path& file, const std::string& fragment = "",
                   const MeshLoadOptions& options = {}) {
    SCOPED_TRACE(file.filename().string());
    std::error_code ec;
    const bool existed = fs::is_regular_file(file, ec);
    Bytes before;
    if (existed) {
        std::ifstream in(file, std::ios::binary);
        before.assign(std::istreambuf_iterator<char>(in), {});
    }
    ::testing::internal::CaptureStderr();
    ::testing::internal::CaptureStdout();
    bool threwExpected = false;
    std::string message;
    std::string wrongType;
    fs::path errorFile;
    try {
        (void)loadMesh(file, options);
    } catch (const E& e) {
        threwExpected = true;
        message = e.what();
        errorFile = e.file();
    } catch (const std::exception& e) {
        wrongType = e.what();
    }
    const std::string printedErr = ::testing::internal::GetCapturedStderr();
    const std::string printedOut = ::testing::internal::GetCapturedStdout();
    EXPECT_TRUE(wrongType.empty()) << "wrong exception type: " << wrongType;
    EXPECT_TRUE(threwExpected || !wrongType.empty()) << "no exception for " << file;
    if (threwExpected) {
        EXPECT_THAT(message, HasSubstr(file.string()));
        EXPECT_EQ(errorFile, file);
        if (!fragment.empty()) {
            EXPECT_THAT(message, HasSubstr(fragment));
        }
    }
    EXPECT_EQ(printedErr, "") << "something was printed to stderr";
    EXPECT_EQ(printedOut, "") << "something was printed to stdout";
    if (existed) {
        std::ifstream in(file, std::ios::binary);
        const Bytes after(std::istreambuf_iterator<char>(in), {});
        EXPECT_EQ(after, before) << "the input file was modified";
    }
}

void expectBox(const Mesh& m, const fs::path& file) {
    EXPECT_EQ(m.vertexCount(), 8U);
    EXPECT_EQ(m.triangleCount(), 12U);
    EXPECT_EQ(m.name, file.stem().string());
    EXPECT_EQ(m.source, file);
    const auto box = m.bounds();
    EXPECT_EQ(box.min, glm::vec3(0, 0, 0));
    EXPECT_EQ(box.max, glm::vec3(2, 3, 4));
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(m.normals[i]), 1.0F, 1e-5F);
    }
    double area = 0.0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        ASSERT_LT(m.indices[t + 2], m.vertexCount());
        const auto& a = m.positions[m.indices[t]];
        const auto& b = m.positions[m.indices[t + 1]];
        const auto& c = m.positions[m.indices[t + 2]];
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    EXPECT_NEAR(area, 2.0 * (2 * 3 + 2 * 4 + 3 * 4), 1e-4);
}

/// Computed normals of the box corners point away from its centre.
void expectOutwardNormals(const Mesh& m) {
    const glm::vec3 centre(1.0F, 1.5F, 2.0F);
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        EXPECT_GT(glm::dot(m.normals[i], m.positions[i] - centre), 0.0F) << "vertex " << i;
    }
}

const vv::scene::DataArray* cellArray(const Mesh& m, const std::string& name) {
    for (const auto& a : m.cellArrays) {
        if (a.name == name)
            return &a;
    }
    return nullptr;
}

// ---------------------------------------------------------------------------
// Formats

TEST_F(MeshLoaderTest, SupportedExtensions) {
    const auto& ext = vv::meshio::supportedMeshExtensions();
    EXPECT_EQ(ext, (std::vector<std::string>{".stl", ".obj", ".ply", ".vtk", ".vtp", ".vtu"}));
}

TEST_F(MeshLoaderTest, AsciiStlMergesCornersAndComputesNormals) {
    const auto file = write("box.stl", asciiStl(boxTriangles()));
    const Mesh m = loadMesh(file);
    expectBox(m, file);
    expectOutwardNormals(m);
    EXPECT_TRUE(m.pointArrays.empty());
    EXPECT_TRUE(m.cellArrays.empty());
}

TEST_F(MeshLoaderTest, BinaryStl) {
    const auto file = write("box.stl", binaryStl(boxTriangles()));
    const Mesh m = loadMesh(file);
    expectBox(m, file);
    expectOutwardNormals(m);
}

TEST_F(MeshLoaderTest, BinaryStlWhoseHeaderStartsWithSolid) {
    // Some exporters write "solid" into binary headers; the content decides.
    const auto file = write("solid.stl", binaryStl(boxTriangles(), "solid exported by a CAD tool"));
    expectBox(loadMesh(file), file);
}

TEST_F(MeshLoaderTest, BinaryStlWithZeroCountInHeaderReadsAllTriangles) {
    // A known exporter bug: the count is 0 but the triangles are there.
    const auto file = write("zero.stl", binaryStl(boxTriangles(), "bogus count", 0U));
    expectBox(loadMesh(file), file);
}

TEST_F(MeshLoaderTest, ExtensionIsCaseInsensitive) {
    const auto file = write("BOX.STL", asciiStl(boxTriangles()));
    expectBox(loadMesh(file), file);
    const auto vtp = write("Box.VtP", boxVtp());
    EXPECT_EQ(loadMesh(vtp).vertexCount(), 8U);
}

TEST_F(MeshLoaderTest, ObjWithoutNormalsGetsComputedOnes) {
    const auto file = write("box.obj", boxObj());
    const Mesh m = loadMesh(file);
    expectBox(m, file);
    expectOutwardNormals(m);
    EXPECT_TRUE(m.cellArrays.empty()) << "a single group gives no GroupIds array";
}

TEST_F(MeshLoaderTest, ObjNormalsAreTakenFromTheFile) {
    const auto file = write("box.obj", boxObj(true));
    const Mesh m = loadMesh(file);
    EXPECT_EQ(m.triangleCount(), 12U);
    for (const auto& n : m.normals) {
        EXPECT_NEAR(glm::length(n - glm::vec3(0, 0, 1)), 0.0F, 1e-6F);
    }
}

TEST_F(MeshLoaderTest, ObjGroupsBecomeAnIntegerCellArray) {
    std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\ng first\nf 1 2 3\ng second\nf 2 4 3\n";
    const auto file = write("groups.obj", obj);
    const Mesh m = loadMesh(file);
    EXPECT_EQ(m.triangleCount(), 2U);
    const auto* groups = cellArray(m, "GroupIds");
    ASSERT_NE(groups, nullptr);
    EXPECT_TRUE(groups->integer);
    EXPECT_NE(groups->values[0], groups->values[1]);
}

TEST_F(MeshLoaderTest, ObjNegativeIndicesAndQuads) {
    const auto file = write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\n");
    const Mesh m = loadMesh(file);
    EXPECT_EQ(m.vertexCount(), 4U);
    EXPECT_EQ(m.triangleCount(), 2U) << "the quad is triangulated";
}

TEST_F(MeshLoaderTest, AsciiPlyWithExtraPropertiesAndNaN) {
    const auto file = write("box.ply", boxPlyAscii());
    const Mesh m = loadMesh(file);
    expectBox(m, file);
    const auto* temp = m.pointArray("temp");
    ASSERT_NE(temp, nullptr);
    EXPECT_EQ(temp->components, 1);
    EXPECT_FALSE(temp->integer);
    EXPECT_EQ(temp->nonFiniteCount(), 1U);
    EXPECT_TRUE(std::isnan(temp->values[5]));
    EXPECT_FLOAT_EQ(temp->values[4], 6.0F);
    const auto* label = cellArray(m, "label");
    ASSERT_NE(label, nullptr);
    EXPECT_TRUE(label->integer);
    ASSERT_EQ(label->values.size(), 12U);
    EXPECT_EQ(label->values[0], 0.0F);
    EXPECT_EQ(label->values[11], 1.0F);
}

TEST_F(MeshLoaderTest, AsciiDecimalsLoadUnderADecimalCommaLocale) {
    // A Qt program takes LC_NUMERIC from the environment: under de_DE,
    // strtod reads "0.5" as 0 and stops at the point. The preflights must
    // not care (they read numbers in the C locale whatever the process's).
    std::string why;
    if (!vv::test::germanLocalePath(why)) {
        GTEST_SKIP() << why;
    }
    const vv::test::GermanNumbers german;
    const auto obj = write("decimals.obj", "v 0.5 0 0\nv 1.5 0 0\nv 0.5 1.25 0\nf 1 2 3\n");
    const Mesh fromObj = loadMesh(obj);
    ASSERT_EQ(fromObj.vertexCount(), 3U);
    EXPECT_FLOAT_EQ(fromObj.positions[2].y, 1.25F);
    const auto ply = write("box.ply", boxPlyAscii());
    expectBox(loadMesh(ply), ply);
}

TEST_F(MeshLoaderTest, BinaryPlyBothEndiannesses) {
    for (const bool big : {false, true}) {
        const auto file = write(big ? "big.ply" : "little.ply", boxPlyBinary(big));
        const Mesh m = loadMesh(file);
        expectBox(m, file);
        for (const auto& n : m.normals) {
            EXPECT_NEAR(n.z, 1.0F, 1e-6F) << "normals come from nx ny nz";
        }
    }
}

TEST_F(MeshLoaderTest, LegacyVtkPolyDataWithUnitsAndCellArrays) {
    const auto file = write("box.vtk", boxLegacyAscii());
    const Mesh m = loadMesh(file);
    expectBox(m, file);
    expectOutwardNormals(m);
    const auto* pressure = m.pointArray("pressure");
    ASSERT_NE(pressure, nullptr);
    EXPECT_EQ(pressure->unit, "mmHg");
    EXPECT_FALSE(pressure->fromCells);
    const auto range = pressure->finiteRange();
    ASSERT_TRUE(range);
    EXPECT_EQ(range->first, 80.0F);
    EXPECT_EQ(range->second, 87.0F);
    const auto* label = cellArray(m, "label");
    ASSERT_NE(label, nullptr);
    EXPECT_TRUE(label->integer);
    EXPECT_EQ(label->tupleCount(), 12U);
    const auto* converted = m.pointArray("label");
    ASSERT_NE(converted, nullptr);
    EXPECT_TRUE(converted->fromCells);
    EXPECT_TRUE(converted->integer);
    EXPECT_EQ(converted->tupleCount(), 8U);
}

TEST_F(MeshLoaderTest, LegacyVtkBinaryKeepsNaNInArrays) {
    const auto file = write("box.vtk", boxLegacyBinary());
    const Mesh m = loadMesh(file);
    expectBox(m, file);
    const auto* p = m.pointArray("p");
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->nonFiniteCount(), 1U);
    EXPECT_TRUE(std::isnan(p->values[2]));
    EXPECT_EQ(p->values[7], 7.0F);
    const auto range = p->finiteRange();
    ASSERT_TRUE(range);
    EXPECT_EQ(range->first, 0.0F);
    EXPECT_EQ(range->second, 7.0F);
}

TEST_F(MeshLoaderTest, LegacyVtkUnstructuredGridGivesItsOuterSurface) {
    const auto file = write("tets.vtk", kTwoTetsLegacy);
    const Mesh m = loadMesh(file);
    EXPECT_EQ(m.vertexCount(), 5U);
    EXPECT_EQ(m.triangleCount(), 6U) << "the shared face is inside, not on the surface";
    const auto* region = cellArray(m, "region");
    ASSERT_NE(region, nullptr);
    EXPECT_EQ(region->tupleCount(), 6U);
    const auto range = region->finiteRange();
    ASSERT_TRUE(range);
    EXPECT_EQ(range->first, 3.0F);
    EXPECT_EQ(range->second, 7.0F);
}

TEST_F(MeshLoaderTest, VtpWithPointAndCellArrays) {
    const auto file = write("box.vtp", boxVtp());
    const Mesh m = loadMesh(file);
    expectBox(m, file);
    const auto* wss = m.pointArray("wss");
    ASSERT_NE(wss, nullptr);
    EXPECT_EQ(wss->unit, "Pa");
    EXPECT_EQ(wss->values[7], 7.0F);
    EXPECT_FALSE(wss->integer);
    const auto* velocity = m.pointArray("velocity");
    ASSERT_NE(velocity, nullptr);
    EXPECT_EQ(velocity->unit, "m/s");
    EXPECT_EQ(velocity->components, 3);
    const auto vr = velocity->finiteRange();
    ASSERT_TRUE(vr);
    EXPECT_EQ(vr->second, 7.0F) << "vector ranges are of the magnitude";
    const auto* label = cellArray(m, "label");
    ASSERT_NE(label, nullptr);
    EXPECT_TRUE(label->integer);
    EXPECT_EQ(label->values[11], 2.0F);
}

// VTK's XML reader slows to a crawl on millions of elements (4 million
// empty tags: ~20 s): the check refuses a file with more than 200,000 tags
// before VTK reads it, and walks the tags in linear time.
TEST_F(MeshLoaderTest, VtpWithHundredsOfThousandsOfTagsIsRefusedBeforeVtkReadsIt) {
    std::string text =
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
        "byte_order=\"LittleEndian\">\n<PolyData>\n";
    for (int i = 0; i < 300000; ++i) {
        text += "<a/>";
    }
    text += "</PolyData></VTKFile>\n";
    const auto file = write("many-tags.vtp", text);
    expectRefused<vv::FormatError>(file, "more than 200000 XML tags");
}

TEST_F(MeshLoaderTest, VtuOuterSurfaceIsExtracted) {
    const auto file = write("tets.vtu", twoTetsVtu());
    const Mesh m = loadMesh(file);
    EXPECT_EQ(m.vertexCount(), 5U);
    EXPECT_EQ(m.triangleCount(), 6U);
    const auto* temperature = m.pointArray("temperature");
    ASSERT_NE(temperature, nullptr);
    EXPECT_EQ(temperature->unit, "K");
    EXPECT_EQ(temperature->values[4], 304.0F);
    const auto* region = cellArray(m, "region");
    ASSERT_NE(region, nullptr);
    EXPECT_TRUE(region->integer);
    // Each surface triangle carries the region of its tetrahedron.
    int threes = 0;
    int sevens = 0;
    for (const float v : region->values) {
        threes += v == 3.0F ? 1 : 0;
        sevens += v == 7.0F ? 1 : 0;
    }
    EXPECT_EQ(threes, 3);
    EXPECT_EQ(sevens, 3);
}

TEST_F(MeshLoaderTest, CellArraysBecomePointArraysOnRequest) {
    // Two triangles sharing the edge 1-2; per triangle: flux 2 and 4, label 1
    // and 5, gap NaN and 6.
    Mesh source;
    source.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    source.indices = {0, 1, 2, 1, 3, 2};
    vv::scene::DataArray flux;
    flux.name = "flux";
    flux.unit = "ml/s";
    flux.values = {2, 4};
    vv::scene::DataArray label;
    label.name = "label";
    label.integer = true;
    label.values = {1, 5};
    vv::scene::DataArray gap;
    gap.name = "gap";
    gap.values = {kNaN, 6};
    source.cellArrays = {flux, label, gap};
    const auto file = path("cells.vtp");
    vv::meshio::writeVtp(source, file);

    const Mesh m = loadMesh(file);
    const auto* converted = m.pointArray("flux");
    ASSERT_NE(converted, nullptr);
    EXPECT_TRUE(converted->fromCells);
    EXPECT_EQ(converted->unit, "ml/s");
    ASSERT_EQ(converted->values.size(), 4U);
    EXPECT_FLOAT_EQ(converted->values[0], 2.0F);  // only in the first triangle
    EXPECT_FLOAT_EQ(converted->values[1], 3.0F);  // shared: the mean
    EXPECT_FLOAT_EQ(converted->values[2], 3.0F);
    EXPECT_FLOAT_EQ(converted->values[3], 4.0F);
    ASSERT_NE(cellArray(m, "flux"), nullptr) << "the cell array is kept too";

    const auto* labels = m.pointArray("label");
    ASSERT_NE(labels, nullptr);
    EXPECT_TRUE(labels->integer);
    EXPECT_EQ(labels->values[1], 1.0F) << "labels are not averaged: the smallest on ties";
    EXPECT_EQ(labels->values[3], 5.0F);

    // NaN cells do not spoil their neighbours' means; alone they stay NaN.
    const auto* gaps = m.pointArray("gap");
    ASSERT_NE(gaps, nullptr);
    EXPECT_TRUE(std::isnan(gaps->values[0]));
    EXPECT_EQ(gaps->values[1], 6.0F);
    EXPECT_EQ(gaps->nonFiniteCount(), 1U);

    MeshLoadOptions off;
    off.cellArraysToPoints = false;
    const Mesh plain = loadMesh(file, off);
    EXPECT_TRUE(plain.pointArrays.empty());
    EXPECT_EQ(plain.cellArrays.size(), 3U);
}

TEST_F(MeshLoaderTest, ConvertedArrayDoesNotReplaceAPointArrayOfTheSameName) {
    const std::string vtk =
        "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n"
        "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\n"
        "POINT_DATA 3\nSCALARS wss float 1\nLOOKUP_TABLE default\n1 2 3\n"
        "CELL_DATA 1\nSCALARS wss float 1\nLOOKUP_TABLE default\n9\n";
    const Mesh m = loadMesh(write("clash.vtk", vtk));
    ASSERT_EQ(m.pointArrays.size(), 2U);
    EXPECT_EQ(m.pointArrays[0].name, "wss");
    EXPECT_FALSE(m.pointArrays[0].fromCells);
    EXPECT_EQ(m.pointArrays[0].values[2], 3.0F);
    EXPECT_EQ(m.pointArrays[1].name, "wss (cells)");
    EXPECT_TRUE(m.pointArrays[1].fromCells);
    EXPECT_EQ(m.pointArrays[1].values[2], 9.0F);
}

TEST_F(MeshLoaderTest, ScaleMultipliesCoordinates) {
    const auto file = write("box.stl", asciiStl(boxTriangles()));
    MeshLoadOptions options;
    options.scale = 1000.0;
    const Mesh m = loadMesh(file, options);
    EXPECT_EQ(m.bounds().max, glm::vec3(2000, 3000, 4000));
    EXPECT_EQ(m.bounds().min, glm::vec3(0));
    expectOutwardNormals(m);
    options.scale = 0.5;
    EXPECT_EQ(loadMesh(file, options).bounds().max, glm::vec3(1, 1.5F, 2));
}

TEST_F(MeshLoaderTest, BadScaleIsRefused) {
    const auto file = write("box.stl", asciiStl(boxTriangles()));
    for (const double scale : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        MeshLoadOptions options;
        options.scale = scale;
        expectRefused<vv::InvalidArgumentError>(file, "scale", options);
    }
    MeshLoadOptions overflow;
    overflow.scale = 1e38;
    expectRefused<vv::FormatError>(file, "scaled", overflow);
}

TEST_F(MeshLoaderTest, ProgressIsReportedAndEndsAtOne) {
    const auto file = write("box.vtp", boxVtp());
    std::vector<double> fractions;
    std::vector<std::string> stages;
    const vv::Progress progress(
        [&](double f, std::string_view stage) {
            fractions.push_back(f);
            stages.emplace_back(stage);
        },
        {});
    (void)loadMesh(file, {}, progress);
    ASSERT_FALSE(fractions.empty());
    EXPECT_EQ(fractions.back(), 1.0);
    for (std::size_t i = 1; i < fractions.size(); ++i) {
        EXPECT_GE(fractions[i], fractions[i - 1]);
    }
    EXPECT_THAT(stages.front(), HasSubstr("box.vtp"));
}

TEST_F(MeshLoaderTest, StoppedBeforeStartThrowsCancelled) {
    const auto file = write("box.stl", asciiStl(boxTriangles()));
    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW((void)loadMesh(file, {}, vv::Progress({}, stop.get_token())), vv::CancelledError);
}

TEST_F(MeshLoaderTest, StoppedWhileReadingThrowsCancelled) {
    // A binary STL large enough for vtkSTLReader to report progress.
    std::vector<Tri> tris;
    for (int i = 0; i < 30000; ++i) {
        const float x = static_cast<float>(i);
        tris.push_back({{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}});
    }
    const auto file = write("many.stl", binaryStl(tris));
    std::stop_source stop;
    int reports = 0;
    const vv::Progress progress(
        [&](double f, std::string_view stage) {
            ++reports;
            if (f > 0.1 && stage.find("Reading") != std::string_view::npos) {
                stop.request_stop();
            }
        },
        stop.get_token());
    EXPECT_THROW((void)loadMesh(file, {}, progress), vv::CancelledError);
    EXPECT_GT(reports, 0);
    // The same file loads when not stopped.
    EXPECT_EQ(loadMesh(file).triangleCount(), 30000U);
}

TEST_F(MeshLoaderTest, LoadSceneKeepsOrderAndFailsOnTheFirstBadFile) {
    const auto a = write("a.stl", asciiStl(boxTriangles()));
    auto shifted = boxTriangles();
    for (auto& t : shifted) {
        t.a.x += 10;
        t.b.x += 10;
        t.c.x += 10;
    }
    const auto b = write("b.stl", binaryStl(shifted));
    const auto scene = vv::meshio::loadScene({a, b});
    ASSERT_EQ(scene.meshes.size(), 2U);
    EXPECT_EQ(scene.meshes[0].name, "a");
    EXPECT_EQ(scene.meshes[1].name, "b");
    EXPECT_EQ(scene.bounds().max, glm::vec3(12, 3, 4));
    EXPECT_TRUE(vv::meshio::loadScene({}).meshes.empty());

    const auto missing = path("missing.stl");
    try {
        (void)vv::meshio::loadScene({a, missing, b});
        FAIL() << "no exception";
    } catch (const vv::IoError& e) {
        EXPECT_EQ(e.file(), missing);
    }
}

// ---------------------------------------------------------------------------
// Files that are not there or not files

TEST_F(MeshLoaderTest, MissingFile) {
    expectRefused<vv::IoError>(path("nope.stl"), "not found");
    expectRefused<vv::IoError>(path("no/such/folder/box.vtp"), "not found");
}

TEST_F(MeshLoaderTest, FolderIsRefused) {
    fs::create_directories(path("folder.stl"));
    expectRefused<vv::IoError>(path("folder.stl"), "folder");
}

TEST_F(MeshLoaderTest, UnreadableFileIsRefused) {
    const auto file = write("secret.stl", asciiStl(boxTriangles()));
    fs::permissions(file, fs::perms::none);
    if (vv::test::runningAsRoot()) {
        // Root reads it anyway: the check runs in a child as nobody (the
        // folders on the way are world-searchable, the file readable by none).
        EXPECT_EXIT(
            {
                if (!vv::test::becomeNobody()) {
                    std::_Exit(2);
                }
                try {
                    (void)vv::meshio::loadMesh(file);
                } catch (const vv::IoError& e) {
                    const std::string what = e.what();
                    std::_Exit(what.find("cannot open") != std::string::npos &&
                                       what.find(file.string()) != std::string::npos
                                   ? 0
                                   : 3);
                } catch (...) {
                    std::_Exit(4);
                }
                std::_Exit(5);  // it was read
            },
            ::testing::ExitedWithCode(0), "");
    } else {
        expectRefused<vv::IoError>(file, "cannot open");
    }
    fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write);
}

TEST_F(MeshLoaderTest, UnknownExtensionIsRefused) {
    expectRefused<vv::FormatError>(write("box.txt", asciiStl(boxTriangles())), "extension");
    expectRefused<vv::FormatError>(write("box", asciiStl(boxTriangles())), "extension");
}

TEST_F(MeshLoaderTest, EmptyFileOfEveryFormatIsRefused) {
    for (const auto& ext : vv::meshio::supportedMeshExtensions()) {
        expectRefused<vv::FormatError>(write("empty" + ext, std::string()), "empty");
    }
}

TEST_F(MeshLoaderTest, PngRenamedToEveryFormatIsRefused) {
    for (const auto& ext : vv::meshio::supportedMeshExtensions()) {
        expectRefused<vv::FormatError>(write("picture" + ext, pngBytes()));
    }
}

// ---------------------------------------------------------------------------
// Malformed STL

TEST_F(MeshLoaderTest, StlTruncated) {
    const std::string text = asciiStl(boxTriangles());
    expectRefused<vv::FormatError>(write("cut.stl", text.substr(0, text.size() / 2)));
    Bytes bytes = binaryStl(boxTriangles());
    bytes.resize(bytes.size() - 30);
    expectRefused<vv::FormatError>(write("cut-binary.stl", bytes), "truncated");
    expectRefused<vv::FormatError>(write("header-only.stl", Bytes(60, 7)), "too short");
}

TEST_F(MeshLoaderTest, StlHugeTriangleCountIsRefusedBeforeReading) {
    expectRefused<vv::FormatError>(write("huge.stl", binaryStl(boxTriangles(), "x", 0xFFFFFFFFU)),
                                   "4294967295");
    expectRefused<vv::FormatError>(write("huge2.stl", binaryStl(boxTriangles(), "x", 400000000U)),
                                   "room for only 12");
}

TEST_F(MeshLoaderTest, StlCorruptBytes) {
    Bytes bytes = binaryStl(boxTriangles());
    std::fill(bytes.begin() + 84 + 50 * 3 + 12, bytes.begin() + 84 + 50 * 3 + 24, 0xFF);  // NaNs
    expectRefused<vv::FormatError>(write("nan-bytes.stl", bytes), "non-finite");
    std::string text = asciiStl(boxTriangles());
    text.replace(text.find("endloop", 200), 7, "end\x01oop");
    expectRefused<vv::FormatError>(write("garbled.stl", text));
    expectRefused<vv::FormatError>(write("words.stl", "solid x\nthis is not a facet\nendsolid\n"));
}

TEST_F(MeshLoaderTest, StlNaNCoordinates) {
    std::string text = asciiStl(boxTriangles());
    text.replace(text.find("vertex 2 3 4"), 12, "vertex nan 3 4");
    expectRefused<vv::FormatError>(write("nan.stl", text), "non-finite");
    auto tris = boxTriangles();
    tris[5].b.y = std::numeric_limits<float>::infinity();
    expectRefused<vv::FormatError>(write("inf.stl", binaryStl(tris)), "non-finite");
}

TEST_F(MeshLoaderTest, StlZeroAreaAndEmpty) {
    const std::vector<Tri> flat = {{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}},
                                   {{0, 0, 0}, {3, 3, 3}, {1, 1, 1}}};
    expectRefused<vv::FormatError>(write("line.stl", asciiStl(flat)), "zero area");
    expectRefused<vv::FormatError>(write("nothing.stl", "solid empty\nendsolid empty\n"), "empty");
    expectRefused<vv::FormatError>(write("nothing-binary.stl", binaryStl({})), "no triangles");
}

// ---------------------------------------------------------------------------
// Malformed OBJ

TEST_F(MeshLoaderTest, ObjTruncatedInsideAVertex) {
    const std::string text = boxObj();
    const auto cut = text.find("v 2 3 0");
    expectRefused<vv::FormatError>(write("cut.obj", text.substr(0, cut + 5)), "three coordinates");
}

TEST_F(MeshLoaderTest, ObjCorruptReferences) {
    const std::string base = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n";
    expectRefused<vv::FormatError>(write("far.obj", base + "f 1 2 99999999999\n"),
                                   "does not exist");
    expectRefused<vv::FormatError>(write("zero.obj", base + "f 0 1 2\n"), "does not exist");
    expectRefused<vv::FormatError>(write("normal.obj", base + "f 1//1 2//1 3//7\n"), "normal 7");
    expectRefused<vv::FormatError>(write("texture.obj", base + "f 1/9 2/1 3/1\n"), "texture");
    expectRefused<vv::FormatError>(write("mixed.obj", base + "f 1//1 2/ 3//1\n"), "mix");
    expectRefused<vv::FormatError>(write("garbage.obj", base + "f 1 2 x3\n"), "reference");
    expectRefused<vv::FormatError>(write("binary.obj", base + "f 1 2 \x01\x02\n"), "binary");
    expectRefused<vv::FormatError>(write("forms.obj", base + "f 1 2 3\nf 1//1 2//1 3//1\n"),
                                   "drop");
}

TEST_F(MeshLoaderTest, ObjNaNCoordinates) {
    std::string text = boxObj();
    text.replace(text.find("v 2 3 4"), 7, "v 2 nan 4");
    expectRefused<vv::FormatError>(write("nan.obj", text), "non-finite");
    expectRefused<vv::FormatError>(write("word.obj", "v 0 zero 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
                                   "coordinate");
}

TEST_F(MeshLoaderTest, ObjZeroAreaAndEmpty) {
    expectRefused<vv::FormatError>(write("line.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n"),
                                   "zero area");
    expectRefused<vv::FormatError>(write("points.obj", "v 0 0 0\nv 1 1 1\n"), "empty");
    expectRefused<vv::FormatError>(write("comments.obj", "# nothing here\n"), "empty");
}

// ---------------------------------------------------------------------------
// Malformed PLY

TEST_F(MeshLoaderTest, PlyTruncated) {
    const std::string text = boxPlyAscii();
    expectRefused<vv::FormatError>(write("cut.ply", text.substr(0, text.size() - 40)));
    expectRefused<vv::FormatError>(write("no-newline.ply", text.substr(0, text.size() - 1)),
                                   "line end");
    expectRefused<vv::FormatError>(write("header.ply", text.substr(0, text.find("end_header"))),
                                   "end_header");
    Bytes bytes = boxPlyBinary(false);
    bytes.resize(bytes.size() - 7);
    expectRefused<vv::FormatError>(write("cut-binary.ply", bytes), "truncated");
}

TEST_F(MeshLoaderTest, PlyHugeCountsAreRefusedBeforeReading) {
    std::string text = boxPlyAscii();
    text.replace(text.find("element vertex 8"), 16, "element vertex 4000000000");
    expectRefused<vv::FormatError>(write("huge.ply", text), "absurd");
    text = boxPlyAscii();
    text.replace(text.find("element face 12"), 15, "element face 400000000");
    expectRefused<vv::FormatError>(write("huge-faces.ply", text), "more elements");
    Bytes bytes = boxPlyBinary(false);
    const std::string header(bytes.begin(), bytes.end());
    bytes[header.find("end_header\n") + 11 + 8 * 24] = 250;  // first face: 250 indices
    expectRefused<vv::FormatError>(write("huge-list.ply", bytes));
}

TEST_F(MeshLoaderTest, PlyCorruptContent) {
    std::string text = boxPlyAscii();
    text.replace(text.find("3 0 2 3"), 7, "3 0 2 300");
    expectRefused<vv::FormatError>(write("index.ply", text), "refers to vertex 300");
    text = boxPlyAscii();
    text.replace(text.find("format ascii"), 12, "format fancy");
    expectRefused<vv::FormatError>(write("format.ply", text), "format");
    text = boxPlyAscii();
    text.replace(text.find("property float temp\n"), 20, "\n");
    expectRefused<vv::FormatError>(write("blank.ply", text), "empty");
    text = boxPlyAscii();
    text.replace(text.find("vertex_indices"), 14, "vertex_indexes");
    expectRefused<vv::FormatError>(write("no-indices.ply", text), "vertex_indices");
    text = boxPlyAscii();
    text.replace(text.find("\n3 0 2 3"), 8, "\n3 0 2 x");
    expectRefused<vv::FormatError>(write("letters.ply", text), "'x'");
}

TEST_F(MeshLoaderTest, PlyNaNCoordinates) {
    std::string text = boxPlyAscii();
    text.replace(text.find("\n2 3 4 "), 7, "\n2 nan 4 ");
    expectRefused<vv::FormatError>(write("nan.ply", text), "non-finite");
}

TEST_F(MeshLoaderTest, PlyZeroArea) {
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 1 1\n2 2 2\n3 0 1 2\n";
    expectRefused<vv::FormatError>(write("line.ply", text), "zero area");
}

// ---------------------------------------------------------------------------
// Malformed legacy VTK

TEST_F(MeshLoaderTest, LegacyVtkTruncated) {
    const std::string text = boxLegacyAscii();
    expectRefused<vv::FormatError>(write("cut.vtk", text.substr(0, text.find("POLYGONS") + 40)));
    expectRefused<vv::FormatError>(write("cut2.vtk", text.substr(0, text.size() - 30)));
    Bytes bytes = boxLegacyBinary();
    bytes.resize(bytes.size() / 2);
    expectRefused<vv::FormatError>(write("cut-binary.vtk", bytes));
}

TEST_F(MeshLoaderTest, LegacyVtkHugeCountsAreRefusedBeforeReading) {
    std::string text = boxLegacyAscii();
    text.replace(text.find("POINTS 8"), 8, "POINTS 4000000000");
    expectRefused<vv::FormatError>(write("points.vtk", text), "4000000000 points");
    text = boxLegacyAscii();
    text.replace(text.find("POLYGONS 12 48"), 14, "POLYGONS 200000000 800000000");
    expectRefused<vv::FormatError>(write("polygons.vtk", text), "200000000 polygons");
    text = boxLegacyAscii();
    text.replace(text.find("POINT_DATA 8"), 12, "POINT_DATA 99999999999");
    expectRefused<vv::FormatError>(write("tuples.vtk", text));
}

TEST_F(MeshLoaderTest, LegacyVtkCorruptCells) {
    std::string text = boxLegacyAscii();
    text.replace(text.find("\n3 0 2 3\n"), 9, "\n4294967295 0 2 3\n");
    expectRefused<vv::FormatError>(write("size.vtk", text));
    text = boxLegacyAscii();
    text.replace(text.find("\n3 0 2 3\n"), 9, "\n3 0 2 300\n");
    expectRefused<vv::FormatError>(write("index.vtk", text), "point 300");
    std::string tets = kTwoTetsLegacy;
    tets.replace(tets.find("10\n10\n"), 6, "42\n10\n");
    expectRefused<vv::FormatError>(write("polyhedron.vtk", tets), "type 42");
    tets = kTwoTetsLegacy;
    tets.replace(tets.find("CELL_TYPES 2\n10\n10\n"), 19, "CELL_TYPES 1\n10\n");
    expectRefused<vv::FormatError>(write("types.vtk", tets), "cell types");
    expectRefused<vv::FormatError>(
        write("image.vtk",
              "# vtk DataFile Version 3.0\nx\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 9999 "
              "9999 9999\nSPACING 1 1 1\nORIGIN 0 0 0\n"),
        "STRUCTURED_POINTS");
    expectRefused<vv::FormatError>(write("header.vtk", "# vtk DataFile Version 3.0\nx\nTEXT\n"),
                                   "ASCII or BINARY");
}

TEST_F(MeshLoaderTest, LegacyVtkNaNCoordinates) {
    expectRefused<vv::FormatError>(write("nan.vtk", boxLegacyBinary(kNaN)), "non-finite");
    std::string text = boxLegacyAscii();
    text.replace(text.find("\n2 3 4\n"), 7, "\nnan 3 4\n");
    expectRefused<vv::FormatError>(write("nan-ascii.vtk", text));
}

TEST_F(MeshLoaderTest, LegacyVtkZeroArea) {
    const std::string text =
        "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n"
        "POINTS 3 float\n0 0 0 1 1 1 2 2 2\nPOLYGONS 1 4\n3 0 1 2\n";
    expectRefused<vv::FormatError>(write("line.vtk", text), "zero area");
}

// ---------------------------------------------------------------------------
// Malformed VTP / VTU

/// A compressed binary VTP written by writeVtp.
fs::path writeBinaryBox(const fs::path& file) {
    Mesh m;
    m.positions = boxCorners();
    m.indices = boxIndices();
    vv::scene::computeNormals(m);
    vv::scene::DataArray wss;
    wss.name = "wss";
    wss.unit = "Pa";
    for (int i = 0; i < 8; ++i)
        wss.values.push_back(static_cast<float>(i));
    m.pointArrays.push_back(wss);
    vv::meshio::writeVtp(m, file);
    return file;
}

TEST_F(MeshLoaderTest, VtpTruncated) {
    const auto good = writeBinaryBox(path("good.vtp"));
    const Bytes bytes = MeshLoaderTest::read(good);
    ASSERT_EQ(loadMesh(good).vertexCount(), 8U);
    expectRefused<vv::FormatError>(
        write("half.vtp", Bytes(bytes.begin(), bytes.begin() + bytes.size() / 2)));
    expectRefused<vv::FormatError>(write("end.vtp", Bytes(bytes.begin(), bytes.end() - 40)));
    const std::string text = boxVtp();
    expectRefused<vv::FormatError>(write("ascii.vtp", text.substr(0, text.size() * 3 / 4)));
}

TEST_F(MeshLoaderTest, VtpCorruptBytes) {
    const auto good = writeBinaryBox(path("good.vtp"));
    Bytes bytes = MeshLoaderTest::read(good);
    const std::string text(bytes.begin(), bytes.end());
    const auto data = text.find("format=\"binary\"");
    ASSERT_NE(data, std::string::npos);
    // Garble the base64 data of the first array (inside its compressed stream).
    const auto start = text.find('>', data) + 30;
    for (std::size_t i = start; i < start + 12; ++i) {
        bytes[i] = static_cast<unsigned char>('A' + (i % 7));
    }
    expectRefused<vv::FormatError>(write("garbled.vtp", bytes));
    // Broken XML structure.
    std::string xml = boxVtp();
    xml.replace(xml.find("</Points>"), 9, "</Pts>");
    expectRefused<vv::FormatError>(write("xml.vtp", xml));
}

TEST_F(MeshLoaderTest, VtpHugeCountsAreRefusedBeforeReading) {
    expectRefused<vv::FormatError>(write("points.vtp", boxVtp("", "4000000000")),
                                   "4000000000 points");
    expectRefused<vv::FormatError>(write("points2.vtp", boxVtp("", "400000000")),
                                   "400000000 points");
    const auto good = writeBinaryBox(path("good.vtp"));
    std::string text;
    {
        const Bytes bytes = MeshLoaderTest::read(good);
        text.assign(bytes.begin(), bytes.end());
    }
    // The compressed block table of the first array: claim 2^31 blocks.
    const auto data = text.find('>', text.find("format=\"binary\"")) + 1;
    const auto first = text.find_first_not_of(" \n", data);
    std::string claimed = text;
    claimed.replace(first, 8, "AAAAgAAA");  // base64 of 00 00 00 80 00 00 (LE uint64 prefix)
    expectRefused<vv::FormatError>(write("blocks.vtp", claimed), "header");
}

TEST_F(MeshLoaderTest, VtpNaNCoordinatesAndZeroArea) {
    Mesh withNaN;
    withNaN.positions = boxCorners();
    withNaN.positions[3].y = kNaN;
    withNaN.indices = boxIndices();
    vv::meshio::writeVtp(withNaN, path("nan.vtp"));
    expectRefused<vv::FormatError>(path("nan.vtp"), "non-finite");
    expectRefused<vv::FormatError>(
        write("flat.vtp", boxVtp("0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0")), "zero area");
}

TEST_F(MeshLoaderTest, VtpWithTheWrongDatasetType) {
    expectRefused<vv::FormatError>(write("grid.vtp", twoTetsVtu()), "UnstructuredGrid");
    expectRefused<vv::FormatError>(write("poly.vtu", boxVtp()), "PolyData");
    expectRefused<vv::FormatError>(write("html.vtp", "<html><body>hello</body></html>\n"),
                                   "not a VTK XML file");
}

TEST_F(MeshLoaderTest, VtuCorruptCells) {
    expectRefused<vv::FormatError>(write("type.vtu", twoTetsVtu("10 42")), "type 42");
    expectRefused<vv::FormatError>(write("unknown.vtu", twoTetsVtu("10 255")), "type 255");
    expectRefused<vv::FormatError>(write("index.vtu", twoTetsVtu("10 10", "0 1 2 3 1 2 3 40")),
                                   "point 40");
    std::string text = twoTetsVtu();
    text.replace(text.find("NumberOfCells=\"2\""), 17, "NumberOfCells=\"900000000\"");
    expectRefused<vv::FormatError>(write("huge.vtu", text), "900000000 cells");
    expectRefused<vv::FormatError>(write("cut.vtu", text.substr(0, 300)));
}

}  // namespace
