// SPDX-License-Identifier: GPL-3.0-or-later
// preflightPly (MeshPreflight.h): the PLY header parser and data walk.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
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

/// The longest PLY line read (vtkPLY reads lines into 4 KiB buffers).
constexpr std::size_t kMaxPlyLine = 4000;

enum class PlyEncoding { Ascii, Little, Big };

/// What the PLY header declares.
struct PlyHeader {
    PlyEncoding encoding = PlyEncoding::Ascii;
    std::vector<PlyElement> elements;
};

/// One line of the PLY header, for its errors.
struct PlyHeaderLine {
    const fs::path& file;
    int number = 0;  // 1 = the "ply" line
    const std::string& text;

    /// The error `why` about this line, quoting it.
    [[nodiscard]] FormatError bad(const std::string& why) const {
        return {file, "PLY header line " + std::to_string(number) + " ('" + printable(text, 80) +
                          "'): " + why};
    }
};

/// Whether `text` has a control character other than those in `allowed`.
bool hasControlCharacter(const std::string& text, std::string_view allowed) {
    return std::any_of(text.begin(), text.end(), [&](char c) {
        const auto u = static_cast<unsigned char>(c);
        return (u < 0x20 && allowed.find(c) == std::string_view::npos) || u == 0x7F;
    });
}

/// Applies a "format ENCODING VERSION" line to `header`.
void readPlyFormat(const PlyHeaderLine& line, const std::vector<std::string_view>& words,
                   PlyHeader& header) {
    if (words.size() < 2) {
        throw line.bad("format missing");
    }
    if (words[1] == "ascii") {
        header.encoding = PlyEncoding::Ascii;
    } else if (words[1] == "binary_little_endian") {
        header.encoding = PlyEncoding::Little;
    } else if (words[1] == "binary_big_endian") {
        header.encoding = PlyEncoding::Big;
    } else {
        throw line.bad("unknown format");
    }
}

/// Adds the element an "element NAME COUNT" line declares: a sane count, a new name.
void readPlyElement(const PlyHeaderLine& line, const std::vector<std::string_view>& words,
                    std::vector<PlyElement>& elements) {
    if (words.size() != 3) {
        throw line.bad("expected 'element NAME COUNT'");
    }
    const auto count = parseCount(words[2]);
    if (!count) {
        throw line.bad("bad element count");
    }
    if (*count > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
        throw line.bad("element count " + printable(words[2]) + " is absurd");
    }
    constexpr std::size_t kMaxElements = 1000;  // the check below is quadratic
    if (elements.size() >= kMaxElements) {
        throw line.bad("more than " + std::to_string(kMaxElements) + " elements: corrupt file");
    }
    if (std::any_of(elements.begin(), elements.end(),
                    [&](const PlyElement& e) { return e.name == words[1]; })) {
        throw line.bad("a second element called '" + printable(words[1]) + "'");
    }
    elements.push_back({std::string(words[1]), *count, {}});
}

