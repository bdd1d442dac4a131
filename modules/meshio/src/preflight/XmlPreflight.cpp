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
#include <utility>
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

/// Throws FormatError: `what` cannot be, as the file has only `size` bytes.
[[noreturn]] void refuseSize(const fs::path& file, std::uintmax_t size, const std::string& what) {
    throw FormatError(file, what + ", but the file has only " + std::to_string(size) +
                                " bytes: corrupt or truncated");
}

/// The count attribute `attribute` of `tag` holds; 0 when it has none;
/// throws FormatError when it holds no count.
std::uint64_t xmlCount(const fs::path& file, const std::string& tag, const char* attribute) {
    const auto text = xmlAttribute(tag, attribute);
    if (!text) {
        return 0;
    }
    const auto value = parseCount(*text);
    if (!value) {
        throw FormatError(file, std::string("the XML attribute ") + attribute + "=\"" +
                                    printable(*text, 30) + "\" is not a count: corrupt file");
    }
    return *value;
}

/// The tags of an XML file one after the other, read in chunks into a window.
class XmlTagReader {
  public:
    XmlTagReader(const fs::path& file, ByteReader& reader, PreflightTicker& tick)
        : file_(file), reader_(reader), tick_(tick) {}

    /// The next tag, "<" to ">"; nullopt at the end of the file. Throws
    /// FormatError for a tag over 1 MiB or more than kMaxXmlTags tags.
    std::optional<std::string> next();

    /// The file offset of the first byte after the last tag.
    [[nodiscard]] std::uint64_t offset() const {
        return reader_.position() - (window_.size() - consumed_);
    }

    /// The file offset where appended data starts: after the '_' that
    /// follows the last tag (whitespace only between them); throws
    /// FormatError when there is no such '_'.
    std::uint64_t appendedDataStart();

  private:
    void compact();
    void refill();

    static constexpr std::size_t kMaxXmlTags = 200000;
    const fs::path& file_;
    ByteReader& reader_;
    PreflightTicker& tick_;
    std::string window_;  // unprocessed text
    // window_[0, consumed_) is processed text: dropped only when the window is
    // refilled or left, so a file of many small tags costs linear time (an
    // erase per tag moved the rest of the window each time: fuzzing finding 11).
    std::size_t consumed_ = 0;
    std::size_t tags_ = 0;
    bool eof_ = false;
    std::array<char, 1 << 16> chunk_{};
};

/// Drops the processed text from the window.
void XmlTagReader::compact() {
    window_.erase(0, consumed_);
    consumed_ = 0;
}

/// Appends the next chunk of the file to the window; eof_ when there is none.
void XmlTagReader::refill() {
    compact();
    const std::size_t got = reader_.readSome(chunk_.data(), chunk_.size());
    eof_ = got == 0;
    window_.append(chunk_.data(), got);
    tick_(reader_.position());
}

std::optional<std::string> XmlTagReader::next() {
    while (true) {
        // Find the next tag start in the window; refill as needed.
        const auto lt = window_.find('<', consumed_);
        if (lt == std::string::npos) {
            window_.clear();
            consumed_ = 0;
        } else {
            consumed_ = lt;
        }
        const auto gt = window_.find('>', consumed_);
        if (consumed_ == window_.size() || gt == std::string::npos) {
            if (window_.size() - consumed_ > (1U << 20)) {
                throw FormatError(file_, "an XML tag is longer than 1 MiB: corrupt file");
            }
            if (eof_) {
                compact();
                return std::nullopt;
            }
            refill();
            continue;
        }
        std::string tag = window_.substr(consumed_, gt + 1 - consumed_);
        consumed_ = gt + 1;
        // VTK's XML reader keeps every element in memory and slows to a crawl
        // on millions of them (4 million empty tags: ~20 s); real files have
        // a few dozen per piece.
        if (++tags_ > kMaxXmlTags) {
            throw FormatError(file_, "has more than " + std::to_string(kMaxXmlTags) +
                                         " XML tags: not a VTK file this program reads "
                                         "(corrupt?)");
        }
        return tag;
    }
}

