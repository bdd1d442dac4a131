// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/meshio/MeshWriter.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/meshio/vtkext/VtkConvert.h"

namespace vv::meshio {

namespace {

void checkArrays(const std::vector<scene::DataArray>& arrays, std::size_t tuples, const char* kind,
                 const std::filesystem::path& file) {
    std::set<std::string> names;
    for (const auto& array : arrays) {
        if (array.name.empty()) {
            throw InvalidArgumentError(file, std::string("a ") + kind + " array has no name");
        }
        if (!names.insert(array.name).second) {
            throw InvalidArgumentError(
                file, std::string("two ") + kind + " arrays are called '" + array.name + "'");
        }
        if (array.components < 1 ||
            array.values.size() != tuples * static_cast<std::size_t>(array.components)) {
            throw InvalidArgumentError(file, std::string("the ") + kind + " array '" + array.name +
                                                 "' has " + std::to_string(array.values.size()) +
                                                 " values, expected " + std::to_string(tuples) +
                                                 " tuples of " + std::to_string(array.components));
        }
    }
}

/// Refuses meshes whose parts do not fit together (they would make a file
/// that cannot be read back).
void checkMesh(const scene::Mesh& mesh, const std::filesystem::path& file) {
    if (mesh.indices.size() % 3 != 0) {
        throw InvalidArgumentError(file, "the index count is not a multiple of 3");
    }
    for (const auto index : mesh.indices) {
        if (index >= mesh.positions.size()) {
            throw InvalidArgumentError(file, "a triangle refers to vertex " +
                                                 std::to_string(index) + " but there are only " +
                                                 std::to_string(mesh.positions.size()));
        }
    }
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) {
        throw InvalidArgumentError(file, "the mesh has " + std::to_string(mesh.normals.size()) +
                                             " normals for " +
                                             std::to_string(mesh.positions.size()) + " vertices");
    }
    checkArrays(mesh.pointArrays, mesh.positions.size(), "point", file);
    checkArrays(mesh.cellArrays, mesh.triangleCount(), "cell", file);
}

/// Runs `writer` (a VTK writer set up for the file) into a temporary file
/// renamed to `file`; `what` names the format in errors. `suffix`: the
/// writer appends it to a file name that lacks it (the PLY library does), so
/// it writes to the temporary name with it, renamed to the temporary name.
template <typename Writer>
void writeThrough(Writer* writer, const std::filesystem::path& file, const char* what,
                  const std::string& suffix = {}) {
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        const std::filesystem::path named = temporary.string() + suffix;
        try {
            detail::VtkMessageCapture capture;
            capture.observe(writer);
            writer->SetFileName(named.c_str());
            const int ok = writer->Write();
            if (ok == 0 || capture.hasErrors()) {
                std::string message = capture.summary();
                throw IoError(file, std::string("cannot write the ") + what + " file" +
                                        (message.empty() ? std::string() : ": " + message));
            }
            if (named != temporary) {
                std::filesystem::rename(named, temporary);
            }
        } catch (...) {
            std::error_code ec;
            std::filesystem::remove(named, ec);
            throw;
        }
    });
}

/// `text` with every control character (line breaks too) made a space.
std::string oneLine(std::string text) {
    std::replace_if(
        text.begin(), text.end(), [](unsigned char c) { return c < 0x20 || c == 0x7F; }, ' ');
    return text;
}

/// The STL header: `summary` on one line, at most 80 bytes cut on a UTF-8
/// character boundary, never starting with "solid".
vtkSmartPointer<vtkUnsignedCharArray> stlHeader(const std::string& summary) {
    std::string text = oneLine(summary);
    if (text.size() > 80) {
        std::size_t cut = 80;
        while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0U) == 0x80U) {
            --cut;  // text[cut] continues a character: cut before it starts
        }
        text.resize(cut);
    }
    if (text.rfind("solid", 0) == 0) {
        text[0] = 'S';
    }
    auto header = vtkSmartPointer<vtkUnsignedCharArray>::New();
    header->SetNumberOfValues(static_cast<vtkIdType>(text.size()));
    for (std::size_t i = 0; i < text.size(); ++i) {
        header->SetValue(static_cast<vtkIdType>(i), static_cast<unsigned char>(text[i]));
    }
    return header;
}

/// Writes `poly` as binary, zlib-compressed VTK XML polydata.
void writeVtpFile(vtkPolyData* poly, const std::filesystem::path& file) {
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    writer->SetInputData(poly);
    writer->SetDataModeToBinary();
    writer->SetCompressorTypeToZLib();
    writer->SetHeaderTypeToUInt64();
    writeThrough(writer.Get(), file, "VTP");
}