/// Adds the property a "property [list COUNT_TYPE] TYPE NAME" line declares
/// to the last element: known types, an integer list count, a new name.
void readPlyProperty(const PlyHeaderLine& line, const std::vector<std::string_view>& words,
                     std::vector<PlyElement>& elements) {
    if (elements.empty()) {
        throw line.bad("property before any element");
    }
    PlyProperty property;
    if (words.size() == 5 && words[1] == "list") {
        property.list = true;
        property.countType = plyType(words[2]);
        property.type = plyType(words[3]);
        property.name = std::string(words[4]);
        if (property.countType.size == 0 || !property.countType.integer) {
            throw line.bad("list count type must be an integer type");
        }
    } else if (words.size() == 3) {
        property.type = plyType(words[1]);
        property.name = std::string(words[2]);
    } else {
        throw line.bad("expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
    }
    if (property.type.size == 0) {
        throw line.bad("unknown property type");
    }
    const auto& existing = elements.back().properties;
    // Real files have a handful; the duplicate check below (and
    // vtkPLY's property look-ups) are quadratic in the count.
    constexpr std::size_t kMaxProperties = 1000;
    if (existing.size() >= kMaxProperties) {
        throw line.bad("more than " + std::to_string(kMaxProperties) +
                       " properties in one element: corrupt file");
    }
    if (std::any_of(existing.begin(), existing.end(),
                    [&](const PlyProperty& p) { return p.name == property.name; })) {
        throw line.bad("a second property called '" + printable(property.name) + "'");
    }
    elements.back().properties.push_back(std::move(property));
}

/// Reads the header from "ply" to "end_header" as vtkPLY would, refusing
/// what would make it crash; throws FormatError naming the line.
PlyHeader readPlyHeader(const fs::path& file, ByteReader& reader) {
    std::string text;
    bool truncated = false;
    if (!reader.readLine(text, kMaxPlyLine, truncated) || text != "ply") {
        throw FormatError(file, "not a PLY file (it does not start with 'ply')");
    }
    PlyHeader header;
    bool haveFormat = false;
    bool ended = false;
    PlyHeaderLine line{file, 1, text};
    while (!ended && reader.readLine(text, kMaxPlyLine, truncated)) {
        ++line.number;
        if (truncated || line.number > 100000) {
            throw FormatError(file, "the PLY header is corrupt (line " +
                                        std::to_string(line.number) +
                                        " too long or no end_header)");
        }
        const auto words = splitWords(text);
        if (words.empty()) {
            // vtkPLY crashes on an empty header line.
            throw FormatError(
                file, "PLY header line " + std::to_string(line.number) + " is empty: corrupt file");
        }
        // vtkPLY splits header words at spaces and tabs only: another control
        // character ("element\f vertex") makes an unknown keyword, and the
        // properties after it crash vtkPLY::add_property (found by fuzzing).
        if (hasControlCharacter(text, "\t")) {
            throw line.bad("a control character in the header");
        }
        if (words[0] == "comment" || words[0] == "obj_info") {
            continue;
        }
        if (words[0] == "format") {
            readPlyFormat(line, words, header);
            haveFormat = true;
        } else if (words[0] == "element") {
            readPlyElement(line, words, header.elements);
        } else if (words[0] == "property") {
            readPlyProperty(line, words, header.elements);
        } else if (words[0] == "end_header") {
            ended = true;
        } else {
            throw line.bad("unknown keyword");
        }
    }
    if (!ended) {
        throw FormatError(file, "the PLY header has no end_header: truncated or corrupt");
    }
    if (!haveFormat) {
        throw FormatError(file, "the PLY header names no format");
    }
    return header;
}

/// Throws FormatError unless 'vertex' and 'face' come before any other
/// element and every element has properties.
void checkPlyElementOrder(const fs::path& file, const std::vector<PlyElement>& elements) {
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
}

/// The vertex and face counts, and an empty PlyExtra for every scalar vertex
/// / face property VTK does not read (its index stored in the property's
/// `extra`). `size` (the file's) bounds the values reserved.
PlyData collectPlyExtras(std::vector<PlyElement>& elements, std::uintmax_t size) {
    PlyData data;
    for (auto& element : elements) {
        if (element.name == "vertex") {
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
    return data;
}

/// Whether `name` is a vertex or face index list's name.
bool isVertexIndexList(const std::string& name) {
    return name == "vertex_indices" || name == "vertex_index";
}

/// Throws FormatError unless there is a vertex element with scalar x, y and z
/// and any face element has an integer vertex index list.
void checkPlyVertexAndFace(const fs::path& file, const std::vector<PlyElement>& elements) {
    const auto vertex = std::find_if(elements.begin(), elements.end(),
                                     [](const PlyElement& e) { return e.name == "vertex"; });
    const auto hasScalar = [&](const char* name) {
        return vertex != elements.end() &&
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
                             return p.list && p.type.integer && isVertexIndexList(p.name);
                         })) {
            throw FormatError(file, "the PLY face element has no integer 'vertex_indices' list");
        }
    }
}