std::uint64_t XmlTagReader::appendedDataStart() {
    compact();
    // Appended data starts after the '_' that follows the AppendedData tag;
    // the arrays' offsets count from there.
    const std::uint64_t position = reader_.position() - window_.size();
    while (window_.find('_') == std::string::npos && !eof_ && window_.size() < 4096) {
        refill();
    }
    const auto marker = window_.find('_');
    if (marker == std::string::npos || window_.find_first_not_of(" \t\r\n") != marker) {
        throw FormatError(file_, "the appended data has no '_' marker: corrupt file");
    }
    return position + marker + 1;
}

/// What one tag asks of the walk that follows it.
enum class XmlNext {
    Tags,          // go on with the next tag
    InlineBinary,  // check the header of the base64 data right after this tag
    Appended       // the structure is complete; appended data follows
};

/// The structure of a VTK XML file, tag by tag: the root, the pieces' and
/// arrays' declared counts, the arrays' types, names and formats. Keeps what
/// the binary header checks need.
class XmlStructure {
  public:
    XmlStructure(const fs::path& file, std::uintmax_t size, std::string expected)
        : file_(file), size_(size), expected_(std::move(expected)) {
        layout_.fileSize = size;
    }

    /// Checks one tag (not a declaration, comment or end tag); throws
    /// FormatError for what VTK's XML reader would not read safely.
    XmlNext read(const std::string& tag);

    /// Whether the root, a VTKFile element, has been read.
    [[nodiscard]] bool sawRoot() const { return sawRoot_; }
    /// How binary array headers are laid out, from the root's attributes.
    [[nodiscard]] const XmlBinaryLayout& layout() const { return layout_; }
    /// The AppendedData element's encoding ("raw" or "base64"), when there is one.
    [[nodiscard]] const std::optional<std::string>& appendedEncoding() const {
        return appendedEncoding_;
    }
    /// The offsets of the appended arrays, sorted, each once.
    [[nodiscard]] std::vector<std::uint64_t> appendedOffsets() const;

  private:
    void readRoot(const std::string& tag);
    void readPiece(const std::string& tag);
    XmlNext readDataArray(const std::string& tag);

    const fs::path& file_;
    std::uintmax_t size_;
    std::string expected_;  // "PolyData" or "UnstructuredGrid"
    bool sawRoot_ = false;
    XmlBinaryLayout layout_;
    std::uint64_t pieceItems_ = 0;  // points or cells of the current piece, whichever is more
    std::vector<std::uint64_t> appendedOffsets_;
    std::set<std::string> arrayNames_;  // of the current section
    std::optional<std::string> appendedEncoding_;
};

XmlNext XmlStructure::read(const std::string& tag) {
    const auto nameEnd = tag.find_first_of(" \t\r\n/>", 1);
    const std::string name = tag.substr(1, nameEnd - 1);
    if (!sawRoot_) {
        if (name != "VTKFile") {
            throw FormatError(file_, "not a VTK XML file (the first element is <" +
                                         printable(name, 40) + ">, not <VTKFile>)");
        }
        readRoot(tag);
        return XmlNext::Tags;
    }
    if (name == "AppendedData") {
        appendedEncoding_ = xmlAttribute(tag, "encoding").value_or("raw");
        if (*appendedEncoding_ != "raw" && *appendedEncoding_ != "base64") {
            throw FormatError(
                file_, "unknown appended data encoding '" + printable(*appendedEncoding_) + "'");
        }
        return XmlNext::Appended;
    }
    if (name == "PointData" || name == "CellData" || name == "FieldData" || name == "Points" ||
        name == "Cells" || name == "Verts" || name == "Lines" || name == "Strips" ||
        name == "Polys") {
        arrayNames_.clear();  // a new section
    }
    if (name == "Piece") {
        readPiece(tag);
    } else if (name == "DataArray") {
        return readDataArray(tag);
    }
    return XmlNext::Tags;
}

