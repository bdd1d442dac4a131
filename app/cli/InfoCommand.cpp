// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli info PATH... [--json] [--scale S]`: what a mesh file holds,
// or which series a DICOM file / folder / DICOMDIR holds.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli/Arguments.h"
#include "cli/Cli.h"
#include "cli/JsonWriter.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/dicom/Dicom.h"
#include "vv/meshio/MeshLoader.h"

namespace vv::cli {

namespace {

constexpr const char* kInfoUsage =
    "usage: vesselview-cli info PATH... [--json] [--scale S]\n"
    "  Loads each mesh (STL, OBJ, PLY, VTK, VTP, VTU) and prints its vertex and\n"
    "  triangle counts, bounds in mm, and every point / cell array with its\n"
    "  components, unit, range of the finite values and count of non-finite ones.\n"
    "  A DICOM file, a folder (searched recursively) or a DICOMDIR instead lists\n"
    "  its studies and series (UID, modality, description, images, size, spacing,\n"
    "  transfer syntax, whether it can be loaded) and the files that were skipped,\n"
    "  with the reason; patient names and IDs are never printed.\n"
    "  --json     print JSON instead of a table\n"
    "  --scale S  multiply coordinates by S (file in metres: --scale 1000)\n";

struct ArrayInfo {
    std::string name;
    std::string unit;
    int components = 1;
    bool integer = false;
    bool fromCells = false;
    std::optional<std::pair<float, float>> range;
    std::size_t nonFinite = 0;
};

struct MeshInfo {
    std::string file;
    std::string name;
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    vv::Aabb bounds;
    std::vector<ArrayInfo> pointArrays;
    std::vector<ArrayInfo> cellArrays;
};

std::vector<ArrayInfo> summarize(const std::vector<vv::scene::DataArray>& arrays) {
    std::vector<ArrayInfo> out;
    out.reserve(arrays.size());
    for (const auto& a : arrays) {
        out.push_back({a.name, a.unit, a.components, a.integer, a.fromCells, a.finiteRange(),
                       a.nonFiniteCount()});
    }
    return out;
}

/// Six significant digits for people to read (and scripts: C locale).
std::string humanNumber(double v) {
    return vv::readableText(v);
}

void writeJsonArrays(JsonWriter& json, const std::vector<ArrayInfo>& arrays) {
    json.beginArray();
    for (const auto& a : arrays) {
        json.beginObject();
        json.member("name", a.name);
        json.member("unit", a.unit);
        json.member("components", static_cast<std::uint64_t>(a.components));
        json.member("integer", a.integer);
        json.member("from_cells", a.fromCells);
        json.member("range_of", a.components == 1 ? "value" : "magnitude");
        json.key("min");
        a.range ? json.number(a.range->first) : json.null();
        json.key("max");
        a.range ? json.number(a.range->second) : json.null();
        json.member("non_finite", a.nonFinite);
        json.endObject();
    }
    json.endArray();
}

void writeMeshArray(JsonWriter& json, const std::vector<MeshInfo>& meshes) {
    json.beginArray();
    for (const auto& m : meshes) {
        json.beginObject();
        json.member("file", m.file);
        json.member("name", m.name);
        json.member("vertices", m.vertices);
        json.member("triangles", m.triangles);
        json.key("bounds_mm");
        json.beginObject();
        const std::pair<const char*, glm::vec3> corners[] = {
            {"min", m.bounds.min}, {"max", m.bounds.max}, {"size", m.bounds.size()}};
        for (const auto& [corner, v] : corners) {
            json.key(corner);
            json.beginArray();
            for (int k = 0; k < 3; ++k) {
                json.number(v[k]);
            }
            json.endArray();
        }
        json.endObject();
        json.key("point_arrays");
        writeJsonArrays(json, m.pointArrays);
        json.key("cell_arrays");
        writeJsonArrays(json, m.cellArrays);
        json.endObject();
    }
    json.endArray();
}

void writeJson(std::ostream& out, const std::vector<MeshInfo>& meshes) {
    JsonWriter json(out);
    json.beginObject();
    json.key("meshes");
    writeMeshArray(json, meshes);
    json.endObject();
    json.finish();
}

// ---------------------------------------------------------------------------
// Human-readable table

void writeArrayTable(std::ostream& out, const char* title, const std::vector<ArrayInfo>& arrays) {
    if (arrays.empty()) {
        out << "  " << title << ": none\n";
        return;
    }
    out << "  " << title << " (" << arrays.size() << "):\n";
    std::vector<std::vector<std::string>> rows = {
        {"name", "comp", "unit", "min", "max", "non-finite", "notes"}};
    for (const auto& a : arrays) {
        std::string notes;
        const auto note = [&](const char* text) {
            notes += notes.empty() ? text : std::string(", ") + text;
        };
        if (a.components > 1)
            note("range of magnitude");
        if (a.integer)
            note("integer");
        if (a.fromCells)
            note("from cells");
        rows.push_back({a.name, std::to_string(a.components), a.unit.empty() ? "-" : a.unit,
                        a.range ? humanNumber(a.range->first) : "-",
                        a.range ? humanNumber(a.range->second) : "-", std::to_string(a.nonFinite),
                        notes});
    }
    std::vector<std::size_t> width(rows.front().size(), 0);
    for (const auto& row : rows) {
        for (std::size_t c = 0; c < row.size(); ++c) {
            width[c] = std::max(width[c], row[c].size());
        }
    }
    for (const auto& row : rows) {
        std::string line = "    ";
        for (std::size_t c = 0; c < row.size(); ++c) {
            line += row[c];
            if (c + 1 < row.size()) {
                line += std::string(width[c] - row[c].size() + 2, ' ');
            }
        }
        while (!line.empty() && line.back() == ' ') {
            line.pop_back();
        }
        out << line << '\n';
    }
}

void writeTable(std::ostream& out, const std::vector<MeshInfo>& meshes) {
    bool first = true;
    for (const auto& m : meshes) {
        if (!first) {
            out << '\n';
        }
        first = false;
        out << m.file << '\n';
        out << "  name:       " << m.name << '\n';
        out << "  vertices:   " << m.vertices << '\n';
        out << "  triangles:  " << m.triangles << '\n';
        const auto& b = m.bounds;
        out << "  bounds mm:  x [" << humanNumber(b.min.x) << ", " << humanNumber(b.max.x)
            << "]  y [" << humanNumber(b.min.y) << ", " << humanNumber(b.max.y) << "]  z ["
            << humanNumber(b.min.z) << ", " << humanNumber(b.max.z) << "]\n";
        const glm::vec3 size = b.size();
        out << "  size mm:    " << humanNumber(size.x) << " x " << humanNumber(size.y) << " x "
            << humanNumber(size.z) << '\n';
        writeArrayTable(out, "point arrays", m.pointArrays);
        writeArrayTable(out, "cell arrays", m.cellArrays);
    }
}

// ---------------------------------------------------------------------------
// DICOM: what scanDicom found under a path. Patients are numbered, never named.

struct DicomInfo {
    std::string path;
    vv::dicom::DicomScanResult scan;
};

/// True when `path` is read as DICOM: a folder, a DICOMDIR, a .dcm file or a
/// file with the DICM prefix — unless its extension names a mesh format.
bool isDicomPath(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const auto& meshes = vv::meshio::supportedMeshExtensions();
    if (std::find(meshes.begin(), meshes.end(), ext) != meshes.end()) {
        return false;
    }
    return vv::dicom::looksLikeDicom(path);
}

std::string spacingText(const vv::dicom::DicomSeries& s) {
    if (!s.pixelSpacing) {
        return "unknown";
    }
    std::string t = humanNumber(s.pixelSpacing->x) + " x " + humanNumber(s.pixelSpacing->y);
    if (s.sliceSpacing) {
        t += " x " + humanNumber(*s.sliceSpacing);
    }
    return t + " mm";
}

void writeDicomTable(std::ostream& out, const DicomInfo& d) {
    const auto series = d.scan.allSeries();
    out << d.path << "\n";
    out << "  DICOM: " << d.scan.filesExamined << " files, " << series.size() << " series, "
        << d.scan.skipped.size() << " skipped\n";
    int patientNumber = 0;
    for (const auto& p : d.scan.patients) {
        ++patientNumber;
        out << "  patient " << patientNumber << "\n";
        for (const auto& st : p.studies) {
            out << "    study " << (st.studyInstanceUid.empty() ? "(no UID)" : st.studyInstanceUid);
            if (!st.date.empty()) {
                out << "  " << st.date;
            }
            if (!st.description.empty()) {
                out << "  \"" << st.description << "\"";
            }
            out << "\n";
            for (const auto& s : st.series) {
                out << "      series "
                    << (s.seriesInstanceUid.empty() ? "(no UID)" : s.seriesInstanceUid) << "\n";
                out << "        modality:    " << (s.modality.empty() ? "-" : s.modality);
                if (s.seriesNumber) {
                    out << "  (series number " << *s.seriesNumber << ")";
                }
                out << "\n";
                if (!s.description.empty()) {
                    out << "        description: " << s.description << "\n";
                }
                out << "        images:      " << s.imageCount
                    << (s.multiFrame ? " (multi-frame)" : "") << " in " << s.files.size()
                    << (s.files.size() == 1 ? " file\n" : " files\n");
                out << "        size:        " << s.columns << " x " << s.rows
                    << (s.mixedSizes ? " (mixed sizes)" : "") << "\n";
                out << "        spacing:     " << spacingText(s) << "\n";
                out << "        syntax:      " << s.transferSyntaxName << "\n";
                out << "        loadable:    "
                    << (s.unsupportedReason.empty() ? std::string("yes")
                                                    : "no: " + s.unsupportedReason)
                    << "\n";
            }
        }
    }
    if (!d.scan.skipped.empty()) {
        out << "  skipped (" << d.scan.skipped.size() << "):\n";
        for (const auto& k : d.scan.skipped) {
            out << "    " << k.file.string() << ": " << k.reason << "\n";
        }
    }
}

void writeDicomJson(JsonWriter& json, const std::vector<DicomInfo>& dicoms) {
    json.beginArray();
    for (const auto& d : dicoms) {
        json.beginObject();
        json.member("path", d.path);
        json.member("files_examined", d.scan.filesExamined);
        json.key("patients");
        json.beginArray();
        for (const auto& p : d.scan.patients) {
            json.beginObject();
            json.key("studies");
            json.beginArray();
            for (const auto& st : p.studies) {
                json.beginObject();
                json.member("study_instance_uid", st.studyInstanceUid);
                json.member("date", st.date);
                json.member("description", st.description);
                json.key("series");
                json.beginArray();
                for (const auto& s : st.series) {
                    json.beginObject();
                    json.member("series_instance_uid", s.seriesInstanceUid);
                    json.member("modality", s.modality);
                    json.member("description", s.description);
                    json.key("series_number");
                    s.seriesNumber ? json.integer(*s.seriesNumber) : json.null();
                    json.member("images", s.imageCount);
                    json.member("files", s.files.size());
                    json.member("multi_frame", s.multiFrame);
                    json.member("rows", static_cast<std::uint64_t>(s.rows));
                    json.member("columns", static_cast<std::uint64_t>(s.columns));
                    json.member("mixed_sizes", s.mixedSizes);
                    json.key("pixel_spacing_mm");
                    if (s.pixelSpacing) {
                        json.beginArray();
                        json.number(s.pixelSpacing->x);
                        json.number(s.pixelSpacing->y);
                        json.endArray();
                    } else {
                        json.null();
                    }
                    json.key("slice_spacing_mm");
                    s.sliceSpacing ? json.number(*s.sliceSpacing) : json.null();
                    json.member("transfer_syntax", s.transferSyntaxName);
                    json.member("transfer_syntax_uid", s.transferSyntaxUid);
                    json.member("sop_class_uid", s.sopClassUid);
                    json.member("loadable", s.unsupportedReason.empty());
                    json.member("unsupported_reason", s.unsupportedReason);
                    json.endObject();
                }
                json.endArray();
                json.endObject();
            }
            json.endArray();
            json.endObject();
        }
        json.endArray();
        json.key("skipped");
        json.beginArray();
        for (const auto& k : d.scan.skipped) {
            json.beginObject();
            json.member("file", k.file.string());
            json.member("reason", k.reason);
            json.endObject();
        }
        json.endArray();
        json.endObject();
    }
    json.endArray();
}

}  // namespace

int infoCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& /*err*/) {
    std::vector<std::filesystem::path> files;
    bool json = false;
    vv::meshio::MeshLoadOptions options;
    bool optionsEnded = false;
    for (Arguments a("info", args); a.next();) {
        const std::string& arg = a.current();
        if (optionsEnded || !a.isOption()) {
            files.emplace_back(arg);
        } else if (arg == "--") {
            optionsEnded = true;
        } else if (arg == "--help" || arg == "-h") {
            out << kInfoUsage;
            return kOk;
        } else if (arg == "--json") {
            json = true;
        } else if (arg == "--scale") {
            options.scale = parseNumber(a.value(), "--scale");
        } else if (arg.rfind("--scale=", 0) == 0) {
            options.scale = parseNumber(std::string_view(arg).substr(8), "--scale");
        } else {
            a.fail("unknown option '" + arg + "'");
        }
    }
    if (files.empty()) {
        throw UsageError("info needs at least one mesh FILE or DICOM path");
    }
    if (!(options.scale > 0.0)) {
        throw UsageError("--scale must be > 0, not " + humanNumber(options.scale));
    }

    // Load everything first: a bad file fails the command before any output,
    // so the JSON is either complete or absent.
    std::vector<MeshInfo> meshes;
    std::vector<DicomInfo> dicoms;
    meshes.reserve(files.size());
    for (const auto& file : files) {
        if (isDicomPath(file)) {
            DicomInfo d{file.string(), vv::dicom::scanDicom(file)};
            if (d.scan.allSeries().empty()) {
                std::string why = "holds no DICOM image series";
                if (d.scan.skipped.size() == 1) {
                    why += " (" + d.scan.skipped.front().reason + ")";
                } else if (!d.scan.skipped.empty()) {
                    why += " (" + std::to_string(d.scan.skipped.size()) + " files skipped)";
                }
                throw vv::FormatError(file, why);
            }
            dicoms.push_back(std::move(d));
            continue;
        }
        const vv::scene::Mesh mesh = vv::meshio::loadMesh(file, options);
        MeshInfo info;
        info.file = file.string();
        info.name = mesh.name;
        info.vertices = mesh.vertexCount();
        info.triangles = mesh.triangleCount();
        info.bounds = mesh.bounds();
        info.pointArrays = summarize(mesh.pointArrays);
        info.cellArrays = summarize(mesh.cellArrays);
        meshes.push_back(std::move(info));
    }
    if (json) {
        if (dicoms.empty()) {
            writeJson(out, meshes);
        } else {
            JsonWriter writer(out);
            writer.beginObject();
            if (!meshes.empty()) {
                writer.key("meshes");
                writeMeshArray(writer, meshes);
            }
            writer.key("dicom");
            writeDicomJson(writer, dicoms);
            writer.endObject();
            writer.finish();
        }
    } else {
        writeTable(out, meshes);
        for (std::size_t i = 0; i < dicoms.size(); ++i) {
            if (i > 0 || !meshes.empty()) {
                out << '\n';
            }
            writeDicomTable(out, dicoms[i]);
        }
    }
    return kOk;
}

}  // namespace vv::cli