/// A VTK array of `array`: 32-bit integers for an integer array whose
/// values are all finite and in range, floats otherwise.
vtkSmartPointer<vtkDataArray> vtkArrayOf(const scene::DataArray& array) {
    const bool asInt =
        array.integer && std::all_of(array.values.begin(), array.values.end(), [](float v) {
            return std::isfinite(v) && std::abs(v) < 2.0e9F;
        });
    vtkSmartPointer<vtkDataArray> out;
    if (asInt) {
        out = vtkSmartPointer<vtkIntArray>::New();
    } else {
        out = vtkSmartPointer<vtkFloatArray>::New();
    }
    out->SetName(array.name.c_str());
    out->SetNumberOfComponents(array.components);
    out->SetNumberOfTuples(static_cast<vtkIdType>(array.tupleCount()));
    for (std::size_t i = 0; i < array.values.size(); ++i) {
        out->SetVariantValue(static_cast<vtkIdType>(i), vtkVariant(array.values[i]));
    }
    return out;
}

void addFieldData(vtkPolyData* poly, const MeshFileMetadata& metadata) {
    for (const auto& [name, value] : metadata.fields) {
        auto array = vtkSmartPointer<vtkStringArray>::New();
        array->SetName(name.c_str());
        array->InsertNextValue(value);
        poly->GetFieldData()->AddArray(array);
    }
}

std::string lowerExtension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

}  // namespace

void writeVtp(const scene::Mesh& mesh, const std::filesystem::path& file) {
    checkMesh(mesh, file);
    writeVtpFile(detail::polyDataFromMesh(mesh), file);
}

const std::vector<std::string>& writableMeshExtensions() {
    static const std::vector<std::string> extensions = {".stl", ".vtp", ".ply"};
    return extensions;
}

void writeMeshFile(const scene::Mesh& mesh, const std::filesystem::path& file,
                   const MeshFileMetadata& metadata) {
    const std::string ext = lowerExtension(file);
    const auto& known = writableMeshExtensions();
    if (std::find(known.begin(), known.end(), ext) == known.end()) {
        throw InvalidArgumentError(file, "cannot write '" + file.extension().string() +
                                             "' files; write .stl, .vtp or .ply");
    }
    checkMesh(mesh, file);
    const vtkSmartPointer<vtkPolyData> poly = detail::polyDataFromMesh(mesh);
    if (ext == ".stl") {
        auto writer = vtkSmartPointer<vtkSTLWriter>::New();
        writer->SetInputData(poly);
        writer->SetFileTypeToBinary();
        writer->SetBinaryHeader(stlHeader(metadata.summary));
        writeThrough(writer.Get(), file, "STL");
    } else if (ext == ".ply") {
        auto writer = vtkSmartPointer<vtkPLYWriter>::New();
        writer->SetInputData(poly);
        writer->SetFileTypeToBinary();
        writer->SetDataByteOrderToLittleEndian();
        writer->SetColorModeToOff();
        for (const auto& [name, value] : metadata.fields) {
            std::string comment = name;
            comment += ": ";
            comment += value;
            writer->AddComment(oneLine(std::move(comment)));
        }
        writeThrough(writer.Get(), file, "PLY", ".ply");
    } else {
        addFieldData(poly, metadata);
        writeVtpFile(poly, file);
    }
}

void writePolylinesVtp(const PolylineSet& lines, const std::filesystem::path& file,
                       const MeshFileMetadata& metadata) {
    for (const auto& line : lines.lines) {
        if (line.size() < 2) {
            throw InvalidArgumentError(file, "a polyline has fewer than two points");
        }
        for (const std::uint32_t index : line) {
            if (index >= lines.points.size()) {
                throw InvalidArgumentError(file, "a polyline refers to point " +
                                                     std::to_string(index) + " of " +
                                                     std::to_string(lines.points.size()));
            }
        }
    }
    checkArrays(lines.pointArrays, lines.points.size(), "point", file);
    checkArrays(lines.lineArrays, lines.lines.size(), "line", file);
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(lines.points.size()));
    for (std::size_t i = 0; i < lines.points.size(); ++i) {
        const glm::dvec3& p = lines.points[i];
        points->SetPoint(static_cast<vtkIdType>(i), p.x, p.y, p.z);
    }
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    for (const auto& line : lines.lines) {
        cells->InsertNextCell(static_cast<int>(line.size()));
        for (const std::uint32_t index : line) {
            cells->InsertCellPoint(static_cast<vtkIdType>(index));
        }
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetLines(cells);
    for (const auto& array : lines.pointArrays) {
        poly->GetPointData()->AddArray(vtkArrayOf(array));
    }
    for (const auto& array : lines.lineArrays) {
        poly->GetCellData()->AddArray(vtkArrayOf(array));
    }
    addFieldData(poly, metadata);
    writeVtpFile(poly, file);
}

}  // namespace vv::meshio
