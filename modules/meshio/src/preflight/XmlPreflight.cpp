// SPDX-License-Identifier: GPL-3.0-or-later
// preflightXml (MeshPreflight.h): the VTK XML structure and binary header checks.
#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "ByteReader.h"
#include "MeshPreflight.h"
#include "PreflightCommon.h"
#include "vv/core/Error.h"

namespace vv::meshio::detail {

namespace fs = std::filesystem;

namespace {

std::optional<std::string> xmlAttribute(std::string_view tag, std::string_view name) {
    std::size_t from = 0;
    while (true) {
        const auto at = tag.find(name, from);
        if (at == std::string_view::npos) {
            return std::nullopt;
        }
        from = at + name.size();
        const bool startOk = at > 0 && std::isspace(static_cast<unsigned char>(tag[at - 1])) != 0;
        std::size_t i = at + name.size();
        while (i < tag.size() && std::isspace(static_cast<unsigned char>(tag[i])) != 0)
            ++i;
        if (!startOk || i >= tag.size() || tag[i] != '=') {
            continue;
        }
        ++i;
        while (i < tag.size() && std::isspace(static_cast<unsigned char>(tag[i])) != 0)
            ++i;
        if (i >= tag.size() || (tag[i] != '"' && tag[i] != '\'')) {
            return std::nullopt;
        }
        const char quote = tag[i];
        const auto close = tag.find(quote, i + 1);
        if (close == std::string_view::npos) {
            return std::nullopt;
        }
        return std::string(tag.substr(i + 1, close - i - 1));
    }
}

/// Decodes standard base64 (no whitespace inside); stops at '=' or a bad char.
std::vector<unsigned char> decodeBase64(std::string_view text) {
    std::vector<unsigned char> out;
    std::uint32_t acc = 0;
    int bits = 0;
    for (const char c : text) {
        int v = -1;
        if (c >= 'A' && c <= 'Z')
            v = c - 'A';
        else if (c >= 'a' && c <= 'z')
            v = c - 'a' + 26;
        else if (c >= '0' && c <= '9')
            v = c - '0' + 52;
        else if (c == '+')
            v = 62;
        else if (c == '/')
            v = 63;
        if (v < 0) {
            break;
        }
        acc = (acc << 6U) | static_cast<std::uint32_t>(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(static_cast<unsigned char>((acc >> static_cast<unsigned>(bits)) & 0xFFU));
        }
    }
    return out;
}

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) {
    return a > std::numeric_limits<std::uint64_t>::max() - b
               ? std::numeric_limits<std::uint64_t>::max()
               : a + b;
}

/// What the XML preflight needs to judge a binary data array's header.
struct XmlBinaryLayout {
    std::uint64_t fileSize = 0;
    std::uint64_t factor = 1;  // largest plausible compression ratio
    bool compressed = false;
    bool bigEndian = false;
    int wordSize = 4;  // header_type UInt32 / UInt64
};

/// The first `n` bytes of the binary data at byte `at` of the file: raw, or
/// decoded from base64 (whitespace skipped); fewer at the end of the data.
std::vector<unsigned char> binaryBytesAt(ByteReader& data, std::uint64_t at, bool base64,
                                         std::size_t n) {
    if (!data.seek(at)) {
        return {};
    }
    if (!base64) {
        std::vector<unsigned char> bytes(n);
        bytes.resize(data.readUpTo(reinterpret_cast<char*>(bytes.data()), n));
        return bytes;
    }
    const std::size_t chars = (n + 2) / 3 * 4;
    std::string text;
    char c = 0;
    while (text.size() < chars && data.read(&c, 1)) {
        if (std::isspace(static_cast<unsigned char>(c)) != 0) {
            continue;
        }
        if (c == '<' || c == '=' || c == '_') {
            break;
        }
        text += c;
    }
    auto bytes = decodeBase64(text);
    if (bytes.size() > n) {
        bytes.resize(n);
    }
    return bytes;
}

/// Checks the header in front of one binary data array (the block table of
/// compressed data, or the byte count of uncompressed data): vtkXMLDataParser
/// allocates what it claims before it reads anything, and divides by the
/// block size. `fetch(n)` gives the first n bytes of the header.
void checkBinaryHeader(const std::function<std::vector<unsigned char>(std::size_t)>& fetch,
                       const XmlBinaryLayout& layout, const fs::path& file) {
    const auto ws = static_cast<std::size_t>(layout.wordSize);
    const auto word = [&](const std::vector<unsigned char>& bytes,
                          std::size_t i) -> std::optional<std::uint64_t> {
        const std::size_t begin = i * ws;
        if (bytes.size() < begin + ws) {
            return std::nullopt;
        }
        std::uint64_t v = 0;
        for (std::size_t k = 0; k < ws; ++k) {
            const std::size_t index = layout.bigEndian ? k : ws - 1 - k;
            v = (v << 8U) | bytes[begin + index];
        }
        return v;
    };
    const auto fail = [&](const std::string& what) {
        throw FormatError(file, "a binary data array header " + what + ", but the file has only " +
                                    std::to_string(layout.fileSize) +
                                    " bytes: corrupt or truncated");
    };
    const std::uint64_t allowed = mulSat(layout.fileSize, layout.factor);
    if (!layout.compressed) {
        const auto count = word(fetch(ws), 0);
        if (!count) {
            throw FormatError(file, "a binary data array is cut short: truncated file");
        }
        if (*count > layout.fileSize) {
            fail("claims " + std::to_string(*count) + " bytes");
        }
        return;
    }
    const auto head = fetch(3 * ws);
    const auto blocks = word(head, 0);
    const auto blockSize = word(head, 1);
    const auto lastSize = word(head, 2);
    if (!blocks || !blockSize || !lastSize) {
        throw FormatError(file, "a compressed data array header is cut short: truncated file");
    }
    if (mulSat(*blocks, ws) > layout.fileSize) {
        fail("claims " + std::to_string(*blocks) + " compressed blocks");
    }
    if ((*blocks > 0 && *blockSize == 0) || *lastSize > *blockSize ||
        (*blocks == 0 && *lastSize != 0)) {
        throw FormatError(file, "a compressed data array header has block sizes " +
                                    std::to_string(*blockSize) + " and " +
                                    std::to_string(*lastSize) + ": corrupt file");
    }
    if (*blockSize > allowed) {
        fail("claims blocks of " + std::to_string(*blockSize) + " bytes");
    }
    const std::uint64_t total = *blocks == 0
                                    ? 0
                                    : saturatingAdd(mulSat(*blocks - 1, *blockSize),
                                                    *lastSize == 0 ? *blockSize : *lastSize);
    if (total > allowed) {
        fail("claims " + std::to_string(total) + " uncompressed bytes");
    }
    // The compressed size of every block: together they must fit in the file.
    const auto table = fetch(static_cast<std::size_t>(3 + *blocks) * ws);
    std::uint64_t compressed = 0;
    for (std::uint64_t b = 0; b < *blocks; ++b) {
        const auto size = word(table, static_cast<std::size_t>(3 + b));
        if (!size) {
            throw FormatError(file, "a compressed data array header is cut short: truncated file");
        }
        compressed = saturatingAdd(compressed, *size);
    }
    if (compressed > layout.fileSize) {
        fail("claims " + std::to_string(compressed) + " compressed bytes");
    }
}

}  // namespace