/// Reads the VTKFile tag: the expected type, and only the compressor, byte
/// order and header type values VTK's writers produce.
void XmlStructure::readRoot(const std::string& tag) {
    const auto type = xmlAttribute(tag, "type").value_or("");
    if (type != expected_) {
        throw FormatError(file_, "is a VTK XML '" + printable(type, 40) + "' file, but a " +
                                     expected_ + " file was expected from its extension");
    }
    // VTK's handling of unexpected values here is not safe: only the
    // values its writers produce are let through.
    const auto compressor = xmlAttribute(tag, "compressor").value_or("");
    const auto byteOrder = xmlAttribute(tag, "byte_order").value_or("LittleEndian");
    const auto headerType = xmlAttribute(tag, "header_type").value_or("UInt32");
    if (!compressor.empty() && compressor != "vtkZLibDataCompressor" &&
        compressor != "vtkLZ4DataCompressor" && compressor != "vtkLZMADataCompressor") {
        throw FormatError(file_, "unknown compressor '" + printable(compressor) + "'");
    }
    if (byteOrder != "LittleEndian" && byteOrder != "BigEndian") {
        throw FormatError(file_, "unknown byte order '" + printable(byteOrder) + "'");
    }
    if (headerType != "UInt32" && headerType != "UInt64") {
        throw FormatError(file_, "unknown header type '" + printable(headerType) + "'");
    }
    layout_.compressed = !compressor.empty();
    layout_.factor = !layout_.compressed                            ? 1
                     : compressor.find("LZMA") != std::string::npos ? 10000
                                                                    : 1100;
    layout_.bigEndian = byteOrder == "BigEndian";
    layout_.wordSize = headerType == "UInt64" ? 8 : 4;
    sawRoot_ = true;
}

