// SPDX-License-Identifier: GPL-3.0-or-later
// preflightStl (MeshPreflight.h): the binary STL size check.
#include <array>
#include <string>
#include <vtksys/SystemTools.hxx>

#include "ByteReader.h"
#include "MeshPreflight.h"
#include "vv/core/Error.h"

namespace vv::meshio::detail {

namespace fs = std::filesystem;

void preflightStl(const fs::path& file, std::uintmax_t size) {
    // Decide binary vs ASCII exactly as vtkSTLReader does.
    const auto type = vtksys::SystemTools::DetectFileType(file.c_str());
    if (type == vtksys::SystemTools::FileTypeText) {
        return;  // ASCII: vtkSTLReader's parser reports problems itself
    }
    if (size < 84) {
        throw FormatError(file,
                          "too short for a binary STL file (" + std::to_string(size) +
                              " bytes, the header alone takes 84): truncated or not an STL file");
    }
    ByteReader reader(file);
    std::array<unsigned char, 84> header{};
    if (!reader.read(header.data(), header.size())) {
        throw FormatError(file, "cannot read the binary STL header");
    }
    const std::uint64_t claimed = static_cast<std::uint64_t>(header[80]) |
                                  (static_cast<std::uint64_t>(header[81]) << 8U) |
                                  (static_cast<std::uint64_t>(header[82]) << 16U) |
                                  (static_cast<std::uint64_t>(header[83]) << 24U);
    const std::uint64_t room = (size - 84) / 50;
    if (claimed > room) {
        throw FormatError(file, "the binary STL header claims " + std::to_string(claimed) +
                                    " triangles but the file (" + std::to_string(size) +
                                    " bytes) has room for only " + std::to_string(room) +
                                    ": truncated or not an STL file");
    }
    if ((size - 84) % 50 != 0) {
        throw FormatError(file, "the file size (" + std::to_string(size) +
                                    " bytes) is not 84 + 50 per triangle: truncated or not an "
                                    "STL file");
    }
    if (room == 0) {
        throw FormatError(file, "the binary STL file holds no triangles (empty mesh)");
    }
}

}  // namespace vv::meshio::detail
