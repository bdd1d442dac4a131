// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/meshio/MeshWriter.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>

#include <set>
#include <string>

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

}  // namespace

void writeVtp(const scene::Mesh& mesh, const std::filesystem::path& file) {
    checkMesh(mesh, file);
    const vtkSmartPointer<vtkPolyData> poly = detail::polyDataFromMesh(mesh);
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        detail::VtkMessageCapture capture;
        auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
        capture.observe(writer);
        writer->SetFileName(temporary.c_str());
        writer->SetInputData(poly);
        writer->SetDataModeToBinary();
        writer->SetCompressorTypeToZLib();
        writer->SetHeaderTypeToUInt64();
        const int ok = writer->Write();
        if (ok == 0 || capture.hasErrors()) {
            std::string message = capture.summary();
            throw IoError(file, "cannot write the VTP file" +
                                    (message.empty() ? std::string() : ": " + message));
        }
    });
}

}  // namespace vv::meshio
