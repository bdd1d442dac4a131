// SPDX-License-Identifier: GPL-3.0-or-later
// preflightLegacyVtk (MeshPreflight.h): the legacy VTK tokenizer and walk.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
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
#include "vv/meshio/vtkext/VtkConvert.h"

namespace vv::meshio::detail {

namespace fs = std::filesystem;

namespace {

/// Bytes `values` values of legacy VTK type `type` take in a binary file;
/// nullopt for types without a fixed binary size (string, variant) or unknown.
std::optional<std::uint64_t> legacyBinaryBytes(const std::string& type, std::uint64_t values) {
    if (type == "bit") {
        return values / 8 + (values % 8 != 0 ? 1 : 0);
    }
    std::uint64_t size = 0;
    if (type == "unsigned_char" || type == "char" || type == "signed_char" ||
        type == "vtktypeint8" || type == "vtktypeuint8") {
        size = 1;
    } else if (type == "short" || type == "unsigned_short" || type == "vtktypeint16" ||
               type == "vtktypeuint16") {
        size = 2;
    } else if (type == "int" || type == "unsigned_int" || type == "float" ||
               type == "vtkidtype" ||  // written as 32-bit int
               type == "vtktypeint32" || type == "vtktypeuint32" || type == "vtktypefloat32") {
        size = 4;
    } else if (type == "double" || type == "vtktypeint64" || type == "vtktypeuint64" ||
               type == "vtktypefloat64" || type == "long" || type == "unsigned_long") {
        size = 8;  // long: sizeof(long) on the LP64 platforms we build for
    } else {
        return std::nullopt;
    }
    return mulSat(values, size);
}

bool isLegacyTypeName(const std::string& word) {
    return legacyBinaryBytes(word, 0).has_value() || word == "string" || word == "utf8_string" ||
           word == "variant";
}

/// Whitespace-separated tokens of a legacy VTK file as vtkDataReader reads
/// them: strings of at most 255 characters; tokens can be pushed back.
class LegacyTokens {
  public:
    explicit LegacyTokens(ByteReader& reader) : reader_(reader) {}

    bool next(std::string& token) {
        if (!pending_.empty()) {
            token = std::move(pending_.back());
            pending_.pop_back();
            return true;
        }
        token.clear();
        char c = 0;
        do {
            if (!reader_.read(&c, 1)) {
                return false;
            }
        } while (std::isspace(static_cast<unsigned char>(c)) != 0);
        token += c;
        while (token.size() < 255 && reader_.peek(c) &&
               std::isspace(static_cast<unsigned char>(c)) == 0) {
            reader_.read(&c, 1);
            token += c;
        }
        return true;
    }
    void pushBack(std::string token) { pending_.push_back(std::move(token)); }
    [[nodiscard]] bool hasPending() const noexcept { return !pending_.empty(); }

    /// Consumes the rest of the current line, as vtkDataReader does before binary data.
    void skipRestOfLine() {
        char c = 0;
        while (reader_.read(&c, 1) && c != '\n') {
        }
    }

