// SPDX-License-Identifier: GPL-3.0-or-later
// Mesh loading through VTK's readers. VTK's readers trust their input: some
// allocate whatever a header claims, some read out of bounds on bad indices,
// some print to stderr and return half-filled output. So every file first
// passes a cheap structural check ("preflight", MeshPreflight.h) that refuses
// what would make a reader crash, hang or allocate absurdly; VTK's own
// messages are then captured and turned into FormatErrors (RunAlgorithm.h), and
// the output is checked again (finite coordinates, connectivity) before any
// filter touches it (MeshReaders.h, VtkConvert.h).
#include "vv/meshio/MeshLoader.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "MeshReaders.h"
#include "preflight/MeshPreflight.h"
#include "preflight/PreflightCommon.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/meshio/vtkext/VtkConvert.h"

namespace vv::meshio {

namespace fs = std::filesystem;

namespace {

using detail::Format;

std::optional<Format> formatOf(const fs::path& file) {
    const std::string ext = detail::lower(file.extension().string());
    if (ext == ".stl")
        return Format::Stl;
    if (ext == ".obj")
        return Format::Obj;
    if (ext == ".ply")
        return Format::Ply;
    if (ext == ".vtk")
        return Format::LegacyVtk;
    if (ext == ".vtp")
        return Format::Vtp;
    if (ext == ".vtu")
        return Format::Vtu;
    return std::nullopt;
}

/// Checks that `file` is an existing, readable regular file; returns its size.
std::uintmax_t checkReadable(const fs::path& file) {
    if (file.empty()) {
        throw IoError("no file name given");
    }
    std::error_code ec;
    const auto status = fs::status(file, ec);
    if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory) {
        throw IoError(file, "cannot access the file: " + ec.message());
    }
    if (!fs::exists(status)) {
        throw IoError(file, "file not found");
    }
    if (fs::is_directory(status)) {
        throw IoError(file, "is a folder, not a mesh file");
    }
    if (!fs::is_regular_file(status)) {
        throw IoError(file, "is not a regular file (device, pipe or socket)");
    }
    std::FILE* probe = std::fopen(file.c_str(), "rb");
    if (probe == nullptr) {
        const int err = errno;
        throw IoError(file, "cannot open the file for reading: " + std::string(std::strerror(err)));
    }
    std::fclose(probe);
    const auto size = fs::file_size(file, ec);
    if (ec) {
        throw IoError(file, "cannot read the file size: " + ec.message());
    }
    return size;
}

/// `v` in the %g form ("1e+38", "0.5", "nan"), C locale.
std::string numberText(double v) {
    return significantText(v, 6);
}

/// vtkOBJReader always adds a float "GroupIds" cell array: drop it when the
/// file has a single group, else mark it as integer labels.
void tidyObjGroups(scene::Mesh& mesh) {
    for (auto it = mesh.cellArrays.begin(); it != mesh.cellArrays.end(); ++it) {
        if (it->name != "GroupIds" || it->components != 1) {
            continue;
        }
        const auto range = it->finiteRange();
        if (!range || range->first == range->second) {
            mesh.cellArrays.erase(it);
        } else {
            it->integer = true;
        }
        return;
    }
}

/// Adds a point array for every cell array: the mean of the finite values of
/// the triangles around each point (for integer arrays the most common value,
/// smallest on ties); NaN where no triangle around the point has a value.
void addPointArraysFromCells(scene::Mesh& mesh, const Progress& progress) {
    if (mesh.cellArrays.empty()) {
        return;
    }
    const std::size_t points = mesh.positions.size();
    const std::size_t triangles = mesh.triangleCount();
    // Point -> triangles, compressed rows.
    std::vector<std::uint32_t> start(points + 1, 0);
    for (const auto index : mesh.indices) {
        ++start[index + 1];
    }
    for (std::size_t p = 0; p < points; ++p) {
        start[p + 1] += start[p];
    }
    std::vector<std::uint32_t> around(mesh.indices.size());
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < mesh.indices.size(); ++k) {
        around[fill[mesh.indices[k]]++] = static_cast<std::uint32_t>(k / 3);
    }
    std::vector<std::string> taken;
    for (const auto& a : mesh.pointArrays) {
        taken.push_back(a.name);
    }
    std::vector<scene::DataArray> converted;
    std::vector<std::pair<std::string, std::map<std::int64_t, std::string>>> namesOfConverted;
    for (const auto& cell : mesh.cellArrays) {
        progress.throwIfCancelled();
        if (cell.components < 1 || cell.tupleCount() != triangles) {
            continue;
        }
        const auto comps = static_cast<std::size_t>(cell.components);
        scene::DataArray out;
        out.name = detail::pointNameForCellArray(cell.name, taken);
        taken.push_back(out.name);
        out.unit = cell.unit;
        out.components = cell.components;
        out.integer = cell.integer;
        out.fromCells = true;
        if (const auto names = mesh.labelNames.find(cell.name); names != mesh.labelNames.end()) {
            namesOfConverted.emplace_back(out.name, names->second);
        }
        out.values.assign(points * comps, std::numeric_limits<float>::quiet_NaN());
        std::vector<double> sum(comps);
        std::vector<std::pair<float, int>> votes;  // label, count; a handful per point
        for (std::size_t p = 0; p < points; ++p) {
            std::fill(sum.begin(), sum.end(), 0.0);
            votes.clear();
            std::size_t used = 0;
            for (std::uint32_t k = start[p]; k < start[p + 1]; ++k) {
                const float* tuple =
                    cell.values.data() + static_cast<std::size_t>(around[k]) * comps;
                if (!std::all_of(tuple, tuple + comps, [](float v) { return std::isfinite(v); })) {
                    continue;
                }
                ++used;
                if (out.integer && comps == 1) {
                    const auto it = std::find_if(votes.begin(), votes.end(), [&](const auto& vote) {
                        return vote.first == tuple[0];
                    });
                    if (it != votes.end()) {
                        ++it->second;
                    } else {
                        votes.emplace_back(tuple[0], 1);
                    }
                } else {
                    for (std::size_t c = 0; c < comps; ++c) {
                        sum[c] += tuple[c];
                    }
                }
            }
            if (used == 0) {
                continue;
            }
            if (out.integer && comps == 1) {
                auto best = votes.front();
                for (const auto& vote : votes) {
                    if (vote.second > best.second ||
                        (vote.second == best.second && vote.first < best.first)) {
                        best = vote;
                    }
                }
                out.values[p] = best.first;
            } else {
                for (std::size_t c = 0; c < comps; ++c) {
                    out.values[p * comps + c] =
                        static_cast<float>(sum[c] / static_cast<double>(used));
                }
            }
        }
        if (out.integer && comps != 1) {
            out.integer = false;  // averaged vectors of labels are no longer labels
        }
        converted.push_back(std::move(out));
    }
    for (auto& a : converted) {
        mesh.pointArrays.push_back(std::move(a));
    }
    for (auto& [name, names] : namesOfConverted) {
        mesh.labelNames.emplace(name, std::move(names));
    }
}