/// Reads a Piece tag: its points and cells must fit in the file.
void XmlStructure::readPiece(const std::string& tag) {
    const std::uint64_t points = xmlCount(file_, tag, "NumberOfPoints");
    std::uint64_t cells = 0;
    for (const char* attribute :
         {"NumberOfCells", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"}) {
        cells = saturatingAdd(cells, xmlCount(file_, tag, attribute));
    }
    pieceItems_ = std::max(points, cells);
    if (saturatingAdd(mulSat(3, points), cells) > mulSat(size_, layout_.factor)) {
        refuseSize(file_, size_,
                   "a piece declares " + std::to_string(points) + " points and " +
                       std::to_string(cells) + " cells");
    }
}

/// Reads a DataArray tag: a numeric type, a name new in its section, a
/// component count and size that fit, a known format (appended ones with an
/// offset, which is kept). InlineBinary when base64 data follows the tag.
XmlNext XmlStructure::readDataArray(const std::string& tag) {
    // Text arrays are refused: VTK reads damaged ones out of bounds,
    // and a mesh has no use for them.
    static const std::vector<std::string> types = {"Int8",    "UInt8",   "Int16",  "UInt16",
                                                   "Int32",   "Int64",   "UInt32", "UInt64",
                                                   "Float32", "Float64", "Bit"};
    if (xmlAttribute(tag, "type").value_or("") == "String") {
        throw FormatError(file_, "the file has a text (String) data array, which is not supported");
    }
    const auto type = xmlAttribute(tag, "type");
    if (!type || std::find(types.begin(), types.end(), *type) == types.end()) {
        throw FormatError(file_, "a data array has " +
                                     (type ? "the unknown type '" + printable(*type) + "'"
                                           : std::string("no type")) +
                                     ": corrupt file");
    }
    // VTK reads a section with two arrays of the same name out of bounds.
    const auto arrayName = xmlAttribute(tag, "Name");
    if (arrayName && !arrayNames_.insert(*arrayName).second) {
        throw FormatError(file_, "two data arrays are called '" + printable(*arrayName) +
                                     "' in the same section: corrupt file");
    }
    if (xmlAttribute(tag, "NumberOfComponents") &&
        xmlCount(file_, tag, "NumberOfComponents") == 0) {
        throw FormatError(file_, "a data array has 0 components: corrupt file");
    }
    const std::uint64_t components =
        std::max<std::uint64_t>(1, xmlCount(file_, tag, "NumberOfComponents"));
    const std::uint64_t tuples = xmlCount(file_, tag, "NumberOfTuples");
    if (mulSat(components, std::max(pieceItems_, tuples)) > mulSat(size_, layout_.factor)) {
        refuseSize(file_, size_,
                   "a data array declares " + std::to_string(components) + " components");
    }
    const std::string dataFormat = xmlAttribute(tag, "format").value_or("ascii");
    if (dataFormat != "ascii" && dataFormat != "binary" && dataFormat != "appended") {
        throw FormatError(file_, "a data array has the unknown format '" + printable(dataFormat) +
                                     "': corrupt file");
    }
    if (dataFormat == "appended" && !xmlAttribute(tag, "offset")) {
        throw FormatError(file_, "an appended data array has no offset: corrupt file");
    }
    const bool selfClosing = tag.size() >= 2 && tag[tag.size() - 2] == '/';
    if (dataFormat == "appended") {
        appendedOffsets_.push_back(xmlCount(file_, tag, "offset"));
    } else if (dataFormat == "binary" && !selfClosing) {
        return XmlNext::InlineBinary;
    }
    return XmlNext::Tags;
}

std::vector<std::uint64_t> XmlStructure::appendedOffsets() const {
    std::vector<std::uint64_t> offsets = appendedOffsets_;
    std::sort(offsets.begin(), offsets.end());
    offsets.erase(std::unique(offsets.begin(), offsets.end()), offsets.end());
    return offsets;
}

/// Checks the header of every appended array (data from `dataStart` on);
/// throws FormatError for one that starts past the end of the file or whose
/// header checkBinaryHeader refuses.
void checkAppendedHeaders(const fs::path& file, std::uintmax_t size, ByteReader& data,
                          const XmlStructure& structure, std::uint64_t dataStart,
                          PreflightTicker& tick) {
    const bool base64 = *structure.appendedEncoding() == "base64";
    for (const auto offset : structure.appendedOffsets()) {
        const std::uint64_t at = saturatingAdd(dataStart, offset);
        if (at >= size) {
            throw FormatError(file, "a data array starts at offset " + std::to_string(offset) +
                                        ", past the end of the file: truncated or corrupt");
        }
        checkBinaryHeader([&](std::size_t n) { return binaryBytesAt(data, at, base64, n); },
                          structure.layout(), file);
        tick(data.position());
    }
}

}  // namespace

void preflightXml(const fs::path& file, std::uintmax_t size, Format format, PreflightTicker& tick) {
    ByteReader reader(file);
    ByteReader data(file);  // random access to binary array headers
    XmlTagReader tags(file, reader, tick);
    XmlStructure structure(file, size, format == Format::Vtp ? "PolyData" : "UnstructuredGrid");
    bool appended = false;
    while (const auto tag = tags.next()) {
        if (tag->rfind("<?", 0) == 0 || tag->rfind("<!", 0) == 0 || tag->rfind("</", 0) == 0) {
            continue;
        }
        const XmlNext next = structure.read(*tag);
        if (next == XmlNext::InlineBinary) {
            // Header of inline binary data: base64 text right after the tag.
            const std::uint64_t at = tags.offset();
            checkBinaryHeader([&](std::size_t n) { return binaryBytesAt(data, at, true, n); },
                              structure.layout(), file);
        } else if (next == XmlNext::Appended) {
            appended = true;
            break;  // raw data follows; the structure is complete
        }
    }
    if (!structure.sawRoot()) {
        throw FormatError(file, "not a VTK XML file (no <VTKFile> element)");
    }
    if (!appended || structure.appendedOffsets().empty()) {
        return;
    }
    checkAppendedHeaders(file, size, data, structure, tags.appendedDataStart(), tick);
}

}  // namespace vv::meshio::detail
