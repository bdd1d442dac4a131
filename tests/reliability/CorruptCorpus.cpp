// SPDX-License-Identifier: GPL-3.0-or-later
// vv_corrupt_corpus OUTDIR GROUP [--demo FILE.vtp]
//
// Writes a corpus of corrupt, degenerate and hostile inputs for one group
// (stl, obj, ply, vtk, vtp, vtu, misc) into OUTDIR, and OUTDIR/cases.txt
// with one line per case: "<path>\t<description>"; a description may end in
// "[limit N s]", a tighter time limit for that case (a regression of a slow
// path). Each mesh format starts from a small valid file written here by
// hand (vtp also from FILE.vtp, the demo tree, when given) and derives
// truncations at many offsets, byte flips, huge and zero declared counts,
// NaN/Inf coordinates, NaN arrays, non-manifold, degenerate and 0-triangle
// meshes and bad indices. "misc" holds empty files, folders named like
// meshes, a folder of 2000 non-DICOM files and random bytes behind a DICOM
// preamble. Deterministic: the same arguments make the same files
// (tests/reliability/run-corpus.sh runs them).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Bytes = std::string;  // file content, text or binary

struct Corpus {
    fs::path dir;
    std::ofstream manifest;
    int count = 0;

    void add(const std::string& name, const Bytes& content, const std::string& what) {
        const fs::path path = dir / name;
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(content.data(), static_cast<std::streamsize>(content.size()));
        if (!out) {
            throw std::runtime_error("cannot write " + path.string());
        }
        note(path, what);
    }
    void note(const fs::path& path, const std::string& what) {
        manifest << path.string() << '\t' << what << '\n';
        ++count;
    }
};

// ---------------------------------------------------------------------------
// The valid seed: an octahedron (6 vertices, 8 triangles) with a point array.

