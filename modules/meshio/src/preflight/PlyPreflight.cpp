// SPDX-License-Identifier: GPL-3.0-or-later
// preflightPly (MeshPreflight.h): the PLY header parser and data walk.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "ByteReader.h"
#include "MeshPreflight.h"
#include "PreflightCommon.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"

namespace vv::meshio::detail {

namespace fs = std::filesystem;

namespace {

struct PlyType {
    int size = 0;  // bytes; 0 = unknown
    bool integer = false;
    bool isSigned = false;
};

PlyType plyType(std::string_view name) {
    if (name == "char" || name == "int8")
        return {1, true, true};
    if (name == "uchar" || name == "uint8")
        return {1, true, false};
    if (name == "short" || name == "int16")
        return {2, true, true};
    if (name == "ushort" || name == "uint16")
        return {2, true, false};
    if (name == "int" || name == "int32")
        return {4, true, true};
    if (name == "uint" || name == "uint32")
        return {4, true, false};
    if (name == "float" || name == "float32")
        return {4, false, true};
    if (name == "double" || name == "float64")
        return {8, false, true};
    return {};
}

struct PlyProperty {
    std::string name;
    PlyType type;
    bool list = false;
    PlyType countType;
    int extra = -1;  // index into PlyData::extras, -1 when VTK reads it itself
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

bool plyPropertyReadByVtk(const std::string& element, const std::string& name) {
    static const std::vector<std::string> vertexNames = {"x",
                                                         "y",
                                                         "z",
                                                         "nx",
                                                         "ny",
                                                         "nz",
                                                         "red",
                                                         "green",
                                                         "blue",
                                                         "alpha",
                                                         "diffuse_red",
                                                         "diffuse_green",
                                                         "diffuse_blue",
                                                         "u",
                                                         "v",
                                                         "s",
                                                         "t",
                                                         "texture_u",
                                                         "texture_v"};
    static const std::vector<std::string> faceNames = {"red", "green", "blue", "alpha",
                                                       "intensity"};
    const auto& names = element == "vertex" ? vertexNames : faceNames;
    return std::find(names.begin(), names.end(), name) != names.end();
}

double readBinaryValue(const unsigned char* bytes, const PlyType& type, bool bigEndian) {
    unsigned char b[8];
    for (int i = 0; i < type.size; ++i) {
        b[i] = bigEndian ? bytes[type.size - 1 - i] : bytes[i];
    }
    // b is now little endian; assemble portably.
    std::uint64_t raw = 0;
    for (int i = type.size - 1; i >= 0; --i) {
        raw = (raw << 8U) | b[i];
    }
    if (!type.integer) {
        if (type.size == 4) {
            const auto bits = static_cast<std::uint32_t>(raw);
            float f = 0.0F;
            std::memcpy(&f, &bits, sizeof f);
            return f;
        }
        double d = 0.0;
        std::memcpy(&d, &raw, sizeof d);
        return d;
    }
    if (!type.isSigned) {
        return static_cast<double>(raw);
    }
    const int bits = type.size * 8;
    if (bits < 64 && (raw & (std::uint64_t{1} << static_cast<unsigned>(bits - 1))) != 0) {
        return static_cast<double>(
            static_cast<std::int64_t>(raw) -
            static_cast<std::int64_t>(std::uint64_t{1} << static_cast<unsigned>(bits)));
    }
    return static_cast<double>(static_cast<std::int64_t>(raw));
}

}  // namespace

PlyData preflightPly(const fs::path& file, std::uintmax_t size, PreflightTicker& tick) {
    ByteReader reader(file);
    std::string line;
    bool truncated = false;
    constexpr std::size_t kMaxHeaderLine = 4000;  // vtkPLY reads lines into 4 KiB buffers
    if (!reader.readLine(line, kMaxHeaderLine, truncated) || line != "ply") {
        throw FormatError(file, "not a PLY file (it does not start with 'ply')");
    }
    enum class Encoding { Ascii, Little, Big } encoding = Encoding::Ascii;
    bool haveFormat = false;
    bool ended = false;
    std::vector<PlyElement> elements;
    int headerLines = 1;
    while (!ended && reader.readLine(line, kMaxHeaderLine, truncated)) {
        ++headerLines;
        if (truncated || headerLines > 100000) {
            throw FormatError(file, "the PLY header is corrupt (line " +
                                        std::to_string(headerLines) +
                                        " too long or no end_header)");
        }
        const auto words = splitWords(line);
        if (words.empty()) {
            // vtkPLY crashes on an empty header line.
            throw FormatError(
                file, "PLY header line " + std::to_string(headerLines) + " is empty: corrupt file");
        }
        const auto bad = [&](const std::string& why) {
            return FormatError(file, "PLY header line " + std::to_string(headerLines) + " ('" +
                                         printable(line, 80) + "'): " + why);
        };
        // vtkPLY splits header words at spaces and tabs only: another control
        // character ("element\f vertex") makes an unknown keyword, and the
        // properties after it crash vtkPLY::add_property (found by fuzzing).
        if (std::any_of(line.begin(), line.end(), [](char c) {
                const auto u = static_cast<unsigned char>(c);
                return (u < 0x20 && c != '\t') || u == 0x7F;
            })) {
            throw bad("a control character in the header");
        }
        if (words[0] == "comment" || words[0] == "obj_info") {
            continue;
        }
        if (words[0] == "format") {
            if (words.size() < 2)
                throw bad("format missing");
            if (words[1] == "ascii")
                encoding = Encoding::Ascii;
            else if (words[1] == "binary_little_endian")
                encoding = Encoding::Little;
            else if (words[1] == "binary_big_endian")
                encoding = Encoding::Big;
            else
                throw bad("unknown format");
            haveFormat = true;
        } else if (words[0] == "element") {
            if (words.size() != 3)
                throw bad("expected 'element NAME COUNT'");
            const auto count = parseCount(words[2]);
            if (!count)
                throw bad("bad element count");
            if (*count > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
                throw bad("element count " + printable(words[2]) + " is absurd");
            }
            constexpr std::size_t kMaxElements = 1000;  // the check below is quadratic
            if (elements.size() >= kMaxElements) {
                throw bad("more than " + std::to_string(kMaxElements) + " elements: corrupt file");
            }
            if (std::any_of(elements.begin(), elements.end(),
                            [&](const PlyElement& e) { return e.name == words[1]; })) {
                throw bad("a second element called '" + printable(words[1]) + "'");
            }
            elements.push_back({std::string(words[1]), *count, {}});
        } else if (words[0] == "property") {
            if (elements.empty())
                throw bad("property before any element");
            PlyProperty property;
            if (words.size() == 5 && words[1] == "list") {
                property.list = true;
                property.countType = plyType(words[2]);
                property.type = plyType(words[3]);
                property.name = std::string(words[4]);
                if (property.countType.size == 0 || !property.countType.integer) {
                    throw bad("list count type must be an integer type");
                }
            } else if (words.size() == 3) {
                property.type = plyType(words[1]);
                property.name = std::string(words[2]);
            } else {
                throw bad("expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
            }
            if (property.type.size == 0)
                throw bad("unknown property type");
            const auto& existing = elements.back().properties;
            // Real files have a handful; the duplicate check below (and
            // vtkPLY's property look-ups) are quadratic in the count.
            constexpr std::size_t kMaxProperties = 1000;
            if (existing.size() >= kMaxProperties) {
                throw bad("more than " + std::to_string(kMaxProperties) +
                          " properties in one element: corrupt file");
            }
            if (std::any_of(existing.begin(), existing.end(),
                            [&](const PlyProperty& p) { return p.name == property.name; })) {
                throw bad("a second property called '" + printable(property.name) + "'");
            }
            elements.back().properties.push_back(std::move(property));
        } else if (words[0] == "end_header") {
            ended = true;
        } else {
            throw bad("unknown keyword");
        }
    }
    if (!ended) {
        throw FormatError(file, "the PLY header has no end_header: truncated or corrupt");
    }
    if (!haveFormat) {
        throw FormatError(file, "the PLY header names no format");
    }

    // vtkPLYReader reads the vertex and face elements where they start only
    // when no other element comes before them: it reads another element's
    // data as vertices or faces otherwise (out-of-bounds reads and crashes,
    // found by fuzzing). Other elements are fine after both.
    bool otherElementSeen = false;
    for (const auto& element : elements) {
        const bool known = element.name == "vertex" || element.name == "face";
        if (known && otherElementSeen) {
            throw FormatError(file, "the PLY element '" + printable(element.name) +
                                        "' follows another element; VTK's PLY reader "
                                        "needs 'vertex' and 'face' first");
        }
        otherElementSeen = otherElementSeen || !known;
        // vtkPLY frees an invalid pointer when it closes a file with an
        // element without properties (found by fuzzing).
        if (element.properties.empty()) {
            throw FormatError(
                file, "the PLY element '" + printable(element.name) + "' has no properties");
        }
    }

    PlyData data;
    const PlyElement* vertex = nullptr;
    for (auto& element : elements) {
        if (element.name == "vertex") {
            vertex = &element;
            data.vertexCount = element.count;
        } else if (element.name == "face") {
            data.faceCount = element.count;
        }
        if (element.name != "vertex" && element.name != "face") {
            continue;
        }
        for (auto& property : element.properties) {
            if (!property.list && !plyPropertyReadByVtk(element.name, property.name)) {
                property.extra = static_cast<int>(data.extras.size());
                PlyExtra extra;
                extra.element = element.name;
                extra.name = property.name;
                extra.integer = property.type.integer;
                // The count is not checked against the file yet: reserve no
                // more than the file could hold (a value takes >= 1 byte).
                extra.values.reserve(
                    static_cast<std::size_t>(std::min<std::uint64_t>(element.count, size)));
                data.extras.push_back(std::move(extra));
            }
        }
    }
    const auto hasScalar = [&](const char* name) {
        return vertex != nullptr &&
               std::any_of(vertex->properties.begin(), vertex->properties.end(),
                           [&](const PlyProperty& p) { return p.name == name && !p.list; });
    };
    if (!hasScalar("x") || !hasScalar("y") || !hasScalar("z")) {
        throw FormatError(file, "the PLY file has no vertex element with x, y and z");
    }
    for (const auto& element : elements) {
        // vtkPLYReader crashes on a face element without a vertex index list.
        if (element.name == "face" &&
            std::none_of(element.properties.begin(), element.properties.end(),
                         [](const PlyProperty& p) {
                             return p.list && p.type.integer &&
                                    (p.name == "vertex_indices" || p.name == "vertex_index");
                         })) {
            throw FormatError(file, "the PLY face element has no integer 'vertex_indices' list");
        }
    }

    // Cheap bound before walking: every element needs some bytes.
    const std::uint64_t remaining = size - reader.position();
    std::uint64_t minimum = 0;
    for (const auto& element : elements) {
        std::uint64_t perElement = 0;
        for (const auto& property : element.properties) {
            perElement += encoding == Encoding::Ascii
                              ? 2
                              : static_cast<std::uint64_t>(property.list ? property.countType.size
                                                                         : property.type.size);
        }
        minimum += mulSat(std::max<std::uint64_t>(perElement, 1), element.count);
        minimum = std::min(minimum, std::numeric_limits<std::uint64_t>::max() / 2);
    }
    if (minimum > remaining) {
        throw FormatError(file, "the PLY header claims more elements than the file can hold (" +
                                    std::to_string(minimum) + " bytes needed, " +
                                    std::to_string(remaining) + " present): truncated or corrupt");
    }

    const bool bigEndian = encoding == Encoding::Big;
    for (const auto& element : elements) {
        const bool isFace = element.name == "face";
        for (std::uint64_t i = 0; i < element.count; ++i) {
            tick(reader.position());
            const auto where = [&] {
                return element.name + " " + std::to_string(i) + " of " +
                       std::to_string(element.count);
            };
            if (encoding == Encoding::Ascii) {
                if (!reader.readLine(line, kMaxHeaderLine, truncated)) {
                    throw FormatError(file,
                                      "the PLY data ends early at " + where() + ": truncated file");
                }
                if (truncated) {
                    throw FormatError(
                        file, "the PLY line for " + where() + " is longer than 4000 characters");
                }
                if (!reader.lineEnded()) {
                    // vtkPLY misreads a last line without its line end.
                    throw FormatError(
                        file, "the PLY line for " + where() + " has no line end: truncated file");
                }
                // vtkPLY splits data words at spaces and tabs only: another
                // control character (e.g. a vertical tab) leaves it a word short
                // and it reads past the line (found by fuzzing).
                if (std::any_of(line.begin(), line.end(), [](char c) {
                        const auto u = static_cast<unsigned char>(c);
                        return (u < 0x20 && c != '\t' && c != '\r') || u == 0x7F;
                    })) {
                    throw FormatError(file, "the PLY line for " + where() +
                                                " has a control character: corrupt file");
                }
                const auto words = splitWords(line);
                std::size_t w = 0;
                const auto number = [&](std::string_view token, const char* what) {
                    const std::optional<double> v = parseDecimalNumber(token);
                    if (!v) {
                        throw FormatError(file, "the PLY data for " + where() + " has '" +
                                                    printable(token) + "' where a " + what +
                                                    " belongs: corrupt file");
                    }
                    return *v;
                };
                for (const auto& property : element.properties) {
                    if (w >= words.size()) {
                        throw FormatError(file, "the PLY data for " + where() +
                                                    " has too few values: truncated or corrupt");
                    }
                    if (!property.list) {
                        const double v = number(words[w++], "number");
                        if (property.extra >= 0) {
                            data.extras[static_cast<std::size_t>(property.extra)].values.push_back(
                                static_cast<float>(v));
                        }
                        continue;
                    }
                    const double n = number(words[w++], "list length");
                    if (!(n >= 0.0) || n != std::floor(n) ||
                        n > static_cast<double>(words.size() - w)) {
                        throw FormatError(file, "the PLY data for " + where() +
                                                    " has a bad list length '" +
                                                    printable(words[w - 1]) + "': corrupt file");
                    }
                    const auto count = static_cast<std::size_t>(n);
                    const bool indices = isFace && (property.name == "vertex_indices" ||
                                                    property.name == "vertex_index");
                    for (std::size_t k = 0; k < count; ++k) {
                        const double v = number(words[w++], "number");
                        if (indices &&
                            (!(v >= 0.0) || v >= static_cast<double>(data.vertexCount))) {
                            throw FormatError(file, "PLY " + where() + " refers to vertex " +
                                                        printable(words[w - 1]) +
                                                        " but there are only " +
                                                        std::to_string(data.vertexCount));
                        }
                    }
                }
                continue;
            }
            for (const auto& property : element.properties) {
                unsigned char bytes[8];
                if (!property.list) {
                    if (!reader.read(bytes, static_cast<std::size_t>(property.type.size))) {
                        throw FormatError(
                            file, "the PLY data ends early at " + where() + ": truncated file");
                    }
                    if (property.extra >= 0) {
                        data.extras[static_cast<std::size_t>(property.extra)].values.push_back(
                            static_cast<float>(readBinaryValue(bytes, property.type, bigEndian)));
                    }
                    continue;
                }
                if (!reader.read(bytes, static_cast<std::size_t>(property.countType.size))) {
                    throw FormatError(file,
                                      "the PLY data ends early at " + where() + ": truncated file");
                }
                const double n = readBinaryValue(bytes, property.countType, bigEndian);
                const auto itemSize = static_cast<std::uint64_t>(property.type.size);
                if (n < 0.0 || mulSat(static_cast<std::uint64_t>(n), itemSize) >
                                   size - std::min<std::uint64_t>(size, reader.position())) {
                    throw FormatError(file, "the PLY data for " + where() +
                                                " has a bad list length " +
                                                std::to_string(static_cast<long long>(n)) +
                                                ": truncated or corrupt");
                }
                const auto count = static_cast<std::uint64_t>(n);
                const bool indices = isFace && (property.name == "vertex_indices" ||
                                                property.name == "vertex_index");
                if (!indices) {
                    if (!reader.skip(count * itemSize)) {
                        throw FormatError(
                            file, "the PLY data ends early at " + where() + ": truncated file");
                    }
                    continue;
                }
                for (std::uint64_t k = 0; k < count; ++k) {
                    if (!reader.read(bytes, static_cast<std::size_t>(itemSize))) {
                        throw FormatError(
                            file, "the PLY data ends early at " + where() + ": truncated file");
                    }
                    const double v = readBinaryValue(bytes, property.type, bigEndian);
                    if (!(v >= 0.0) || v >= static_cast<double>(data.vertexCount)) {
                        throw FormatError(file, "PLY " + where() + " refers to vertex " +
                                                    std::to_string(static_cast<long long>(v)) +
                                                    " but there are only " +
                                                    std::to_string(data.vertexCount));
                    }
                }
            }
        }
    }
    return data;
}

}  // namespace vv::meshio::detail