  private:
    ByteReader& reader_;
    std::vector<std::string> pending_;
};

/// The keywords vtkDataReader knows; it compares by prefix ("cells\x01" is "cells").
const std::string& legacyKeyword(const std::string& lowered) {
    static const std::vector<std::string> keywords = {
        "dataset",         "points",        "vertices",     "lines",      "polygons",
        "triangle_strips", "cells",         "cell_types",   "point_data", "cell_data",
        "scalars",         "color_scalars", "vectors",      "normals",    "tensors6",
        "tensors",         "global_ids",    "pedigree_ids", "edge_flags", "texture_coordinates",
        "lookup_table",    "field",         "metadata"};
    static const std::string none;
    for (const auto& k : keywords) {
        if (lowered.rfind(k, 0) == 0) {
            return k;
        }
    }
    return none;
}

/// What the first lines of a legacy VTK file say.
struct LegacyHeader {
    int major = 0;  // file format version; 0 when not "%d.%d" (the old cell format)
    bool binary = false;
};

/// Reads the version line, the title and the ASCII / BINARY word as
/// vtkDataReader does; throws FormatError when one is missing or wrong.
LegacyHeader readLegacyHeader(const fs::path& file, ByteReader& reader, LegacyTokens& tokens) {
    std::string line;
    bool truncated = false;
    constexpr const char* kMagic = "# vtk DataFile Version";
    if (!reader.readLine(line, 256, truncated) || line.rfind(kMagic, 0) != 0) {
        throw FormatError(file, "not a legacy VTK file (no '# vtk DataFile Version' line)");
    }
    // Parsed as vtkDataReader does: anything but "%d.%d" means version 0,
    // which selects the old cell format.
    LegacyHeader header;
    int minor = 0;
    if (std::sscanf(line.c_str() + std::strlen(kMagic), "%d.%d", &header.major, &minor) != 2) {
        header.major = 0;
    }
    if (!reader.readLine(line, 256, truncated)) {  // title
        throw FormatError(file, "the legacy VTK header is truncated");
    }
    std::string token;
    if (!tokens.next(token)) {
        throw FormatError(file, "the legacy VTK header is truncated");
    }
    const std::string encoding = lower(token);
    if (encoding.rfind("ascii", 0) != 0 && encoding.rfind("binary", 0) != 0) {
        throw FormatError(file, "the legacy VTK header says '" + printable(token) +
                                    "' where ASCII or BINARY belongs");
    }
    header.binary = encoding.rfind("binary", 0) == 0;
    return header;
}

/// Whether `key` (from legacyKeyword) starts a geometry section.
bool isLegacyGeometryKey(const std::string& key) {
    return key == "points" || key == "vertices" || key == "lines" || key == "polygons" ||
           key == "triangle_strips" || key == "cells" || key == "cell_types";
}

/// The walk through a legacy VTK file after its header, section by section,
/// keeping only what the later checks need (counts, cell sizes and types).
/// Every member that reads throws FormatError for what vtkDataReader would
/// stumble over, and what the ticker throws.
class LegacyWalk {
  public:
    LegacyWalk(const fs::path& file, std::uintmax_t size, ByteReader& reader, LegacyTokens& tokens,
               const LegacyHeader& header, PreflightTicker& tick)
        : file_(file),
          size_(size),
          reader_(reader),
          tokens_(tokens),
          tick_(tick),
          major_(header.major),
          binary_(header.binary) {}

    /// Walks the DATASET line and every section to the end of the file, then
    /// checks the cells against their types; returns the dataset type.
    LegacyDataset run();

  private:
    // Reading pieces, as vtkDataReader reads them.
    [[nodiscard]] FormatError bad(const std::string& what) const;
    void fits(std::uint64_t values, const std::string& what) const;
    std::uint64_t count(const std::string& what);
    std::string word(const std::string& what);
    std::string dataType();
    template <typename Use>
    void readInts(std::uint64_t n, const Use& use);
    void skipArray(std::uint64_t values, const std::string& type);
    void skipMetadata();
    void skipFollowingMetadata();
    // Sections.
    LegacyDataset readDataset();
    void readSection(const std::string& key);
    void readField();
    void readPoints();
    void readCellTypes();
    void readCells(const std::string& key);
    std::uint64_t readCellRecords(const std::string& key, std::uint64_t declared,
                                  std::uint64_t values, std::vector<std::int32_t>& sizes);
    void readAttributeHeader(const std::string& key);
    void readAttribute(const std::string& key);
    void readScalars();
    void checkGridCells() const;