/// Cheap bound before walking: throws FormatError when the elements need
/// more bytes (at least 2 per ASCII value, the type's size per binary one)
/// than the `remaining` bytes after the header.
void checkPlyMinimumSize(const fs::path& file, const PlyHeader& header, std::uint64_t remaining) {
    std::uint64_t minimum = 0;
    for (const auto& element : header.elements) {
        std::uint64_t perElement = 0;
        for (const auto& property : element.properties) {
            perElement += header.encoding == PlyEncoding::Ascii
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
}

/// The bytes of one binary value (8 at most).
using PlyBytes = std::array<unsigned char, 8>;

/// "vertex 3 of 10": element `i` of `element`, for messages.
std::string plyWhere(const PlyElement& element, std::uint64_t i) {
    return element.name + " " + std::to_string(i) + " of " + std::to_string(element.count);
}

/// The walk through the PLY data after the header: every element as its
/// properties declare, list lengths that fit, face indices naming existing
/// vertices; the values of the extra properties are stored in `data`. Throws
/// FormatError naming the element, IoError, and what the ticker throws.
class PlyDataWalk {
  public:
    PlyDataWalk(const fs::path& file, std::uintmax_t size, ByteReader& reader, PlyData& data)
        : file_(file), size_(size), reader_(reader), data_(data) {}

    /// Walks every element of `header`, in order.
    void run(const PlyHeader& header, PreflightTicker& tick);

  private:
    void readAsciiLine(const PlyElement& element, std::uint64_t i);
    void walkAscii(const PlyElement& element, std::uint64_t i);
    void walkAsciiList(const PlyElement& element, std::uint64_t i, const PlyProperty& property,
                       const std::vector<std::string_view>& words, std::size_t& w);
    void walkBinary(const PlyElement& element, std::uint64_t i, bool bigEndian);
    void walkBinaryList(const PlyElement& element, std::uint64_t i, const PlyProperty& property,
                        bool bigEndian);
    void readBytes(PlyBytes& bytes, std::size_t n, const PlyElement& element, std::uint64_t i);
    void storeExtra(const PlyProperty& property, double value);

    const fs::path& file_;
    std::uintmax_t size_;
    ByteReader& reader_;
    PlyData& data_;
    std::string line_;
};

void PlyDataWalk::run(const PlyHeader& header, PreflightTicker& tick) {
    const bool bigEndian = header.encoding == PlyEncoding::Big;
    for (const auto& element : header.elements) {
        for (std::uint64_t i = 0; i < element.count; ++i) {
            tick(reader_.position());
            if (header.encoding == PlyEncoding::Ascii) {
                walkAscii(element, i);
            } else {
                walkBinary(element, i, bigEndian);
            }
        }
    }
}

/// Appends `value` to the values of `property`'s extra, when it has one.
void PlyDataWalk::storeExtra(const PlyProperty& property, double value) {
    if (property.extra >= 0) {
        data_.extras[static_cast<std::size_t>(property.extra)].values.push_back(
            static_cast<float>(value));
    }
}

/// Reads the line of element `i` into line_: complete, not too long, no control characters.
void PlyDataWalk::readAsciiLine(const PlyElement& element, std::uint64_t i) {
    bool truncated = false;
    if (!reader_.readLine(line_, kMaxPlyLine, truncated)) {
        throw FormatError(
            file_, "the PLY data ends early at " + plyWhere(element, i) + ": truncated file");
    }
    if (truncated) {
        throw FormatError(
            file_, "the PLY line for " + plyWhere(element, i) + " is longer than 4000 characters");
    }
    if (!reader_.lineEnded()) {
        // vtkPLY misreads a last line without its line end.
        throw FormatError(
            file_, "the PLY line for " + plyWhere(element, i) + " has no line end: truncated file");
    }
    // vtkPLY splits data words at spaces and tabs only: another control
    // character (e.g. a vertical tab) leaves it a word short and it reads
    // past the line (found by fuzzing).
    if (hasControlCharacter(line_, "\t\r")) {
        throw FormatError(file_, "the PLY line for " + plyWhere(element, i) +
                                     " has a control character: corrupt file");
    }
}

/// The number `token` spells; throws FormatError naming it as a `what` of
/// element `i` otherwise.
double plyNumber(const fs::path& file, std::string_view token, const char* what,
                 const PlyElement& element, std::uint64_t i) {
    const std::optional<double> v = parseDecimalNumber(token);
    if (!v) {
        throw FormatError(file, "the PLY data for " + plyWhere(element, i) + " has '" +
                                    printable(token) + "' where a " + what +
                                    " belongs: corrupt file");
    }
    return *v;
}

/// Walks element `i` of an ASCII file: one line with a value per scalar
/// property and a length and its values per list.
void PlyDataWalk::walkAscii(const PlyElement& element, std::uint64_t i) {
    readAsciiLine(element, i);
    const auto words = splitWords(line_);
    std::size_t w = 0;
    for (const auto& property : element.properties) {
        if (w >= words.size()) {
            throw FormatError(file_, "the PLY data for " + plyWhere(element, i) +
                                         " has too few values: truncated or corrupt");
        }
        if (property.list) {
            walkAsciiList(element, i, property, words, w);
        } else {
            storeExtra(property, plyNumber(file_, words[w++], "number", element, i));
        }
    }
}

/// Walks one ASCII list from words[w] on (w moves past it): a whole length
/// within the line, numbers, and vertex indices in range in a face.
void PlyDataWalk::walkAsciiList(const PlyElement& element, std::uint64_t i,
                                const PlyProperty& property,
                                const std::vector<std::string_view>& words, std::size_t& w) {
    const double n = plyNumber(file_, words[w++], "list length", element, i);
    if (!(n >= 0.0) || n != std::floor(n) || n > static_cast<double>(words.size() - w)) {
        throw FormatError(file_, "the PLY data for " + plyWhere(element, i) +
                                     " has a bad list length '" + printable(words[w - 1]) +
                                     "': corrupt file");
    }
    const auto count = static_cast<std::size_t>(n);
    const bool indices = element.name == "face" && isVertexIndexList(property.name);
    for (std::size_t k = 0; k < count; ++k) {
        const double v = plyNumber(file_, words[w++], "number", element, i);
        if (indices && (!(v >= 0.0) || v >= static_cast<double>(data_.vertexCount))) {
            throw FormatError(file_, "PLY " + plyWhere(element, i) + " refers to vertex " +
                                         printable(words[w - 1]) + " but there are only " +
                                         std::to_string(data_.vertexCount));
        }
    }
}

/// Reads `n` bytes of element `i`; throws FormatError at the end of the file.
void PlyDataWalk::readBytes(PlyBytes& bytes, std::size_t n, const PlyElement& element,
                            std::uint64_t i) {
    if (!reader_.read(bytes.data(), n)) {
        throw FormatError(
            file_, "the PLY data ends early at " + plyWhere(element, i) + ": truncated file");
    }
}

/// Walks element `i` of a binary file, property by property.
void PlyDataWalk::walkBinary(const PlyElement& element, std::uint64_t i, bool bigEndian) {
    for (const auto& property : element.properties) {
        if (property.list) {
            walkBinaryList(element, i, property, bigEndian);
            continue;
        }
        PlyBytes bytes{};
        readBytes(bytes, static_cast<std::size_t>(property.type.size), element, i);
        if (property.extra >= 0) {
            storeExtra(property, readBinaryValue(bytes.data(), property.type, bigEndian));
        }
    }
}

/// Walks one binary list: a length whose items fit in the rest of the file,
/// and vertex indices in range in a face (other lists are skipped).
void PlyDataWalk::walkBinaryList(const PlyElement& element, std::uint64_t i,
                                 const PlyProperty& property, bool bigEndian) {
    PlyBytes bytes{};
    readBytes(bytes, static_cast<std::size_t>(property.countType.size), element, i);
    const double n = readBinaryValue(bytes.data(), property.countType, bigEndian);
    const auto itemSize = static_cast<std::uint64_t>(property.type.size);
    if (n < 0.0 || mulSat(static_cast<std::uint64_t>(n), itemSize) >
                       size_ - std::min<std::uint64_t>(size_, reader_.position())) {
        throw FormatError(file_,
                          "the PLY data for " + plyWhere(element, i) + " has a bad list length " +
                              std::to_string(static_cast<long long>(n)) + ": truncated or corrupt");
    }
    const auto count = static_cast<std::uint64_t>(n);
    if (element.name != "face" || !isVertexIndexList(property.name)) {
        if (!reader_.skip(count * itemSize)) {
            throw FormatError(
                file_, "the PLY data ends early at " + plyWhere(element, i) + ": truncated file");
        }
        return;
    }
    for (std::uint64_t k = 0; k < count; ++k) {
        readBytes(bytes, static_cast<std::size_t>(itemSize), element, i);
        const double v = readBinaryValue(bytes.data(), property.type, bigEndian);
        if (!(v >= 0.0) || v >= static_cast<double>(data_.vertexCount)) {
            throw FormatError(file_, "PLY " + plyWhere(element, i) + " refers to vertex " +
                                         std::to_string(static_cast<long long>(v)) +
                                         " but there are only " +
                                         std::to_string(data_.vertexCount));
        }
    }
}

}  // namespace

PlyData preflightPly(const fs::path& file, std::uintmax_t size, PreflightTicker& tick) {
    ByteReader reader(file);
    PlyHeader header = readPlyHeader(file, reader);
    checkPlyElementOrder(file, header.elements);
    PlyData data = collectPlyExtras(header.elements, size);
    checkPlyVertexAndFace(file, header.elements);
    checkPlyMinimumSize(file, header, size - reader.position());
    PlyDataWalk(file, size, reader, data).run(header, tick);
    return data;
}

}  // namespace vv::meshio::detail