struct Seed {
    std::vector<std::array<float, 3>> points = {{1.5F, 0, 0}, {-1, 0, 0},    {0, 1.25F, 0},
                                                {0, -1, 0},   {0, 0, 1.75F}, {0, 0, -1}};
    std::vector<std::array<std::int64_t, 3>> triangles = {
        {0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    std::vector<float> pressure = {10.5F, 11.5F, 12.5F, 13.5F, 14.5F, 15.5F};
};

/// Shortest text that reads back to `v` ("nan", "inf" as such).
std::string num(double v) {
    if (std::isnan(v)) {
        return "nan";
    }
    if (std::isinf(v)) {
        return v > 0 ? "inf" : "-inf";
    }
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

template <typename T>
void put(Bytes& out, T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    out.append(raw, sizeof(T));
}

Seed nonManifold() {
    // Three triangles share the edge 0-1, plus a dangling one touching at a vertex.
    Seed s;
    s.points = {{0, 0, 0},    {1, 0, 0}, {0.5F, 1, 0}, {0.5F, -1, 0},
                {0.5F, 0, 1}, {0, 0, 2}, {1, 1, 2}};
    s.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {0, 5, 6}};
    s.pressure = {1, 2, 3, 4, 5, 6, 7};
    return s;
}

Seed degenerate() {
    // Zero-area triangles only: repeated vertices and collinear points.
    Seed s;
    s.points = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
    s.triangles = {{0, 1, 2}, {1, 2, 3}, {0, 0, 0}, {3, 3, 1}};
    s.pressure = {1, 2, 3, 4};
    return s;
}

Seed withPoint(Seed s, std::size_t index, std::array<float, 3> p) {
    s.points[index] = p;
    return s;
}

// ---------------------------------------------------------------------------
// Writers for each format.

Bytes stlAscii(const Seed& s) {
    std::ostringstream o;
    o << "solid seed\n";
    for (const auto& t : s.triangles) {
        o << " facet normal 0 0 1\n  outer loop\n";
        for (const auto i : t) {
            const auto& p = s.points.at(static_cast<std::size_t>(i));
            o << "   vertex " << num(p[0]) << ' ' << num(p[1]) << ' ' << num(p[2]) << '\n';
        }
        o << "  endloop\n endfacet\n";
    }
    o << "endsolid seed\n";
    return o.str();
}

Bytes stlBinary(const Seed& s, std::uint32_t declared) {
    Bytes b(80, ' ');
    b.replace(0, 11, "binary seed");
    put<std::uint32_t>(b, declared);
    for (const auto& t : s.triangles) {
        for (int k = 0; k < 3; ++k) {
            put<float>(b, k == 2 ? 1.0F : 0.0F);
        }
        for (const auto i : t) {
            for (const float c : s.points.at(static_cast<std::size_t>(i))) {
                put<float>(b, c);
            }
        }
        put<std::uint16_t>(b, 0);
    }
    return b;
}

Bytes obj(const Seed& s, const std::string& indexBase = "") {
    std::ostringstream o;
    o << "# seed\no seed\n";
    for (const auto& p : s.points) {
        o << "v " << num(p[0]) << ' ' << num(p[1]) << ' ' << num(p[2]) << '\n';
    }
    for (const auto& t : s.triangles) {
        o << "f";
        for (const auto i : t) {
            o << ' ' << indexBase << (i + 1);
        }
        o << '\n';
    }
    return o.str();
}

Bytes plyHeader(const std::string& format, std::uint64_t vertices, std::uint64_t faces,
                const std::string& listCount = "uchar") {
    std::ostringstream o;
    o << "ply\nformat " << format << " 1.0\ncomment seed\nelement vertex " << vertices
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty float pressure\n"
      << "element face " << faces << "\nproperty list " << listCount << " int vertex_indices\n"
      << "end_header\n";
    return o.str();
}

Bytes plyAscii(const Seed& s) {
    Bytes b = plyHeader("ascii", s.points.size(), s.triangles.size());
    std::ostringstream o;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        const auto& p = s.points[i];
        o << num(p[0]) << ' ' << num(p[1]) << ' ' << num(p[2]) << ' ' << num(s.pressure[i]) << '\n';
    }
    for (const auto& t : s.triangles) {
        o << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
    return b + o.str();
}

Bytes plyBinary(const Seed& s, std::uint64_t vertices, std::uint64_t faces,
                std::uint8_t listCount = 3) {
    Bytes b = plyHeader("binary_little_endian", vertices, faces);
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        for (const float c : s.points[i]) {
            put<float>(b, c);
        }
        put<float>(b, s.pressure[i]);
    }
    for (const auto& t : s.triangles) {
        put<std::uint8_t>(b, listCount);
        for (const auto i : t) {
            put<std::int32_t>(b, static_cast<std::int32_t>(i));
        }
    }
    return b;
}

Bytes vtkLegacyAscii(const Seed& s) {
    std::ostringstream o;
    o << "# vtk DataFile Version 3.0\nseed\nASCII\nDATASET POLYDATA\nPOINTS " << s.points.size()
      << " float\n";
    for (const auto& p : s.points) {
        o << num(p[0]) << ' ' << num(p[1]) << ' ' << num(p[2]) << '\n';
    }
    o << "POLYGONS " << s.triangles.size() << ' ' << s.triangles.size() * 4 << '\n';
    for (const auto& t : s.triangles) {
        o << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
    o << "POINT_DATA " << s.points.size() << "\nSCALARS pressure float 1\nLOOKUP_TABLE default\n";
    for (const float v : s.pressure) {
        o << num(v) << '\n';
    }
    return o.str();
}

template <typename T>
void putBig(Bytes& out, T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    std::reverse(raw, raw + sizeof(T));
    out.append(raw, sizeof(T));
}

Bytes vtkLegacyBinary(const Seed& s) {
    Bytes b = "# vtk DataFile Version 3.0\nseed\nBINARY\nDATASET POLYDATA\nPOINTS " +
              std::to_string(s.points.size()) + " float\n";
    for (const auto& p : s.points) {
        for (const float c : p) {
            putBig<float>(b, c);
        }
    }
    b += "\nPOLYGONS " + std::to_string(s.triangles.size()) + " " +
         std::to_string(s.triangles.size() * 4) + "\n";
    for (const auto& t : s.triangles) {
        putBig<std::int32_t>(b, 3);
        for (const auto i : t) {
            putBig<std::int32_t>(b, static_cast<std::int32_t>(i));
        }
    }
    b += "\nPOINT_DATA " + std::to_string(s.points.size()) +
         "\nSCALARS pressure float 1\nLOOKUP_TABLE default\n";
    for (const float v : s.pressure) {
        putBig<float>(b, v);
    }
    b += "\n";
    return b;
}

Bytes vtkLegacyGrid(const Seed& s) {
    std::ostringstream o;
    o << "# vtk DataFile Version 3.0\nseed grid\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS "
      << s.points.size() << " float\n";
    for (const auto& p : s.points) {
        o << num(p[0]) << ' ' << num(p[1]) << ' ' << num(p[2]) << '\n';
    }
    o << "CELLS " << s.triangles.size() << ' ' << s.triangles.size() * 4 << '\n';
    for (const auto& t : s.triangles) {
        o << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
    o << "CELL_TYPES " << s.triangles.size() << '\n';
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
        o << "5\n";
    }
    return o.str();
}

std::string joinPoints(const Seed& s) {
    std::string t;
    for (const auto& p : s.points) {
        t += num(p[0]) + " " + num(p[1]) + " " + num(p[2]) + " ";
    }
    return t;
}

std::string joinValues(const std::vector<float>& values) {
    std::string t;
    for (const float v : values) {
        t += num(v) + " ";
    }
    return t;
}

std::string connectivity(const Seed& s) {
    std::string c;
    for (const auto& t : s.triangles) {
        c += std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + " ";
    }
    return c;
}

std::string offsets(const Seed& s) {
    std::string o;
    for (std::size_t i = 1; i <= s.triangles.size(); ++i) {
        o += std::to_string(3 * i) + " ";
    }
    return o;
}

Bytes vtpAscii(const Seed& s, const std::string& pointCount = "",
               const std::string& polyCount = "") {
    std::ostringstream o;
    o << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << " <PolyData>\n  <Piece NumberOfPoints=\""
      << (pointCount.empty() ? std::to_string(s.points.size()) : pointCount)
      << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\""
      << (polyCount.empty() ? std::to_string(s.triangles.size()) : polyCount) << "\">\n"
      << "   <PointData Scalars=\"pressure\">\n"
      << "    <DataArray type=\"Float32\" Name=\"pressure\" format=\"ascii\">"
      << joinValues(s.pressure) << "</DataArray>\n   </PointData>\n"
      << "   <Points>\n    <DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">"
      << joinPoints(s) << "</DataArray>\n   </Points>\n   <Polys>\n"
      << "    <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">" << connectivity(s)
      << "</DataArray>\n"
      << "    <DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">" << offsets(s)
      << "</DataArray>\n   </Polys>\n  </Piece>\n </PolyData>\n</VTKFile>\n";
    return o.str();
}

Bytes vtuAscii(const Seed& s) {
    std::ostringstream o;
    o << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << " <UnstructuredGrid>\n  <Piece NumberOfPoints=\"" << s.points.size()
      << "\" NumberOfCells=\"" << s.triangles.size() << "\">\n"
      << "   <PointData Scalars=\"pressure\">\n"
      << "    <DataArray type=\"Float32\" Name=\"pressure\" format=\"ascii\">"
      << joinValues(s.pressure) << "</DataArray>\n   </PointData>\n"
      << "   <Points>\n    <DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">"
      << joinPoints(s) << "</DataArray>\n   </Points>\n   <Cells>\n"
      << "    <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">" << connectivity(s)
      << "</DataArray>\n"
      << "    <DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">" << offsets(s)
      << "</DataArray>\n    <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">";
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
        o << "5 ";
    }
    o << "</DataArray>\n   </Cells>\n  </Piece>\n </UnstructuredGrid>\n</VTKFile>\n";
    return o.str();
}

/// A VTU with raw appended binary data (UInt32 block headers); `sizeOverride`
/// replaces the points block's byte count when non-zero.
Bytes vtuRaw(const Seed& s, std::uint32_t sizeOverride = 0) {
    std::vector<Bytes> blocks;
    Bytes pressure, points, conn, offs, types;
    for (const float v : s.pressure)
        put<float>(pressure, v);
    for (const auto& p : s.points)
        for (const float c : p)
            put<float>(points, c);
    for (const auto& t : s.triangles)
        for (const auto i : t)
            put<std::int32_t>(conn, static_cast<std::int32_t>(i));
    for (std::size_t i = 1; i <= s.triangles.size(); ++i)
        put<std::int32_t>(offs, static_cast<std::int32_t>(3 * i));
    for (std::size_t i = 0; i < s.triangles.size(); ++i)
        put<std::uint8_t>(types, 5);
    blocks = {pressure, points, conn, offs, types};
    std::vector<std::size_t> at;
    Bytes appended;
    for (std::size_t k = 0; k < blocks.size(); ++k) {
        at.push_back(appended.size());
        put<std::uint32_t>(appended, k == 1 && sizeOverride != 0
                                         ? sizeOverride
                                         : static_cast<std::uint32_t>(blocks[k].size()));
        appended += blocks[k];
    }
    std::ostringstream o;
    o << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt32\">\n"
      << " <UnstructuredGrid>\n  <Piece NumberOfPoints=\"" << s.points.size()
      << "\" NumberOfCells=\"" << s.triangles.size() << "\">\n"
      << "   <PointData><DataArray type=\"Float32\" Name=\"pressure\" format=\"appended\" "
         "offset=\""
      << at[0] << "\"/></PointData>\n"
      << "   <Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"appended\" "
         "offset=\""
      << at[1] << "\"/></Points>\n   <Cells>\n"
      << "    <DataArray type=\"Int32\" Name=\"connectivity\" format=\"appended\" offset=\""
      << at[2] << "\"/>\n"
      << "    <DataArray type=\"Int32\" Name=\"offsets\" format=\"appended\" offset=\"" << at[3]
      << "\"/>\n"
      << "    <DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"" << at[4]
      << "\"/>\n   </Cells>\n  </Piece>\n </UnstructuredGrid>\n"
      << " <AppendedData encoding=\"raw\">\n   _";
    return o.str() + appended + "\n </AppendedData>\n</VTKFile>\n";
}

// ---------------------------------------------------------------------------
// Generic mutations of a valid file.

/// Replaces the first occurrence of `from` (which must be there) by `to`.
Bytes replaced(Bytes b, const std::string& from, const std::string& to) {
    const auto at = b.find(from);
    if (at == Bytes::npos) {
        throw std::runtime_error("corpus generator: '" + from + "' not found in a seed");
    }
    return b.replace(at, from.size(), to);
}

/// Replaces every occurrence of `from` by `to`.
Bytes replacedAll(Bytes b, const std::string& from, const std::string& to) {
    for (auto at = b.find(from); at != Bytes::npos; at = b.find(from, at + to.size())) {
        b.replace(at, from.size(), to);
    }
    return b;
}

/// Truncations at fixed small offsets (inside the first header line, at the
/// end of a binary STL header, ...), at `fractions` even fractions of the size
/// and one byte short; single-byte changes, then bursts of several bytes, at
/// deterministic pseudo-random positions.
void mutations(Corpus& c, const std::string& stem, const std::string& ext, const Bytes& seed,
               unsigned rngSeed, int fractions = 8, int flips = 10) {
    c.add(stem + "-valid" + ext, seed, "the valid seed");
    std::set<std::size_t> cuts = {1, 5, 11, 40, 84, 200};
    for (int k = 1; k < fractions; ++k) {
        cuts.insert(seed.size() * static_cast<std::size_t>(k) /
                    static_cast<std::size_t>(fractions));
    }
    cuts.insert(seed.size() - 1);
    for (const auto cut : cuts) {
        if (cut == 0 || cut >= seed.size()) {
            continue;
        }
        c.add(stem + "-trunc" + std::to_string(cut) + ext, seed.substr(0, cut),
              "truncated to " + std::to_string(cut) + " of " + std::to_string(seed.size()) +
                  " bytes");
    }
    std::mt19937 rng(rngSeed);
    for (int k = 0; k < flips; ++k) {
        Bytes b = seed;
        const int bytes = k < flips / 2 ? 1 : 1 + k;  // single flips, then bursts
        std::string where;
        for (int j = 0; j < bytes; ++j) {
            const std::size_t at = rng() % b.size();
            const auto value = static_cast<char>(k % 3 == 0 ? ~b[at] : static_cast<char>(rng()));
            b[at] = value;
            if (j < 4) {
                where += (where.empty() ? "" : ",") + std::to_string(at);
            }
        }
        c.add(stem + "-flip" + std::to_string(k) + ext, b,
              std::to_string(bytes) + " byte(s) changed at " + where + (bytes > 4 ? ",..." : ""));
    }
}

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

void stlGroup(Corpus& c) {
    const Seed s;
    mutations(c, "ascii", ".stl", stlAscii(s), 11);
    mutations(c, "binary", ".stl", stlBinary(s, 8), 12);
    c.add("binary-count-huge.stl", stlBinary(s, 0xFFFFFFFFU), "binary: 4294967295 triangles");
    c.add("binary-count-plus1.stl", stlBinary(s, 9), "binary: one triangle more than present");
    c.add("binary-count-minus1.stl", stlBinary(s, 7), "binary: one triangle less than present");
    c.add("binary-count-zero.stl", stlBinary(Seed{.triangles = {}}, 0), "binary: 0 triangles");
    c.add("binary-header-only.stl", stlBinary(s, 8).substr(0, 84), "binary: header only");
    c.add("binary-solid-header.stl", replaced(stlBinary(s, 8), "binary seed", "solid seedx"),
          "binary file whose header starts with 'solid'");
    c.add("binary-nan.stl", stlBinary(withPoint(s, 0, {kNaN, 0, 0}), 8), "binary: NaN vertex");
    c.add("binary-inf.stl", stlBinary(withPoint(s, 4, {0, kInf, -kInf}), 8), "binary: Inf vertex");
    c.add("binary-huge-coords.stl", stlBinary(withPoint(s, 1, {3e38F, -3e38F, 3e38F}), 8),
          "binary: coordinates near FLT_MAX");
    c.add("binary-degenerate.stl", stlBinary(degenerate(), 4), "binary: zero-area triangles only");
    c.add("ascii-zero.stl", "solid empty\nendsolid empty\n", "ascii: 0 triangles");
    c.add("ascii-nan.stl", stlAscii(withPoint(s, 0, {kNaN, 0, 0})), "ascii: NaN vertex");
    c.add("ascii-inf.stl", stlAscii(withPoint(s, 2, {kInf, 0, -kInf})), "ascii: Inf vertex");
    c.add("ascii-nonmanifold.stl", stlAscii(nonManifold()), "ascii: non-manifold edges");
    c.add("ascii-degenerate.stl", stlAscii(degenerate()), "ascii: zero-area triangles only");
    c.add("ascii-garbage-number.stl", replacedAll(stlAscii(s), "1.75", "1.7e99999"),
          "ascii: number out of float range");
    c.add("ascii-quad.stl",
          replaced(stlAscii(s), "  endloop", "   vertex 9 9 9\n   vertex 8 8 8\n  endloop"),
          "ascii: a facet with 5 vertices");
    c.add("ascii-no-endsolid.stl", replaced(stlAscii(s), "endsolid seed\n", ""),
          "ascii: no endsolid");
    c.add("ascii-long-line.stl", "solid " + Bytes(1 << 20, 'x') + "\n" + stlAscii(s).substr(11),
          "ascii: a 1 MiB name line");
}

void objGroup(Corpus& c) {
    const Seed s;
    mutations(c, "seed", ".obj", obj(s), 21);
    c.add("index-zero.obj", obj(s) + "f 0 1 2\n", "face index 0");
    c.add("index-out-of-range.obj", obj(s) + "f 1 2 99\n", "face index past the vertices");
    c.add("index-negative-range.obj", obj(s) + "f -1 -2 -99\n", "relative index before the start");
    c.add("index-huge.obj", obj(s) + "f 1 2 99999999999999999999\n", "index beyond 64 bits");
    c.add("index-intmax.obj", obj(s) + "f 1 2 2147483648\n", "index 2^31");
    c.add("relative.obj", obj(s, "") + "f -1 -2 -3\n", "relative indices (valid)");
    c.add("vertices-only.obj", obj(Seed{.triangles = {}}), "0 faces");
    c.add("nan.obj", obj(withPoint(s, 0, {kNaN, 0, 0})), "NaN vertex");
    c.add("inf.obj", obj(withPoint(s, 3, {0, kInf, 0})), "Inf vertex");
    c.add("nonmanifold.obj", obj(nonManifold()), "non-manifold edges");
    c.add("degenerate.obj", obj(degenerate()), "zero-area faces only");
    c.add("short-face.obj", obj(s) + "f 1 2\n", "a face with 2 vertices");
    c.add(
        "long-face.obj",
        obj(s) + "f" +
            [] {
                std::string f;
                for (int i = 0; i < 20000; ++i)
                    f += " " + std::to_string(1 + i % 6);
                return f;
            }() +
            "\n",
        "a face with 20000 vertices");
    c.add("slashes.obj", obj(s) + "f 1/1/1 2//2 3/9999/\n",
          "texture / normal indices out of range");
    c.add("vertex-missing-coords.obj", "v 1\nv 2 3\nv\nf 1 2 3\n", "vertices with < 3 coordinates");
    c.add("binary-junk.obj", Bytes("v 1 2 3\n") + Bytes("\0\0\xff\xfe\0f 1 1 1\n", 14),
          "NUL bytes in the text");
}

void plyGroup(Corpus& c) {
    const Seed s;
    mutations(c, "ascii", ".ply", plyAscii(s), 31);
    mutations(c, "binary", ".ply", plyBinary(s, 6, 8), 32);
    c.add("ascii-vertex-huge.ply",
          replaced(plyAscii(s), "element vertex 6", "element vertex 4294967296"),
          "ascii: 2^32 vertices declared");
    c.add("ascii-face-huge.ply",
          replaced(plyAscii(s), "element face 8", "element face 99999999999999999999"),
          "ascii: 10^20 faces declared");
    c.add("binary-vertex-huge.ply", plyBinary(s, 2000000000, 8), "binary: 2e9 vertices declared");
    c.add("binary-face-huge.ply", plyBinary(s, 6, 4000000000ULL), "binary: 4e9 faces declared");
    c.add("binary-vertex-zero.ply",
          plyBinary(Seed{.points = {}, .triangles = {}, .pressure = {}}, 0, 0),
          "binary: 0 vertices, 0 faces");
    c.add("binary-face-zero.ply", plyBinary(Seed{.triangles = {}}, 6, 0), "binary: 0 faces");
    c.add("binary-list-255.ply", plyBinary(s, 6, 8, 255), "binary: faces claim 255 indices");
    c.add("binary-list-0.ply", plyBinary(s, 6, 8, 0), "binary: faces with 0 indices");
    c.add("ascii-list-huge.ply", replaced(plyAscii(s), "\n3 0 2 4", "\n1000000000 0 2 4"),
          "ascii: a face claims 1e9 indices");
    c.add("ascii-list-negative.ply", replaced(plyAscii(s), "\n3 0 2 4", "\n-3 0 2 4"),
          "ascii: a negative index count");
    c.add("ascii-index-range.ply", replaced(plyAscii(s), "\n3 0 2 4", "\n3 0 2 400"),
          "ascii: index past the vertices");
    c.add("ascii-index-negative.ply", replaced(plyAscii(s), "\n3 0 2 4", "\n3 0 -2 4"),
          "ascii: negative index");
    c.add("binary-index-range.ply",
          plyBinary(Seed{.triangles = {{0, 1, 2}, {0, 1, 1 << 30}}}, 6, 2), "binary: index 2^30");
    c.add("binary-index-negative.ply", plyBinary(Seed{.triangles = {{0, 1, 2}, {0, -1, 2}}}, 6, 2),
          "binary: index -1");
    c.add("ascii-nan.ply", plyAscii(withPoint(s, 0, {kNaN, kNaN, kNaN})), "ascii: NaN vertex");
    c.add("binary-inf.ply", plyBinary(withPoint(s, 1, {kInf, 0, 0}), 6, 8), "binary: Inf vertex");
    Seed nanArray = s;
    nanArray.pressure = {kNaN, kNaN, kNaN, kNaN, kNaN, kNaN};
    c.add("binary-nan-array.ply", plyBinary(nanArray, 6, 8), "binary: all-NaN pressure array");
    nanArray.pressure = {kNaN, 1, kInf, -kInf, 2, kNaN};
    c.add("ascii-mixed-array.ply", plyAscii(nanArray), "ascii: NaN / Inf in the array");
    c.add("nonmanifold.ply", plyAscii(nonManifold()), "ascii: non-manifold edges");
    c.add("degenerate.ply", plyBinary(degenerate(), 4, 4), "binary: zero-area faces only");
    c.add("bad-format.ply", replaced(plyAscii(s), "format ascii", "format binary_middle_endian"),
          "unknown format");
    c.add("bad-type.ply",
          replaced(plyAscii(s), "property float pressure", "property quad pressure"),
          "unknown property type");
    c.add("no-end-header.ply", replaced(plyAscii(s), "end_header\n", ""), "no end_header");
    c.add("header-only.ply", plyHeader("ascii", 6, 8), "header only, no data");
    c.add(
        "many-properties.ply",
        [&] {
            Bytes h = "ply\nformat ascii 1.0\nelement vertex 1\n";
            for (int i = 0; i < 100000; ++i)
                h += "property float p" + std::to_string(i) + "\n";
            return h + "end_header\n";
        }(),
        "100000 properties (took 12 s before the fix) [limit 8 s]");
    c.add(
        "many-properties-ended.ply",
        [&] {
            Bytes h = "ply\nformat ascii 1.0\nelement vertex 1\n";
            for (int i = 0; i < 90000; ++i)
                h += "property float p" + std::to_string(i) + "\n";
            return h + "end_header\n";
        }(),
        "90000 properties and an end_header [limit 8 s]");
    c.add(
        "many-elements.ply",
        [&] {
            Bytes h = "ply\nformat ascii 1.0\n";
            for (int i = 0; i < 90000; ++i)
                h += "element e" + std::to_string(i) + " 0\n";
            return h + "end_header\n";
        }(),
        "90000 elements [limit 8 s]");
}

void vtkGroup(Corpus& c) {
    const Seed s;
    const Bytes ascii = vtkLegacyAscii(s);
    mutations(c, "ascii", ".vtk", ascii, 41);
    mutations(c, "binary", ".vtk", vtkLegacyBinary(s), 42, 6, 8);
    mutations(c, "grid", ".vtk", vtkLegacyGrid(s), 43, 4, 4);
    c.add("points-huge.vtk", replaced(ascii, "POINTS 6", "POINTS 2000000000"),
          "2e9 points declared");
    c.add("points-64bit.vtk", replaced(ascii, "POINTS 6", "POINTS 18446744073709551615"),
          "2^64-1 points declared");
    c.add("points-negative.vtk", replaced(ascii, "POINTS 6", "POINTS -6"), "negative point count");
    c.add("points-zero.vtk", replaced(ascii, "POINTS 6", "POINTS 0"), "0 points declared");
    c.add("polygons-huge.vtk", replaced(ascii, "POLYGONS 8 32", "POLYGONS 8 4000000000"),
          "polygon list size 4e9");
    c.add("polygons-zero.vtk", replaced(ascii, "POLYGONS 8 32", "POLYGONS 0 0"), "0 polygons");
    c.add("polygon-size-huge.vtk", replaced(ascii, "\n3 0 2 4", "\n2000000000 0 2 4"),
          "a polygon claims 2e9 vertices");
    c.add("index-range.vtk", replaced(ascii, "\n3 0 2 4", "\n3 0 2 99"), "index past the points");
    c.add("index-negative.vtk", replaced(ascii, "\n3 0 2 4", "\n3 0 -2 4"), "negative index");
    c.add("point-data-huge.vtk", replaced(ascii, "POINT_DATA 6", "POINT_DATA 999999999"),
          "point data count 1e9");
    c.add("point-data-short.vtk", replaced(ascii, "POINT_DATA 6", "POINT_DATA 5"),
          "point data count one short");
    c.add("scalars-components.vtk",
          replaced(ascii, "SCALARS pressure float 1", "SCALARS pressure float 4000000"),
          "scalars with 4e6 components");
    c.add("nan.vtk", vtkLegacyAscii(withPoint(s, 0, {kNaN, 0, 0})), "NaN point");
    c.add("inf-binary.vtk", vtkLegacyBinary(withPoint(s, 5, {0, 0, -kInf})), "binary: Inf point");
    Seed nanArray = s;
    nanArray.pressure.assign(6, kNaN);
    c.add("nan-array.vtk", vtkLegacyAscii(nanArray), "all-NaN pressure array");
    c.add("nonmanifold.vtk", vtkLegacyAscii(nonManifold()), "non-manifold edges");
    c.add("degenerate.vtk", vtkLegacyAscii(degenerate()), "zero-area polygons only");
    c.add("structured-points.vtk",
          "# vtk DataFile Version 3.0\nvol\nASCII\nDATASET STRUCTURED_POINTS\n"
          "DIMENSIONS 100000 100000 100000\nSPACING 1 1 1\nORIGIN 0 0 0\n",
          "structured points of 10^15 voxels");
    c.add("grid-cell-type.vtk", replacedAll(vtkLegacyGrid(s), "\n5\n", "\n42\n"),
          "grid: unknown cell type 42");
    c.add("grid-tetra-range.vtk",
          "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n"
          "0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 77\nCELL_TYPES 1\n10\n",
          "grid: a tetrahedron with an index past the points");
    c.add("bad-version.vtk", replaced(ascii, "Version 3.0", "Version 99.0"), "version 99.0");
}

void vtpGroup(Corpus& c, const fs::path& demo) {
    const Seed s;
    const Bytes ascii = vtpAscii(s);
    mutations(c, "ascii", ".vtp", ascii, 51);
    if (!demo.empty()) {
        std::ifstream in(demo, std::ios::binary);
        const Bytes bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (bytes.empty()) {
            throw std::runtime_error("cannot read the demo file " + demo.string());
        }
        mutations(c, "demo", ".vtp", bytes, 52, 12, 12);
        // The demo's first appended block header (UInt64 after the '_').
        const auto underscore = bytes.find("<AppendedData encoding=\"raw\">");
        if (underscore != Bytes::npos) {
            const auto at = bytes.find('_', underscore) + 1;
            for (const auto& [value, name] : std::vector<std::pair<std::uint64_t, std::string>>{
                     {~0ULL, "max"}, {1ULL << 40, "1tb"}, {0, "zero"}}) {
                Bytes b = bytes;
                std::memcpy(b.data() + at, &value, sizeof value);
                c.add("demo-block-" + name + ".vtp", b,
                      "demo: first appended block header says " + std::to_string(value));
            }
            Bytes b = bytes;
            std::fill(b.begin() + static_cast<std::ptrdiff_t>(at) + 8,
                      b.begin() + static_cast<std::ptrdiff_t>(std::min(at + 200, b.size() - 20)),
                      '\x5a');
            c.add("demo-zlib-garbage.vtp", b, "demo: first compressed block overwritten");
        }
    }
    c.add("points-huge.vtp", vtpAscii(s, "99999999999"), "1e11 points declared");
    c.add("points-negative.vtp", vtpAscii(s, "-6"), "negative point count");
    c.add("points-zero.vtp", vtpAscii(Seed{.points = {}, .triangles = {}, .pressure = {}}),
          "0 points, 0 polygons");
    c.add("polys-zero.vtp", vtpAscii(Seed{.triangles = {}}), "0 polygons");
    c.add("polys-huge.vtp", vtpAscii(s, "", "4294967297"), "2^32+1 polygons declared");
    c.add("index-range.vtp", replaced(ascii, "\">0 2 4 ", "\">0 2 400 "), "index past the points");
    c.add("index-negative.vtp", replaced(ascii, "\">0 2 4 ", "\">0 -2 4 "), "negative index");
    c.add("offsets-decreasing.vtp", replaced(ascii, "\">3 6 9 ", "\">3 24 9 "),
          "offsets out of order");
    c.add("offsets-huge.vtp", replaced(ascii, "\">3 6 9 ", "\">3 6 2000000000 "),
          "an offset past the connectivity");
    c.add("nan.vtp", vtpAscii(withPoint(s, 0, {kNaN, kNaN, 0})), "NaN points");
    c.add("inf.vtp", vtpAscii(withPoint(s, 2, {kInf, 0, 0})), "Inf point");
    Seed nanArray = s;
    nanArray.pressure.assign(6, kNaN);
    c.add("nan-array.vtp", vtpAscii(nanArray), "all-NaN pressure array");
    c.add("nonmanifold.vtp", vtpAscii(nonManifold()), "non-manifold edges");
    c.add("degenerate.vtp", vtpAscii(degenerate()), "zero-area polygons only");
    c.add("components-huge.vtp",
          replaced(ascii, "NumberOfComponents=\"3\"", "NumberOfComponents=\"1000000000\""),
          "points with 1e9 components");
    c.add("wrong-type.vtp", replaced(ascii, "type=\"PolyData\"", "type=\"ImageData\""),
          "VTKFile type ImageData");
    c.add("base64-garbage.vtp",
          replaced(ascii, "format=\"ascii\">0 2 4", "format=\"binary\">@@@@!!"),
          "binary data that is not base64");
    c.add(
        "deep-nesting.vtp",
        "<?xml version=\"1.0\"?>\n" +
            [] {
                std::string x;
                for (int i = 0; i < 100000; ++i)
                    x += "<a>";
                return x;
            }(),
        "100000 nested elements");
    c.add("xml-entity.vtp",
          "<?xml version=\"1.0\"?>\n<!DOCTYPE x [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b "
          "\"&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;\"><!ENTITY c \"&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;\">"
          "<!ENTITY d \"&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;\">]>\n<VTKFile type=\"PolyData\">&d;"
          "</VTKFile>\n",
          "nested XML entities");
}

void vtuGroup(Corpus& c) {
    const Seed s;
    const Bytes ascii = vtuAscii(s);
    mutations(c, "ascii", ".vtu", ascii, 61);
    mutations(c, "raw", ".vtu", vtuRaw(s), 62);
    c.add("raw-block-huge.vtu", vtuRaw(s, 0xFFFFFFF0U), "raw: points block claims 4 GiB");
    c.add("raw-block-short.vtu", vtuRaw(s, 8), "raw: points block claims 8 bytes");
    c.add("cells-huge.vtu", replaced(ascii, "NumberOfCells=\"8\"", "NumberOfCells=\"3000000000\""),
          "3e9 cells declared");
    c.add("cells-zero.vtu", vtuAscii(Seed{.triangles = {}}), "0 cells");
    c.add("points-huge.vtu",
          replaced(ascii, "NumberOfPoints=\"6\"", "NumberOfPoints=\"9000000000\""),
          "9e9 points declared");
    c.add("cell-type.vtu", replacedAll(ascii, "5 5 5", "99 5 5"), "unknown cell type 99");
    c.add("index-range.vtu", replaced(ascii, "\">0 2 4 ", "\">0 2 4000 "), "index past the points");
    c.add("offsets-huge.vtu", replaced(ascii, "\">3 6 9 ", "\">3 6 900000000 "),
          "an offset past the connectivity");
    c.add("nan.vtu", vtuAscii(withPoint(s, 0, {kNaN, 0, 0})), "NaN point");
    c.add("nan-raw.vtu", vtuRaw(withPoint(s, 1, {0, kInf, kNaN})), "raw: NaN / Inf point");
    Seed nanArray = s;
    nanArray.pressure.assign(6, kNaN);
    c.add("nan-array.vtu", vtuAscii(nanArray), "all-NaN pressure array");
    c.add("nonmanifold.vtu", vtuAscii(nonManifold()), "non-manifold edges");
    c.add("degenerate.vtu", vtuAscii(degenerate()), "zero-area cells only");
    c.add("tetra.vtu", replacedAll(vtuAscii(degenerate()), "5 5 5 5", "10 10 10 10"),
          "tetrahedra made of triangle connectivity");
}

void miscGroup(Corpus& c) {
    for (const char* ext : {".stl", ".obj", ".ply", ".vtk", ".vtp", ".vtu"}) {
        c.add(std::string("empty") + ext, "", "empty file");
        const fs::path dir = c.dir / (std::string("folder") + ext);
        fs::create_directories(dir);
        c.note(dir, "a folder named like a mesh file");
        c.add(std::string("nul") + ext, Bytes(4096, '\0'), "4 KiB of zero bytes");
        c.add(std::string("spaces") + ext, Bytes(1000, ' ') + "\n\n\n", "only white space");
    }
    c.add("unknown.xyz", "1 2 3\n", "unknown extension");
    c.add("empty.dcm", "", "empty .dcm");
    // ~2000 tiny files that are not DICOM, in nested folders.
    const fs::path many = c.dir / "many-files";
    std::mt19937 rng(71);
    for (int i = 0; i < 2000; ++i) {
        const fs::path sub = many / ("d" + std::to_string(i % 20));
        fs::create_directories(sub);
        Bytes b(static_cast<std::size_t>(rng() % 300), '\0');
        for (auto& ch : b)
            ch = static_cast<char>(rng());
        static const char* names[] = {"", ".dcm", ".txt", ".ima", ".DCM"};
        std::ofstream(sub / ("f" + std::to_string(i) + names[i % 5]), std::ios::binary)
            .write(b.data(), static_cast<std::streamsize>(b.size()));
    }
    c.note(many, "a folder with 2000 non-DICOM files");
    // Random bytes behind a DICOM preamble, at several lengths.
    for (const std::size_t length : {0, 1, 7, 64, 1000, 100000}) {
        Bytes b(128, '\0');
        b += "DICM";
        for (std::size_t k = 0; k < length; ++k)
            b += static_cast<char>(rng());
        c.add("preamble-random-" + std::to_string(length) + ".dcm", b,
              "DICOM preamble + " + std::to_string(length) + " random bytes");
        c.add("preamble-random-" + std::to_string(length), b,
              "no extension: DICOM preamble + " + std::to_string(length) + " random bytes");
    }
    // A plausible meta header whose group length and element lengths lie.
    Bytes meta(128, '\0');
    meta += "DICM";
    meta += Bytes("\x02\x00\x00\x00UL\x04\x00", 8);
    put<std::uint32_t>(meta, 0xFFFFFFF0U);
    meta += Bytes("\x02\x00\x10\x00UI", 6);
    put<std::uint16_t>(meta, 0xFFFF);
    meta += "1.2.840.10008.1.2.1";
    c.add("meta-lengths.dcm", meta, "DICOM meta header with huge lengths");
    Bytes dataset = meta.substr(0, 132);
    dataset += Bytes(
        "\x28\x00\x10\x00US\x02\x00\xff\xff\x28\x00\x11\x00US\x02\x00\xff\xff"
        "\xe0\x7f\x10\x00OW\x00\x00",
        28);
    put<std::uint32_t>(dataset, 0xFFFFFFFEU);
    c.add("pixel-data-huge.dcm", dataset, "65535 x 65535 image with a 4 GiB pixel data length");
    // A folder of DICOM-looking junk for render (segmentation path).
    const fs::path junk = c.dir / "dicom-junk";
    fs::create_directories(junk);
    for (int i = 0; i < 5; ++i) {
        std::ofstream(junk / ("i" + std::to_string(i) + ".dcm"), std::ios::binary)
            .write(dataset.data(), static_cast<std::streamsize>(dataset.size()));
    }
    c.note(junk, "a folder of 5 DICOM files with impossible pixel data");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3 && !(argc == 5 && std::string(argv[3]) == "--demo")) {
        std::cerr << "usage: vv_corrupt_corpus OUTDIR stl|obj|ply|vtk|vtp|vtu|misc "
                     "[--demo FILE.vtp]\n";
        return 2;
    }
    try {
        Corpus c;
        c.dir = argv[1];
        fs::create_directories(c.dir);
        c.manifest.open(c.dir / "cases.txt", std::ios::trunc);
        const std::string group = argv[2];
        const fs::path demo = argc == 5 ? fs::path(argv[4]) : fs::path();
        if (group == "stl") {
            stlGroup(c);
        } else if (group == "obj") {
            objGroup(c);
        } else if (group == "ply") {
            plyGroup(c);
        } else if (group == "vtk") {
            vtkGroup(c);
        } else if (group == "vtp") {
            vtpGroup(c, demo);
        } else if (group == "vtu") {
            vtuGroup(c);
        } else if (group == "misc") {
            miscGroup(c);
        } else {
            std::cerr << "vv_corrupt_corpus: unknown group '" << group << "'\n";
            return 2;
        }
        c.manifest.close();
        std::cout << group << ": " << c.count << " cases in " << c.dir.string() << "\n";
    } catch (const std::exception& e) {
        std::cerr << "vv_corrupt_corpus: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