    const fs::path& file_;
    std::uintmax_t size_;
    ByteReader& reader_;
    LegacyTokens& tokens_;
    PreflightTicker& tick_;
    int major_;
    bool binary_;
    bool grid_ = false;  // UNSTRUCTURED_GRID (else POLYDATA)
    std::string token_;  // the last token read
    std::optional<std::uint64_t> pointCount_;
    std::uint64_t cellTotal_ = 0;             // all cells (POLYDATA: of every section)
    std::optional<std::uint64_t> gridCells_;  // UNSTRUCTURED_GRID: cells of CELLS
    std::vector<std::int32_t> cellSizes_;     // their sizes (files before version 5)
    std::optional<std::vector<std::int32_t>> cellTypes_;
    std::uint64_t tuples_ = 0;  // of the current POINT_DATA / CELL_DATA
    bool inAttributes_ = false;
};

/// The error for `what`, naming the byte the walk has reached.
FormatError LegacyWalk::bad(const std::string& what) const {
    return {file_, "legacy VTK data near byte " + std::to_string(reader_.position()) + ": " + what};
}

/// Throws FormatError when `values` values (each at least one byte) cannot fit in the file.
void LegacyWalk::fits(std::uint64_t values, const std::string& what) const {
    if (values > size_) {  // every value takes at least one byte
        throw bad(what + " declared, but the file has only " + std::to_string(size_) +
                  " bytes: corrupt or truncated");
    }
}

/// A count as `stream >> n` reads it: the leading digits of the next token;
/// what follows them stays for the next read. Required: VTK's handling of a
/// missing count is not safe.
std::uint64_t LegacyWalk::count(const std::string& what) {
    if (!tokens_.next(token_)) {
        throw bad("the file ends where " + what + " belongs: truncated");
    }
    const std::size_t start = token_[0] == '+' ? 1 : 0;
    std::size_t end = start;
    while (end < token_.size() && std::isdigit(static_cast<unsigned char>(token_[end])) != 0) {
        ++end;
    }
    if (end == start) {
        throw bad("'" + printable(token_) + "' where " + what + " belongs");
    }
    const std::uint64_t value = parseCount(std::string_view(token_).substr(start, end - start))
                                    .value_or(std::numeric_limits<std::uint64_t>::max());
    if (end < token_.size()) {
        tokens_.pushBack(token_.substr(end));
    }
    return value;
}

/// The next token, required (`what` names it in the error).
std::string LegacyWalk::word(const std::string& what) {
    std::string w;
    if (!tokens_.next(w)) {
        throw bad("the file ends where " + what + " belongs: truncated");
    }
    return w;
}

/// The next token as a known data type (lower case) this file's encoding can hold.
std::string LegacyWalk::dataType() {
    std::string type = lower(word("a data type"));
    if (!isLegacyTypeName(type)) {
        throw bad("unknown data type '" + printable(type) + "'");
    }
    if (binary_ && !legacyBinaryBytes(type, 0)) {
        throw bad("binary arrays of type '" + type + "' are not supported");
    }
    return type;
}

/// Reads `n` ints as vtkDataReader reads cell data: ASCII numbers or
/// big-endian int32 after the end of the keyword line; passes each to `use`.
template <typename Use>
void LegacyWalk::readInts(std::uint64_t n, const Use& use) {
    if (binary_) {
        if (tokens_.hasPending()) {
            throw bad("unexpected text before binary cell data");
        }
        tokens_.skipRestOfLine();
        for (std::uint64_t i = 0; i < n; ++i) {
            unsigned char b[4];
            if (!reader_.read(b, 4)) {
                throw bad("the binary cell data ends early: truncated file");
            }
            const std::uint32_t u = (std::uint32_t{b[0]} << 24U) | (std::uint32_t{b[1]} << 16U) |
                                    (std::uint32_t{b[2]} << 8U) | std::uint32_t{b[3]};
            use(static_cast<std::int64_t>(static_cast<std::int32_t>(u)));
            if ((i & 0xFFFFU) == 0) {
                tick_(reader_.position());
            }
        }
        return;
    }
    for (std::uint64_t i = 0; i < n; ++i) {
        if (!tokens_.next(token_)) {
            throw bad("the cell data ends early: truncated file");
        }
        char* end = nullptr;
        errno = 0;
        const long long v = std::strtoll(token_.c_str(), &end, 10);
        if (end != token_.c_str() + token_.size() || errno == ERANGE ||
            v < std::numeric_limits<std::int32_t>::min() ||
            v > std::numeric_limits<std::int32_t>::max()) {
            throw bad("'" + printable(token_) + "' where a cell index or size belongs");
        }
        use(static_cast<std::int64_t>(v));
        if ((i & 0xFFFFU) == 0) {
            tick_(reader_.position());
        }
    }
}

/// Skips an array of `values` values: its bytes in a binary file (after the
/// end of the keyword line), its numbers in an ASCII one.
void LegacyWalk::skipArray(std::uint64_t values, const std::string& type) {
    fits(values, std::to_string(values) + " values");
    if (!binary_) {
        // vtkDataReader reads numbers with operator>>: on text glued to a
        // number ("0POLYGONS0") it loses its place in the file and later
        // dereferences a null pointer (found by fuzzing). Numbers only.
        const bool numeric = legacyBinaryBytes(type, 0).has_value();
        for (std::uint64_t k = 0; k < values; ++k) {
            if (!tokens_.next(token_)) {
                throw bad("the data ends early (" + std::to_string(k) + " of " +
                          std::to_string(values) + " values): truncated file");
            }
            if (numeric) {
                if (!parseDecimalNumber(token_)) {
                    throw bad("'" + printable(token_) + "' where a number belongs");
                }
            }
            if ((k & 0xFFFFU) == 0) {
                tick_(reader_.position());
            }
        }
        return;
    }
    if (tokens_.hasPending()) {
        throw bad("unexpected text before binary data");
    }
    tokens_.skipRestOfLine();
    if (!reader_.skip(legacyBinaryBytes(type, values).value_or(0))) {
        throw bad("the binary data ends early: truncated file");
    }
    tick_(reader_.position());
}

/// Skips a METADATA block (information keys, component names, which follow
/// arrays) up to the next keyword.
void LegacyWalk::skipMetadata() {
    while (tokens_.next(token_)) {
        const std::string& key = legacyKeyword(lower(token_));
        if (!key.empty() && key != "metadata") {
            tokens_.pushBack(token_);
            return;
        }
    }
}

/// Skips the METADATA block after an array when one follows.
void LegacyWalk::skipFollowingMetadata() {
    if (tokens_.next(token_)) {
        if (legacyKeyword(lower(token_)) == "metadata") {
            skipMetadata();
        } else {
            tokens_.pushBack(token_);
        }
    }
}

/// Reads "DATASET type"; only POLYDATA and UNSTRUCTURED_GRID pass.
LegacyDataset LegacyWalk::readDataset() {
    if (!tokens_.next(token_) || legacyKeyword(lower(token_)) != "dataset") {
        throw bad("expected DATASET after the header");
    }
    const std::string type = lower(word("the dataset type"));
    if (type.rfind("polydata", 0) == 0) {
        return LegacyDataset::PolyData;
    }
    if (type.rfind("unstructured_grid", 0) == 0) {
        return LegacyDataset::UnstructuredGrid;
    }
    std::string upper = type;
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    throw FormatError(file_, "the legacy VTK file holds a " + printable(upper) +
                                 " dataset; only POLYDATA and UNSTRUCTURED_GRID are supported");
}

LegacyDataset LegacyWalk::run() {
    const LegacyDataset dataset = readDataset();
    grid_ = dataset == LegacyDataset::UnstructuredGrid;
    while (tokens_.next(token_)) {
        tick_(reader_.position());
        const std::string& key = legacyKeyword(lower(token_));
        readSection(key);
        if (key != "metadata" && key != "field") {
            skipFollowingMetadata();
        }
    }
    if (grid_) {
        checkGridCells();
    }
    return dataset;
}

/// Reads the section that keyword `key` (the token just read) starts.
void LegacyWalk::readSection(const std::string& key) {
    const bool geometry = isLegacyGeometryKey(key);
    if (key.empty() || key == "dataset" || (geometry && inAttributes_)) {
        throw bad("unexpected '" + printable(token_) + "'");
    }
    if (key == "metadata") {
        skipMetadata();
    } else if (key == "field") {
        readField();
    } else if (key == "points") {
        readPoints();
    } else if (key == "cell_types") {
        readCellTypes();
    } else if (geometry) {
        readCells(key);
    } else if (key == "point_data" || key == "cell_data") {
        readAttributeHeader(key);
    } else if (!inAttributes_) {
        throw bad("'" + printable(token_) + "' outside POINT_DATA / CELL_DATA");
    } else {
        readAttribute(key);
    }
}

/// Reads a FIELD: its name, its arrays (each with its METADATA).
void LegacyWalk::readField() {
    (void)word("a field name");
    const std::uint64_t arrays = count("a field array count");
    fits(arrays, std::to_string(arrays) + " field arrays");
    for (std::uint64_t i = 0; i < arrays; ++i) {
        const std::string name = word("a field array name");
        if (lower(name) == "null_array") {
            continue;
        }
        const std::uint64_t components = count("a component count");
        const std::uint64_t n = count("a tuple count");
        const std::string arrayType = dataType();
        skipArray(mulSat(components, n), arrayType);
        skipFollowingMetadata();
    }
}

/// Reads POINTS: the count, the type and the coordinates.
void LegacyWalk::readPoints() {
    const std::uint64_t n = count("the point count");
    fits(mulSat(3, n), std::to_string(n) + " points");
    const std::string pointType = dataType();
    skipArray(mulSat(3, n), pointType);
    pointCount_ = n;
}

/// Reads CELL_TYPES (UNSTRUCTURED_GRID only); every type must be one we support.
void LegacyWalk::readCellTypes() {
    if (!grid_) {
        throw bad("CELL_TYPES in a POLYDATA file");
    }
    const std::uint64_t n = count("the cell type count");
    fits(n, std::to_string(n) + " cell types");
    std::vector<std::int32_t> types;
    readInts(n, [&](std::int64_t v) {
        if (detail::supportedCellPointCount(static_cast<int>(v)) < 0) {
            throw FormatError(file_, "the legacy VTK file has cells of type " + std::to_string(v) +
                                         ", which is not supported (only linear and "
                                         "common quadratic cells are)");
        }
        types.push_back(static_cast<std::int32_t>(v));
    });
    cellTypes_ = std::move(types);
}

/// Reads a cell section (`key`: CELLS in a grid, VERTICES / LINES / POLYGONS
/// / TRIANGLE_STRIPS in polydata) in the format of the file's version.
void LegacyWalk::readCells(const std::string& key) {
    if ((key == "cells") != grid_) {
        throw bad(key + " in a " + (grid_ ? "UNSTRUCTURED_GRID" : "POLYDATA") + " file");
    }
    const std::uint64_t a = count("a cell count");
    const std::uint64_t b = count("a connectivity size");
    fits(a, std::to_string(a) + " " + key);
    fits(b, std::to_string(b) + " connectivity values");
    std::uint64_t cells = 0;
    std::vector<std::int32_t> sizes;
    if (major_ >= 5) {
        // Offsets and connectivity arrays; their content is checked after reading.
        for (const char* part : {"offsets", "connectivity"}) {
            if (lower(word(part)).rfind(part, 0) != 0) {
                throw bad("expected " + std::string(part) + " in the " + key + " section");
            }
            const std::string partType = dataType();
            skipArray(std::string(part) == "offsets" ? a : b, partType);
        }
        cells = a > 0 ? a - 1 : 0;
    } else {
        cells = readCellRecords(key, a, b, sizes);
    }
    if (grid_) {
        gridCells_ = cells;
        cellSizes_ = std::move(sizes);
        cellTotal_ = cells;
    } else {
        cellTotal_ += cells;
    }
}

/// Reads the old cell format, "n id1 ... idn" records filling exactly
/// `values` values, which must make `declared` cells; returns the cell count
/// and, in a grid, appends each cell's size to `sizes`.
std::uint64_t LegacyWalk::readCellRecords(const std::string& key, std::uint64_t declared,
                                          std::uint64_t values, std::vector<std::int32_t>& sizes) {
    std::uint64_t cells = 0;
    std::int64_t left = 0;  // ids still to come in the current record
    readInts(values, [&](std::int64_t v) {
        if (left > 0) {
            --left;
            return;
        }
        if (v < 0) {
            throw bad("a cell in the " + key + " section has a negative size");
        }
        ++cells;
        left = v;
        if (grid_) {
            sizes.push_back(static_cast<std::int32_t>(v));
        }
    });
    if (left != 0) {
        throw bad("the last cell of the " + key + " section runs past its size");
    }
    if (cells != declared) {
        throw bad("the " + key + " section declares " + std::to_string(declared) +
                  " cells but holds " + std::to_string(cells));
    }
    return cells;
}

/// Reads POINT_DATA / CELL_DATA: the tuple count must match the points / cells.
void LegacyWalk::readAttributeHeader(const std::string& key) {
    tuples_ = count("a tuple count");
    const bool points = key == "point_data";
    const std::uint64_t expected = points ? pointCount_.value_or(0) : cellTotal_;
    if (tuples_ != expected) {
        throw bad(std::string(points ? "POINT_DATA" : "CELL_DATA") + " declares " +
                  std::to_string(tuples_) + " values for " + std::to_string(expected) +
                  (points ? " points" : " cells"));
    }
    inAttributes_ = true;
}

/// Reads one attribute array of the current POINT_DATA / CELL_DATA.
void LegacyWalk::readAttribute(const std::string& key) {
    if (key == "scalars") {
        readScalars();
    } else if (key == "color_scalars") {
        (void)word("an array name");
        const std::uint64_t components = count("a component count");
        skipArray(mulSat(components, tuples_), binary_ ? "unsigned_char" : "float");
    } else if (key == "lookup_table") {
        (void)word("a lookup table name");
        const std::uint64_t colours = count("a colour count");
        skipArray(mulSat(4, colours), binary_ ? "unsigned_char" : "float");
    } else if (key == "texture_coordinates") {
        (void)word("an array name");
        const std::uint64_t dimension = count("a dimension");
        if (dimension < 1 || dimension > 3) {
            throw bad("texture coordinates of dimension " + std::to_string(dimension));
        }
        const std::string arrayType = dataType();
        skipArray(mulSat(dimension, tuples_), arrayType);
    } else {
        // vectors, normals, tensors, tensors6, global_ids, pedigree_ids, edge_flags
        const std::uint64_t components = key == "tensors"                         ? 9
                                         : key == "tensors6"                      ? 6
                                         : (key == "vectors" || key == "normals") ? 3
                                                                                  : 1;
        (void)word("an array name");
        const std::string arrayType = dataType();
        skipArray(mulSat(components, tuples_), arrayType);
    }
}

/// Reads SCALARS: name, type, optional component count (1..4), LOOKUP_TABLE, values.
void LegacyWalk::readScalars() {
    (void)word("an array name");
    const std::string arrayType = dataType();
    std::uint64_t components = 1;
    std::string next = lower(word("LOOKUP_TABLE"));
    if (next != "lookup_table") {
        tokens_.pushBack(next);
        components = count("a component count");
        if (components < 1 || components > 4) {
            throw bad("scalars with " + std::to_string(components) + " components");
        }
        next = lower(word("LOOKUP_TABLE"));
    }
    if (next != "lookup_table") {
        throw bad("expected LOOKUP_TABLE after SCALARS");
    }
    (void)word("a lookup table name");
    skipArray(mulSat(components, tuples_), arrayType);
}

/// UNSTRUCTURED_GRID: cells and cell types both or neither, as many of each,
/// and (old format) every cell with the point count its type has.
void LegacyWalk::checkGridCells() const {
    if (gridCells_.has_value() != cellTypes_.has_value()) {
        throw FormatError(file_,
                          "the legacy VTK file has cells without cell types, or "
                          "cell types without cells");
    }
    if (gridCells_ && cellTypes_->size() != *gridCells_) {
        throw FormatError(file_, "the legacy VTK file has " + std::to_string(*gridCells_) +
                                     " cells but " + std::to_string(cellTypes_->size()) +
                                     " cell types");
    }
    for (std::size_t c = 0; cellTypes_ && c < cellSizes_.size() && c < cellTypes_->size(); ++c) {
        const int expected = detail::supportedCellPointCount((*cellTypes_)[c]);
        if ((expected > 0 && cellSizes_[c] != expected) || (expected == 0 && cellSizes_[c] < 1)) {
            throw FormatError(file_, "cell " + std::to_string(c) + " of type " +
                                         std::to_string((*cellTypes_)[c]) + " has " +
                                         std::to_string(cellSizes_[c]) + " points (corrupt file)");
        }
    }
}

}  // namespace

LegacyDataset preflightLegacyVtk(const fs::path& file, std::uintmax_t size, PreflightTicker& tick) {
    ByteReader reader(file);
    LegacyTokens tokens(reader);
    const LegacyHeader header = readLegacyHeader(file, reader, tokens);
    LegacyWalk walk(file, size, reader, tokens, header, tick);
    return walk.run();
}

}  // namespace vv::meshio::detail