void preflightXml(const fs::path& file, std::uintmax_t size, Format format, PreflightTicker& tick) {
    ByteReader reader(file);
    ByteReader data(file);  // random access to binary array headers
    const std::string expected = format == Format::Vtp ? "PolyData" : "UnstructuredGrid";
    std::string window;  // unprocessed text
    bool sawRoot = false;
    XmlBinaryLayout layout;
    layout.fileSize = size;
    std::uint64_t pieceItems = 0;  // points or cells of the current piece, whichever is more
    std::vector<std::uint64_t> appendedOffsets;
    bool inlineBinaryNext = false;     // the text after the last tag is base64 array data
    std::set<std::string> arrayNames;  // of the current section
    std::optional<std::string> appendedEncoding;
    std::array<char, 1 << 16> chunk{};
    bool eof = false;
    const auto refuse = [&](const std::string& what) {
        throw FormatError(file, what + ", but the file has only " + std::to_string(size) +
                                    " bytes: corrupt or truncated");
    };
    // window[0, consumed) is processed text: dropped only when the window is
    // refilled or left, so a file of many small tags costs linear time (an
    // erase per tag moved the rest of the window each time: fuzzing finding 11).
    std::size_t consumed = 0;
    std::size_t tags = 0;
    constexpr std::size_t kMaxXmlTags = 200000;
    const auto compact = [&] {
        window.erase(0, consumed);
        consumed = 0;
    };
    const auto refill = [&] {
        compact();
        const std::size_t got = reader.readSome(chunk.data(), chunk.size());
        eof = got == 0;
        window.append(chunk.data(), got);
        tick(reader.position());
    };
    while (true) {
        if (inlineBinaryNext) {
            // Header of inline binary data: base64 text right after the tag.
            const std::uint64_t at = reader.position() - (window.size() - consumed);
            checkBinaryHeader([&](std::size_t n) { return binaryBytesAt(data, at, true, n); },
                              layout, file);
            inlineBinaryNext = false;
        }
        // Find the next tag start in the window; refill as needed.
        const auto lt = window.find('<', consumed);
        if (lt == std::string::npos) {
            window.clear();
            consumed = 0;
        } else {
            consumed = lt;
        }
        const auto gt = window.find('>', consumed);
        if (consumed == window.size() || gt == std::string::npos) {
            if (window.size() - consumed > (1U << 20)) {
                throw FormatError(file, "an XML tag is longer than 1 MiB: corrupt file");
            }
            if (eof) {
                compact();
                break;
            }
            refill();
            continue;
        }
        const std::string tag = window.substr(consumed, gt + 1 - consumed);
        consumed = gt + 1;
        // VTK's XML reader keeps every element in memory and slows to a crawl
        // on millions of them (4 million empty tags: ~20 s); real files have
        // a few dozen per piece.
        if (++tags > kMaxXmlTags) {
            throw FormatError(file, "has more than " + std::to_string(kMaxXmlTags) +
                                        " XML tags: not a VTK file this program reads "
                                        "(corrupt?)");
        }
        if (tag.rfind("<?", 0) == 0 || tag.rfind("<!", 0) == 0 || tag.rfind("</", 0) == 0) {
            continue;
        }
        const auto nameEnd = tag.find_first_of(" \t\r\n/>", 1);
        const std::string name = tag.substr(1, nameEnd - 1);
        if (!sawRoot) {
            if (name != "VTKFile") {
                throw FormatError(file, "not a VTK XML file (the first element is <" +
                                            printable(name, 40) + ">, not <VTKFile>)");
            }
            const auto type = xmlAttribute(tag, "type").value_or("");
            if (type != expected) {
                throw FormatError(file, "is a VTK XML '" + printable(type, 40) + "' file, but a " +
                                            expected + " file was expected from its extension");
            }
            // VTK's handling of unexpected values here is not safe: only the
            // values its writers produce are let through.
            const auto compressor = xmlAttribute(tag, "compressor").value_or("");
            const auto byteOrder = xmlAttribute(tag, "byte_order").value_or("LittleEndian");
            const auto headerType = xmlAttribute(tag, "header_type").value_or("UInt32");
            if (!compressor.empty() && compressor != "vtkZLibDataCompressor" &&
                compressor != "vtkLZ4DataCompressor" && compressor != "vtkLZMADataCompressor") {
                throw FormatError(file, "unknown compressor '" + printable(compressor) + "'");
            }
            if (byteOrder != "LittleEndian" && byteOrder != "BigEndian") {
                throw FormatError(file, "unknown byte order '" + printable(byteOrder) + "'");
            }
            if (headerType != "UInt32" && headerType != "UInt64") {
                throw FormatError(file, "unknown header type '" + printable(headerType) + "'");
            }
            layout.compressed = !compressor.empty();
            layout.factor = !layout.compressed                             ? 1
                            : compressor.find("LZMA") != std::string::npos ? 10000
                                                                           : 1100;
            layout.bigEndian = xmlAttribute(tag, "byte_order").value_or("") == "BigEndian";
            layout.wordSize =
                xmlAttribute(tag, "header_type").value_or("UInt32") == "UInt64" ? 8 : 4;
            sawRoot = true;
            continue;
        }
        if (name == "AppendedData") {
            appendedEncoding = xmlAttribute(tag, "encoding").value_or("raw");
            if (*appendedEncoding != "raw" && *appendedEncoding != "base64") {
                throw FormatError(
                    file, "unknown appended data encoding '" + printable(*appendedEncoding) + "'");
            }
            compact();
            break;  // raw data follows; the structure is complete
        }
        const auto number = [&](const char* attribute) -> std::uint64_t {
            const auto text = xmlAttribute(tag, attribute);
            if (!text) {
                return 0;
            }
            const auto value = parseCount(*text);
            if (!value) {
                throw FormatError(file, std::string("the XML attribute ") + attribute + "=\"" +
                                            printable(*text, 30) +
                                            "\" is not a count: corrupt file");
            }
            return *value;
        };
        const std::uint64_t allowed = mulSat(size, layout.factor);
        if (name == "PointData" || name == "CellData" || name == "FieldData" || name == "Points" ||
            name == "Cells" || name == "Verts" || name == "Lines" || name == "Strips" ||
            name == "Polys") {
            arrayNames.clear();  // a new section
        }
        if (name == "Piece") {
            const std::uint64_t points = number("NumberOfPoints");
            std::uint64_t cells = 0;
            for (const char* attribute : {"NumberOfCells", "NumberOfVerts", "NumberOfLines",
                                          "NumberOfStrips", "NumberOfPolys"}) {
                cells = saturatingAdd(cells, number(attribute));
            }
            pieceItems = std::max(points, cells);
            if (saturatingAdd(mulSat(3, points), cells) > allowed) {
                refuse("a piece declares " + std::to_string(points) + " points and " +
                       std::to_string(cells) + " cells");
            }
        } else if (name == "DataArray") {
            // Text arrays are refused: VTK reads damaged ones out of bounds,
            // and a mesh has no use for them.
            static const std::vector<std::string> types = {"Int8",    "UInt8",   "Int16",  "UInt16",
                                                           "Int32",   "Int64",   "UInt32", "UInt64",
                                                           "Float32", "Float64", "Bit"};
            if (xmlAttribute(tag, "type").value_or("") == "String") {
                throw FormatError(file,
                                  "the file has a text (String) data array, which is not "
                                  "supported");
            }
            const auto type = xmlAttribute(tag, "type");
            if (!type || std::find(types.begin(), types.end(), *type) == types.end()) {
                throw FormatError(file, "a data array has " +
                                            (type ? "the unknown type '" + printable(*type) + "'"
                                                  : std::string("no type")) +
                                            ": corrupt file");
            }
            // VTK reads a section with two arrays of the same name out of bounds.
            const auto arrayName = xmlAttribute(tag, "Name");
            if (arrayName && !arrayNames.insert(*arrayName).second) {
                throw FormatError(file, "two data arrays are called '" + printable(*arrayName) +
                                            "' in the same section: corrupt file");
            }
            if (xmlAttribute(tag, "NumberOfComponents") && number("NumberOfComponents") == 0) {
                throw FormatError(file, "a data array has 0 components: corrupt file");
            }
            const std::uint64_t components =
                std::max<std::uint64_t>(1, number("NumberOfComponents"));
            const std::uint64_t tuples = number("NumberOfTuples");
            if (mulSat(components, std::max(pieceItems, tuples)) > allowed) {
                refuse("a data array declares " + std::to_string(components) + " components");
            }
            const std::string dataFormat = xmlAttribute(tag, "format").value_or("ascii");
            if (dataFormat != "ascii" && dataFormat != "binary" && dataFormat != "appended") {
                throw FormatError(file, "a data array has the unknown format '" +
                                            printable(dataFormat) + "': corrupt file");
            }
            if (dataFormat == "appended" && !xmlAttribute(tag, "offset")) {
                throw FormatError(file, "an appended data array has no offset: corrupt file");
            }
            const bool selfClosing = tag.size() >= 2 && tag[tag.size() - 2] == '/';
            if (dataFormat == "appended") {
                appendedOffsets.push_back(number("offset"));
            } else if (dataFormat == "binary" && !selfClosing) {
                inlineBinaryNext = true;
            }
        }
    }
    if (!sawRoot) {
        throw FormatError(file, "not a VTK XML file (no <VTKFile> element)");
    }
    if (!appendedEncoding || appendedOffsets.empty()) {
        return;
    }
    // Appended data starts after the '_' that follows the AppendedData tag;
    // the arrays' offsets count from there.
    std::uint64_t position = reader.position() - window.size();
    while (window.find('_') == std::string::npos && !eof && window.size() < 4096) {
        refill();
    }
    const auto marker = window.find('_');
    if (marker == std::string::npos || window.find_first_not_of(" \t\r\n") != marker) {
        throw FormatError(file, "the appended data has no '_' marker: corrupt file");
    }
    position += marker + 1;
    const std::uint64_t dataStart = position;
    const bool base64 = *appendedEncoding == "base64";
    std::sort(appendedOffsets.begin(), appendedOffsets.end());
    appendedOffsets.erase(std::unique(appendedOffsets.begin(), appendedOffsets.end()),
                          appendedOffsets.end());
    for (const auto offset : appendedOffsets) {
        const std::uint64_t at = saturatingAdd(dataStart, offset);
        if (at >= size) {
            throw FormatError(file, "a data array starts at offset " + std::to_string(offset) +
                                        ", past the end of the file: truncated or corrupt");
        }
        checkBinaryHeader([&](std::size_t n) { return binaryBytesAt(data, at, base64, n); }, layout,
                          file);
        tick(data.position());
    }
}

}  // namespace vv::meshio::detail