void scaleMesh(scene::Mesh& mesh, double scale, const fs::path& file) {
    double area2 = 0.0;
    for (auto& p : mesh.positions) {
        const glm::dvec3 scaled = glm::dvec3(p) * scale;
        p = glm::vec3(scaled);
        if (!isFinite(p)) {
            throw FormatError(file, "coordinates overflow when scaled by " + numberText(scale));
        }
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        area2 +=
            doubleTriangleArea(mesh.positions[mesh.indices[t]], mesh.positions[mesh.indices[t + 1]],
                               mesh.positions[mesh.indices[t + 2]]);
    }
    if (!(area2 > 0.0)) {
        throw FormatError(file, "the surface has zero area when scaled by " + numberText(scale));
    }
}

}  // namespace

const std::vector<std::string>& supportedMeshExtensions() {
    static const std::vector<std::string> extensions = {".stl", ".obj", ".ply",
                                                        ".vtk", ".vtp", ".vtu"};
    return extensions;
}

scene::Mesh loadMesh(const fs::path& file, const MeshLoadOptions& options,
                     const Progress& progress) {
    if (!std::isfinite(options.scale) || !(options.scale > 0.0)) {
        throw InvalidArgumentError(
            file, "the scale must be a finite number > 0, not " + numberText(options.scale));
    }
    progress.throwIfCancelled();
    const std::uintmax_t size = checkReadable(file);
    const auto format = formatOf(file);
    if (!format) {
        std::string known;
        for (const auto& ext : supportedMeshExtensions()) {
            known += (known.empty() ? "" : ", ") + ext;
        }
        throw FormatError(file, "unknown mesh file extension '" + file.extension().string() +
                                    "' (supported: " + known + ")");
    }
    if (size == 0) {
        throw FormatError(file, "the file is empty");
    }
    const std::string name = file.filename().string();
    detail::PreflightTicker tick(progress, size, "Checking " + name);
    tick(0);
    const std::string stage = "Reading " + name;

    vtkSmartPointer<vtkPolyData> poly;
    switch (*format) {
        case Format::Stl:
            detail::preflightStl(file, size);
            poly = detail::readStl(file, progress, stage);
            break;
        case Format::Obj:
            detail::preflightObj(file, tick);
            poly = detail::readObj(file, progress, stage);
            break;
        case Format::Ply: {
            const detail::PlyData ply = detail::preflightPly(file, size, tick);
            poly = detail::readPly(file, ply, progress, stage);
            break;
        }
        case Format::LegacyVtk: {
            const detail::LegacyDataset dataset = detail::preflightLegacyVtk(file, size, tick);
            poly = detail::readLegacy(file, dataset, progress, stage);
            break;
        }
        case Format::Vtp:
            detail::preflightXml(file, size, *format, tick);
            poly = detail::readVtp(file, progress, stage);
            break;
        case Format::Vtu:
            detail::preflightXml(file, size, *format, tick);
            poly = detail::readVtu(file, progress, stage);
            break;
    }
    progress.report(0.8, "Converting " + name);
    scene::Mesh mesh = detail::meshFromPolyData(poly, file);
    poly = nullptr;
    if (*format == Format::Obj) {
        tidyObjGroups(mesh);
    }
    if (options.cellArraysToPoints) {
        addPointArraysFromCells(mesh, progress);
    }
    if (options.scale != 1.0) {
        scaleMesh(mesh, options.scale, file);
    }
    progress.report(1.0, "Loaded " + name);
    return mesh;
}

scene::Scene loadScene(const std::vector<fs::path>& files, const MeshLoadOptions& options,
                       const Progress& progress) {
    scene::Scene scene;
    scene.meshes.reserve(files.size());
    const double n = static_cast<double>(files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
        const double begin = static_cast<double>(i) / n;
        const double end = static_cast<double>(i + 1) / n;
        scene.meshes.push_back(loadMesh(files[i], options, progress.sub(begin, end)));
    }
    return scene;
}

}  // namespace vv::meshio
