// SPDX-License-Identifier: GPL-3.0-or-later
// Mesh loading through VTK's readers. VTK's readers trust their input: some
// allocate whatever a header claims, some read out of bounds on bad indices,
// some print to stderr and return half-filled output. So every file first
// passes a cheap structural check here ("preflight") that refuses what would
// make a reader crash, hang or allocate absurdly; VTK's own messages are then
// captured and turned into FormatErrors, and the output is checked again
// (finite coordinates, connectivity) before any filter touches it.
#include "vv/io/MeshLoader.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkCommand.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <limits>
#include <new>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>
#include <vtksys/SystemTools.hxx>

#include "VtkConvert.h"
#include "vv/core/Error.h"

namespace vv::io {

namespace fs = std::filesystem;

namespace {

enum class Format { Stl, Obj, Ply, LegacyVtk, Vtp, Vtu };

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

std::optional<Format> formatOf(const fs::path& file) {
    const std::string ext = lower(file.extension().string());
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

/// `v` in the shortest %g form ("1e+38", "0.5", "nan").
std::string numberText(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

/// a * b, saturating at the largest value instead of overflowing.
std::uint64_t mulSat(std::uint64_t a, std::uint64_t b) {
    if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a) {
        return std::numeric_limits<std::uint64_t>::max();
    }
    return a * b;
}

std::optional<std::uint64_t> parseCount(std::string_view token) {
    if (token.empty() || token.size() > 20) {
        return std::nullopt;
    }
    std::uint64_t value = 0;
    for (const char c : token) {
        if (c < '0' || c > '9') {
            return std::nullopt;
        }
        const auto digit = static_cast<std::uint64_t>(c - '0');
        if (value > (std::numeric_limits<std::uint64_t>::max() - digit) / 10) {
            return std::numeric_limits<std::uint64_t>::max();
        }
        value = value * 10 + digit;
    }
    return value;
}

std::vector<std::string_view> splitWords(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])) != 0) {
            ++i;
        }
        const std::size_t start = i;
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])) == 0) {
            ++i;
        }
        if (i > start) {
            words.push_back(line.substr(start, i - start));
        }
    }
    return words;
}

/// `text` cut to `max` characters with bytes outside printable ASCII shown
/// as '?', for quoting file content in messages.
std::string printable(std::string_view text, std::size_t max = 40) {
    std::string out;
    for (const char c : text.substr(0, max)) {
        const auto u = static_cast<unsigned char>(c);
        out += (u >= 0x20 && u < 0x7F) ? c : '?';
    }
    if (text.size() > max) {
        out += "...";
    }
    return out;
}

/// Buffered sequential reading for the preflight checks.
class ByteReader {
  public:
    explicit ByteReader(const fs::path& file) : file_(file), fp_(std::fopen(file.c_str(), "rb")) {
        if (fp_ == nullptr) {
            const int err = errno;
            throw IoError(file,
                          "cannot open the file for reading: " + std::string(std::strerror(err)));
        }
    }
    ~ByteReader() { std::fclose(fp_); }
    ByteReader(const ByteReader&) = delete;
    ByteReader& operator=(const ByteReader&) = delete;

    /// Bytes consumed so far.
    [[nodiscard]] std::uint64_t position() const noexcept { return consumed_; }

    /// Reads exactly n bytes; false at end of file.
    bool read(void* out, std::size_t n) {
        auto* dst = static_cast<char*>(out);
        while (n > 0) {
            if (pos_ == len_ && !fill()) {
                return false;
            }
            const std::size_t take = std::min(n, len_ - pos_);
            std::memcpy(dst, buffer_.data() + pos_, take);
            pos_ += take;
            consumed_ += take;
            dst += take;
            n -= take;
        }
        return true;
    }

    /// Moves to byte `offset` from the start; false when that is not possible.
    bool seek(std::uint64_t offset) {
        if (offset > static_cast<std::uint64_t>(std::numeric_limits<long>::max()) ||
            std::fseek(fp_, static_cast<long>(offset), SEEK_SET) != 0) {
            return false;
        }
        pos_ = len_ = 0;
        consumed_ = offset;
        return true;
    }

    /// Reads up to n bytes, fewer only at the end of the file; returns how many.
    std::size_t readUpTo(char* out, std::size_t n) {
        std::size_t got = 0;
        while (got < n) {
            const std::size_t k = readSome(out + got, n - got);
            if (k == 0) {
                break;
            }
            got += k;
        }
        return got;
    }

    /// The next byte without consuming it; false at end of file.
    bool peek(char& c) {
        if (pos_ == len_ && !fill()) {
            return false;
        }
        c = buffer_[pos_];
        return true;
    }

    /// Whether the last line readLine returned ended with '\n'.
    [[nodiscard]] bool lineEnded() const noexcept { return lineEnded_; }

    /// Reads up to n bytes; returns how many (0 at end of file).
    std::size_t readSome(char* out, std::size_t n) {
        if (pos_ == len_ && !fill()) {
            return 0;
        }
        const std::size_t take = std::min(n, len_ - pos_);
        std::memcpy(out, buffer_.data() + pos_, take);
        pos_ += take;
        consumed_ += take;
        return take;
    }

    /// Skips n bytes; false at end of file.
    bool skip(std::uint64_t n) {
        while (n > 0) {
            if (pos_ == len_ && !fill()) {
                return false;
            }
            const auto take = static_cast<std::size_t>(std::min<std::uint64_t>(n, len_ - pos_));
            pos_ += take;
            consumed_ += take;
            n -= take;
        }
        return true;
    }

    /// Reads one line without its '\n' (and '\r'). Keeps at most `maxKeep`
    /// characters; `truncated` tells whether more were skipped. False at end
    /// of file when nothing was read.
    bool readLine(std::string& line, std::size_t maxKeep, bool& truncated) {
        line.clear();
        truncated = false;
        lineEnded_ = false;
        bool any = false;
        for (;;) {
            if (pos_ == len_ && !fill()) {
                break;
            }
            any = true;
            const char* begin = buffer_.data() + pos_;
            const auto* newline = static_cast<const char*>(std::memchr(begin, '\n', len_ - pos_));
            const std::size_t n =
                newline != nullptr ? static_cast<std::size_t>(newline - begin) : len_ - pos_;
            const std::size_t keep = std::min(n, maxKeep - std::min(maxKeep, line.size()));
            line.append(begin, keep);
            truncated = truncated || keep < n;
            pos_ += n;
            consumed_ += n;
            if (newline != nullptr) {
                ++pos_;
                ++consumed_;
                lineEnded_ = true;
                break;
            }
        }
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        return any;
    }

  private:
    bool fill() {
        len_ = std::fread(buffer_.data(), 1, buffer_.size(), fp_);
        pos_ = 0;
        if (len_ == 0 && std::ferror(fp_) != 0) {
            throw IoError(file_, "read error while checking the file");
        }
        return len_ > 0;
    }

    fs::path file_;
    std::FILE* fp_;
    std::array<char, 1 << 16> buffer_{};
    std::size_t pos_ = 0;
    std::size_t len_ = 0;
    std::uint64_t consumed_ = 0;
    bool lineEnded_ = false;
};

/// Reports preflight progress every few MB, as the first tenth of the load.
class PreflightTicker {
  public:
    PreflightTicker(const Progress& progress, std::uintmax_t size, std::string stage)
        : progress_(progress), size_(size), stage_(std::move(stage)) {}
    void operator()(std::uint64_t position) {
        if (position >= next_) {
            next_ = position + (4U << 20);
            // The checks take the first tenth of the load's progress.
            progress_.report(
                size_ > 0 ? 0.1 * static_cast<double>(position) / static_cast<double>(size_) : 0.0,
                stage_);
        }
    }

  private:
    const Progress& progress_;
    std::uintmax_t size_;
    std::string stage_;
    std::uint64_t next_ = 0;
};

// ---------------------------------------------------------------------------
// STL

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

// ---------------------------------------------------------------------------
// OBJ

void preflightObj(const fs::path& file, PreflightTicker& tick) {
    ByteReader reader(file);
    std::string line;
    bool truncated = false;
    std::uint64_t lineNumber = 0;
    std::int64_t counts[3] = {0, 0, 0};  // v, vt, vn
    int faceForm = -1;                   // bit 0 vertex, 1 texture, 2 normal
    constexpr std::size_t kMaxLine = 1 << 16;
    while (reader.readLine(line, kMaxLine, truncated)) {
        ++lineNumber;
        tick(reader.position());
        if (truncated) {
            throw FormatError(file, "line " + std::to_string(lineNumber) +
                                        " is longer than 64 KiB: corrupt or not an OBJ file");
        }
        // OBJ is text; vtkOBJReader misreads binary bytes (NUL in particular).
        if (std::any_of(line.begin(), line.end(), [](char c) {
                const auto u = static_cast<unsigned char>(c);
                return u < 0x20 && u != '\t' && u != '\r' && u != '\v' && u != '\f';
            })) {
            throw FormatError(
                file, "line " + std::to_string(lineNumber) + " holds binary data: not an OBJ file");
        }
        const auto words = splitWords(line);
        if (words.empty()) {
            continue;
        }
        const std::string_view key = words.front();
        if (key == "v") {
            // vtkOBJReader reads "nan" as 0 without a word: check here.
            if (words.size() < 4) {
                throw FormatError(file, "line " + std::to_string(lineNumber) +
                                            ": a vertex needs three coordinates");
            }
            for (std::size_t c = 1; c <= 3; ++c) {
                const std::string text(words[c]);
                char* end = nullptr;
                const double v = std::strtod(text.c_str(), &end);
                if (end != text.c_str() + text.size()) {
                    throw FormatError(file, "line " + std::to_string(lineNumber) + ": vertex " +
                                                std::to_string(counts[0] + 1) + " has '" +
                                                printable(text) + "' where a coordinate belongs");
                }
                if (!std::isfinite(v)) {
                    throw FormatError(file, "line " + std::to_string(lineNumber) + ": vertex " +
                                                std::to_string(counts[0] + 1) +
                                                " has a non-finite coordinate");
                }
            }
            ++counts[0];
        } else if (key == "vt") {
            ++counts[1];
        } else if (key == "vn") {
            ++counts[2];
        } else if (key == "f" || key == "l" || key == "p") {
            // Each reference is v[/vt[/vn]]; vtkOBJReader does not check them,
            // reads out of bounds on mixed forms within an element and drops
            // faces whose form differs from the others'.
            int elementForm = -1;
            for (std::size_t w = 1; w < words.size(); ++w) {
                const std::string_view ref = words[w];
                std::vector<std::string_view> parts;
                std::size_t from = 0;
                while (true) {
                    const auto slash = ref.find('/', from);
                    parts.push_back(ref.substr(from, slash == std::string_view::npos
                                                         ? std::string_view::npos
                                                         : slash - from));
                    if (slash == std::string_view::npos) {
                        break;
                    }
                    from = slash + 1;
                }
                if (parts.size() > 3 || parts[0].empty()) {
                    throw FormatError(file, "line " + std::to_string(lineNumber) + ": '" +
                                                printable(ref) + "' is not a valid reference");
                }
                int form = 0;
                for (std::size_t kind = 0; kind < parts.size(); ++kind) {
                    if (parts[kind].empty()) {
                        continue;
                    }
                    form |= 1 << kind;
                    const std::string text(parts[kind]);
                    char* end = nullptr;
                    errno = 0;
                    const long long index = std::strtoll(text.c_str(), &end, 10);
                    const char* what = kind == 0   ? "vertex"
                                       : kind == 1 ? "texture coordinate"
                                                   : "normal";
                    if (end != text.c_str() + text.size() || errno == ERANGE) {
                        throw FormatError(file, "line " + std::to_string(lineNumber) + ": '" +
                                                    printable(ref) + "' is not a valid " + what +
                                                    " reference");
                    }
                    const std::int64_t available = counts[kind];
                    if (index == 0 || index > available || index < -available) {
                        throw FormatError(file, "line " + std::to_string(lineNumber) + ": " + what +
                                                    " " + std::to_string(index) +
                                                    " does not exist (" +
                                                    std::to_string(available) + " defined so far)");
                    }
                }
                if (elementForm >= 0 && form != elementForm) {
                    throw FormatError(file, "line " + std::to_string(lineNumber) +
                                                ": the references mix forms (with and without "
                                                "texture coordinates or normals)");
                }
                elementForm = form;
            }
            if (key == "f" && elementForm >= 0) {
                if (faceForm >= 0 && elementForm != faceForm) {
                    throw FormatError(file, "line " + std::to_string(lineNumber) +
                                                ": faces with and without texture coordinates or "
                                                "normals are mixed; VTK's OBJ reader would drop "
                                                "some of them");
                }
                faceForm = elementForm;
            }
        }
    }
}

// ---------------------------------------------------------------------------
// PLY

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

/// A scalar vertex or face property vtkPLYReader ignores; we attach it ourselves.
struct PlyExtra {
    std::string element;  // "vertex" or "face"
    std::string name;
    bool integer = false;
    std::vector<float> values;
};

struct PlyData {
    std::vector<PlyExtra> extras;
    std::uint64_t vertexCount = 0;
    std::uint64_t faceCount = 0;
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

/// Parses the header, then walks all element data to be sure vtkPLYReader
/// (which trusts every count and index) can read it safely. Collects the
/// scalar vertex / face properties VTK does not read.
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
                extra.values.reserve(static_cast<std::size_t>(element.count));
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
                const auto words = splitWords(line);
                std::size_t w = 0;
                const auto number = [&](std::string_view token, const char* what) {
                    const std::string text(token);
                    char* end = nullptr;
                    const double v = std::strtod(text.c_str(), &end);
                    if (end != text.c_str() + text.size()) {
                        throw FormatError(file, "the PLY data for " + where() + " has '" +
                                                    printable(text) + "' where a " + what +
                                                    " belongs: corrupt file");
                    }
                    return v;
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

// ---------------------------------------------------------------------------
// Legacy VTK

enum class LegacyDataset { PolyData, UnstructuredGrid };

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

/// Walks a legacy VTK file the way vtkPolyDataReader / vtkUnstructuredGridReader
/// read it, without storing it, and refuses everything those readers would
/// stumble over: their error paths are not safe (some crash), they allocate
/// declared counts before reading, import old-format cells trusting every cell
/// size, and accept arrays cut short by the end of the file. So: known
/// keywords and data types only, counts that fit in the file, complete data,
/// well-formed cells, supported cell types matching the cells, attribute
/// counts matching the points and cells. Returns the dataset type.
LegacyDataset preflightLegacyVtk(const fs::path& file, std::uintmax_t size, PreflightTicker& tick) {
    ByteReader reader(file);
    std::string line;
    bool truncated = false;
    constexpr const char* kMagic = "# vtk DataFile Version";
    if (!reader.readLine(line, 256, truncated) || line.rfind(kMagic, 0) != 0) {
        throw FormatError(file, "not a legacy VTK file (no '# vtk DataFile Version' line)");
    }
    // Parsed as vtkDataReader does: anything but "%d.%d" means version 0,
    // which selects the old cell format.
    int major = 0;
    int minor = 0;
    if (std::sscanf(line.c_str() + std::strlen(kMagic), "%d.%d", &major, &minor) != 2) {
        major = 0;
    }
    if (!reader.readLine(line, 256, truncated)) {  // title
        throw FormatError(file, "the legacy VTK header is truncated");
    }
    LegacyTokens tokens(reader);
    std::string token;
    if (!tokens.next(token)) {
        throw FormatError(file, "the legacy VTK header is truncated");
    }
    const std::string encoding = lower(token);
    if (encoding.rfind("ascii", 0) != 0 && encoding.rfind("binary", 0) != 0) {
        throw FormatError(file, "the legacy VTK header says '" + printable(token) +
                                    "' where ASCII or BINARY belongs");
    }
    const bool binary = encoding.rfind("binary", 0) == 0;

    const auto bad = [&](const std::string& what) {
        return FormatError(
            file, "legacy VTK data near byte " + std::to_string(reader.position()) + ": " + what);
    };
    const auto fits = [&](std::uint64_t values, const std::string& what) {
        if (values > size) {  // every value takes at least one byte
            throw bad(what + " declared, but the file has only " + std::to_string(size) +
                      " bytes: corrupt or truncated");
        }
    };
    // A count as `stream >> n` reads it: the leading digits of the next token;
    // what follows them stays for the next read. Required: VTK's handling of
    // a missing count is not safe.
    const auto count = [&](const std::string& what) -> std::uint64_t {
        if (!tokens.next(token)) {
            throw bad("the file ends where " + what + " belongs: truncated");
        }
        const std::size_t start = token[0] == '+' ? 1 : 0;
        std::size_t end = start;
        while (end < token.size() && std::isdigit(static_cast<unsigned char>(token[end])) != 0) {
            ++end;
        }
        if (end == start) {
            throw bad("'" + printable(token) + "' where " + what + " belongs");
        }
        const std::uint64_t value = parseCount(std::string_view(token).substr(start, end - start))
                                        .value_or(std::numeric_limits<std::uint64_t>::max());
        if (end < token.size()) {
            tokens.pushBack(token.substr(end));
        }
        return value;
    };
    const auto word = [&](const std::string& what) {
        std::string w;
        if (!tokens.next(w)) {
            throw bad("the file ends where " + what + " belongs: truncated");
        }
        return w;
    };
    const auto dataType = [&] {
        std::string type = lower(word("a data type"));
        if (!isLegacyTypeName(type)) {
            throw bad("unknown data type '" + printable(type) + "'");
        }
        if (binary && !legacyBinaryBytes(type, 0)) {
            throw bad("binary arrays of type '" + type + "' are not supported");
        }
        return type;
    };
    // Reads `n` ints as vtkDataReader reads cell data: ASCII numbers or
    // big-endian int32 after the end of the keyword line.
    const auto readInts = [&](std::uint64_t n, const auto& use) {
        if (binary) {
            if (tokens.hasPending()) {
                throw bad("unexpected text before binary cell data");
            }
            tokens.skipRestOfLine();
            for (std::uint64_t i = 0; i < n; ++i) {
                unsigned char b[4];
                if (!reader.read(b, 4)) {
                    throw bad("the binary cell data ends early: truncated file");
                }
                const std::uint32_t u = (std::uint32_t{b[0]} << 24U) |
                                        (std::uint32_t{b[1]} << 16U) | (std::uint32_t{b[2]} << 8U) |
                                        std::uint32_t{b[3]};
                use(static_cast<std::int64_t>(static_cast<std::int32_t>(u)));
                if ((i & 0xFFFFU) == 0) {
                    tick(reader.position());
                }
            }
            return;
        }
        for (std::uint64_t i = 0; i < n; ++i) {
            if (!tokens.next(token)) {
                throw bad("the cell data ends early: truncated file");
            }
            char* end = nullptr;
            errno = 0;
            const long long v = std::strtoll(token.c_str(), &end, 10);
            if (end != token.c_str() + token.size() || errno == ERANGE ||
                v < std::numeric_limits<std::int32_t>::min() ||
                v > std::numeric_limits<std::int32_t>::max()) {
                throw bad("'" + printable(token) + "' where a cell index or size belongs");
            }
            use(static_cast<std::int64_t>(v));
            if ((i & 0xFFFFU) == 0) {
                tick(reader.position());
            }
        }
    };
    // Skips an array of `values` values: its bytes in a binary file (after the
    // end of the keyword line), its numbers in an ASCII one.
    const auto skipArray = [&](std::uint64_t values, const std::string& type) {
        fits(values, std::to_string(values) + " values");
        if (!binary) {
            for (std::uint64_t k = 0; k < values; ++k) {
                if (!tokens.next(token)) {
                    throw bad("the data ends early (" + std::to_string(k) + " of " +
                              std::to_string(values) + " values): truncated file");
                }
                if ((k & 0xFFFFU) == 0) {
                    tick(reader.position());
                }
            }
            return;
        }
        if (tokens.hasPending()) {
            throw bad("unexpected text before binary data");
        }
        tokens.skipRestOfLine();
        if (!reader.skip(legacyBinaryBytes(type, values).value_or(0))) {
            throw bad("the binary data ends early: truncated file");
        }
        tick(reader.position());
    };
    // METADATA blocks (information keys, component names) follow arrays;
    // skipped up to the next keyword.
    const auto skipMetadata = [&] {
        while (tokens.next(token)) {
            const std::string& key = legacyKeyword(lower(token));
            if (!key.empty() && key != "metadata") {
                tokens.pushBack(token);
                return;
            }
        }
    };

    if (!tokens.next(token) || legacyKeyword(lower(token)) != "dataset") {
        throw bad("expected DATASET after the header");
    }
    const std::string type = lower(word("the dataset type"));
    LegacyDataset dataset = LegacyDataset::PolyData;
    if (type.rfind("polydata", 0) == 0) {
        dataset = LegacyDataset::PolyData;
    } else if (type.rfind("unstructured_grid", 0) == 0) {
        dataset = LegacyDataset::UnstructuredGrid;
    } else {
        std::string upper = type;
        std::transform(upper.begin(), upper.end(), upper.begin(),
                       [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
        throw FormatError(file, "the legacy VTK file holds a " + printable(upper) +
                                    " dataset; only POLYDATA and UNSTRUCTURED_GRID are supported");
    }
    const bool grid = dataset == LegacyDataset::UnstructuredGrid;

    std::optional<std::uint64_t> pointCount;
    std::uint64_t cellTotal = 0;             // all cells (POLYDATA: of every section)
    std::optional<std::uint64_t> gridCells;  // UNSTRUCTURED_GRID: cells of CELLS
    std::vector<std::int32_t> cellSizes;     // their sizes (files before version 5)
    std::optional<std::vector<std::int32_t>> cellTypes;
    std::uint64_t tuples = 0;  // of the current POINT_DATA / CELL_DATA
    bool inAttributes = false;

    const auto readField = [&] {
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
            if (tokens.next(token)) {
                if (legacyKeyword(lower(token)) == "metadata") {
                    skipMetadata();
                } else {
                    tokens.pushBack(token);
                }
            }
        }
    };

    while (tokens.next(token)) {
        tick(reader.position());
        const std::string& key = legacyKeyword(lower(token));
        const bool geometry = key == "points" || key == "vertices" || key == "lines" ||
                              key == "polygons" || key == "triangle_strips" || key == "cells" ||
                              key == "cell_types";
        if (key.empty() || key == "dataset" || (geometry && inAttributes)) {
            throw bad("unexpected '" + printable(token) + "'");
        }
        if (key == "metadata") {
            skipMetadata();
        } else if (key == "field") {
            readField();
        } else if (key == "points") {
            const std::uint64_t n = count("the point count");
            fits(mulSat(3, n), std::to_string(n) + " points");
            const std::string pointType = dataType();
            skipArray(mulSat(3, n), pointType);
            pointCount = n;
        } else if (key == "cell_types") {
            if (!grid) {
                throw bad("CELL_TYPES in a POLYDATA file");
            }
            const std::uint64_t n = count("the cell type count");
            fits(n, std::to_string(n) + " cell types");
            std::vector<std::int32_t> types;
            readInts(n, [&](std::int64_t v) {
                if (detail::supportedCellPointCount(static_cast<int>(v)) < 0) {
                    throw FormatError(file, "the legacy VTK file has cells of type " +
                                                std::to_string(v) +
                                                ", which is not supported (only linear and "
                                                "common quadratic cells are)");
                }
                types.push_back(static_cast<std::int32_t>(v));
            });
            cellTypes = std::move(types);
        } else if (geometry) {
            if ((key == "cells") != grid) {
                throw bad(key + " in a " + (grid ? "UNSTRUCTURED_GRID" : "POLYDATA") + " file");
            }
            const std::uint64_t a = count("a cell count");
            const std::uint64_t b = count("a connectivity size");
            fits(a, std::to_string(a) + " " + key);
            fits(b, std::to_string(b) + " connectivity values");
            std::uint64_t cells = 0;
            std::vector<std::int32_t> sizes;
            if (major >= 5) {
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
                // "n id1 ... idn" records filling exactly b values.
                std::int64_t left = 0;  // ids still to come in the current record
                readInts(b, [&](std::int64_t v) {
                    if (left > 0) {
                        --left;
                        return;
                    }
                    if (v < 0) {
                        throw bad("a cell in the " + key + " section has a negative size");
                    }
                    ++cells;
                    left = v;
                    if (grid) {
                        sizes.push_back(static_cast<std::int32_t>(v));
                    }
                });
                if (left != 0) {
                    throw bad("the last cell of the " + key + " section runs past its size");
                }
                if (cells != a) {
                    throw bad("the " + key + " section declares " + std::to_string(a) +
                              " cells but holds " + std::to_string(cells));
                }
            }
            if (grid) {
                gridCells = cells;
                cellSizes = std::move(sizes);
                cellTotal = cells;
            } else {
                cellTotal += cells;
            }
        } else if (key == "point_data" || key == "cell_data") {
            tuples = count("a tuple count");
            const bool points = key == "point_data";
            const std::uint64_t expected = points ? pointCount.value_or(0) : cellTotal;
            if (tuples != expected) {
                throw bad(std::string(points ? "POINT_DATA" : "CELL_DATA") + " declares " +
                          std::to_string(tuples) + " values for " + std::to_string(expected) +
                          (points ? " points" : " cells"));
            }
            inAttributes = true;
        } else if (!inAttributes) {
            throw bad("'" + printable(token) + "' outside POINT_DATA / CELL_DATA");
        } else if (key == "scalars") {
            (void)word("an array name");
            const std::string arrayType = dataType();
            std::uint64_t components = 1;
            std::string next = lower(word("LOOKUP_TABLE"));
            if (next != "lookup_table") {
                tokens.pushBack(next);
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
            skipArray(mulSat(components, tuples), arrayType);
        } else if (key == "color_scalars") {
            (void)word("an array name");
            const std::uint64_t components = count("a component count");
            skipArray(mulSat(components, tuples), binary ? "unsigned_char" : "float");
        } else if (key == "lookup_table") {
            (void)word("a lookup table name");
            const std::uint64_t colours = count("a colour count");
            skipArray(mulSat(4, colours), binary ? "unsigned_char" : "float");
        } else if (key == "texture_coordinates") {
            (void)word("an array name");
            const std::uint64_t dimension = count("a dimension");
            if (dimension < 1 || dimension > 3) {
                throw bad("texture coordinates of dimension " + std::to_string(dimension));
            }
            const std::string arrayType = dataType();
            skipArray(mulSat(dimension, tuples), arrayType);
        } else {
            // vectors, normals, tensors, tensors6, global_ids, pedigree_ids, edge_flags
            const std::uint64_t components = key == "tensors"                         ? 9
                                             : key == "tensors6"                      ? 6
                                             : (key == "vectors" || key == "normals") ? 3
                                                                                      : 1;
            (void)word("an array name");
            const std::string arrayType = dataType();
            skipArray(mulSat(components, tuples), arrayType);
        }
        if (key != "metadata" && key != "field" && tokens.next(token)) {
            if (legacyKeyword(lower(token)) == "metadata") {
                skipMetadata();
            } else {
                tokens.pushBack(token);
            }
        }
    }
    if (grid) {
        if (gridCells.has_value() != cellTypes.has_value()) {
            throw FormatError(file,
                              "the legacy VTK file has cells without cell types, or "
                              "cell types without cells");
        }
        if (gridCells && cellTypes->size() != *gridCells) {
            throw FormatError(file, "the legacy VTK file has " + std::to_string(*gridCells) +
                                        " cells but " + std::to_string(cellTypes->size()) +
                                        " cell types");
        }
        for (std::size_t c = 0; cellTypes && c < cellSizes.size() && c < cellTypes->size(); ++c) {
            const int expected = detail::supportedCellPointCount((*cellTypes)[c]);
            if ((expected > 0 && cellSizes[c] != expected) || (expected == 0 && cellSizes[c] < 1)) {
                throw FormatError(file, "cell " + std::to_string(c) + " of type " +
                                            std::to_string((*cellTypes)[c]) + " has " +
                                            std::to_string(cellSizes[c]) +
                                            " points (corrupt file)");
            }
        }
    }
    return dataset;
}

// ---------------------------------------------------------------------------
// VTK XML

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

/// Scans the XML structure of a .vtp / .vtu file: the root must be a VTKFile
/// of the expected type; the counts the pieces and arrays declare, and the
/// headers of binary arrays (inline or appended), must fit in the file given
/// its compression, since vtkXMLReader allocates them before reading data.
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
    const auto refill = [&] {
        const std::size_t got = reader.readSome(chunk.data(), chunk.size());
        eof = got == 0;
        window.append(chunk.data(), got);
        tick(reader.position());
    };
    while (true) {
        if (inlineBinaryNext) {
            // Header of inline binary data: base64 text right after the tag.
            const std::uint64_t at = reader.position() - window.size();
            checkBinaryHeader([&](std::size_t n) { return binaryBytesAt(data, at, true, n); },
                              layout, file);
            inlineBinaryNext = false;
        }
        // Find the next tag start in the window; refill as needed.
        const auto lt = window.find('<');
        if (lt == std::string::npos) {
            window.clear();
        } else if (lt > 0) {
            window.erase(0, lt);
        }
        const auto gt = window.find('>');
        if (window.empty() || gt == std::string::npos) {
            if (window.size() > (1U << 20)) {
                throw FormatError(file, "an XML tag is longer than 1 MiB: corrupt file");
            }
            if (eof) {
                break;
            }
            refill();
            continue;
        }
        const std::string tag = window.substr(0, gt + 1);
        window.erase(0, gt + 1);
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

// ---------------------------------------------------------------------------
// Running a reader

struct ProgressRelay {
    const Progress* progress = nullptr;
    vtkAlgorithm* algorithm = nullptr;
    double begin = 0.0;
    double end = 1.0;
    std::string stage;
    bool cancelled = false;
    std::exception_ptr error;
};

void onProgress(vtkObject* /*caller*/, unsigned long /*event*/, void* clientData, void* callData) {
    auto* relay = static_cast<ProgressRelay*>(clientData);
    if (relay == nullptr || relay->cancelled || relay->error || callData == nullptr) {
        return;
    }
    const double fraction = *static_cast<const double*>(callData);
    try {
        relay->progress->report(relay->begin + (relay->end - relay->begin) * fraction,
                                relay->stage);
    } catch (const CancelledError&) {
        relay->cancelled = true;
        relay->algorithm->AbortExecuteOn();
    } catch (...) {
        // Exceptions must not cross VTK's C-style pipeline; rethrown after Update().
        relay->error = std::current_exception();
        relay->algorithm->AbortExecuteOn();
    }
}

/// Runs `algorithm` (a reader or filter) with progress, cancellation and VTK
/// messages captured; throws FormatError naming `file` when it reports an error.
void runAlgorithm(vtkAlgorithm* algorithm, const fs::path& file, const std::string& what,
                  const Progress& progress, double begin, double end, const std::string& stage) {
    progress.throwIfCancelled();
    detail::VtkMessageCapture capture;
    capture.observe(algorithm);
    ProgressRelay relay;
    relay.progress = &progress;
    relay.algorithm = algorithm;
    relay.begin = begin;
    relay.end = end;
    relay.stage = stage;
    auto command = vtkSmartPointer<vtkCallbackCommand>::New();
    command->SetCallback(&onProgress);
    command->SetClientData(&relay);
    struct ObserverGuard {
        vtkAlgorithm* algorithm;
        unsigned long tag;
        ~ObserverGuard() { algorithm->RemoveObserver(tag); }
    } guard{algorithm, algorithm->AddObserver(vtkCommand::ProgressEvent, command)};
    int ok = 0;
    try {
        ok = algorithm->GetExecutive()->Update();
    } catch (const std::bad_alloc&) {
        throw FormatError(file, "not enough memory to read the " + what +
                                    " content (corrupt counts in the file?)");
    } catch (const std::exception& e) {
        throw FormatError(
            file, "cannot read the " + what + " content (corrupt file?): " + std::string(e.what()));
    }
    if (relay.error) {
        std::rethrow_exception(relay.error);
    }
    if (relay.cancelled || progress.cancelled()) {
        throw CancelledError();
    }
    if (ok == 0 || capture.hasErrors()) {
        std::string message = capture.summary();
        if (message.empty()) {
            message = "the reader failed without saying why";
        }
        throw FormatError(
            file, "cannot read the " + what + " content (corrupt or truncated?): " + message);
    }
}

vtkSmartPointer<vtkPolyData> polyDataOutput(vtkAlgorithm* algorithm, const fs::path& file,
                                            const std::string& what) {
    vtkSmartPointer<vtkPolyData> poly =
        vtkPolyData::SafeDownCast(algorithm->GetOutputDataObject(0));
    if (poly == nullptr) {
        throw FormatError(file, "the " + what + " reader produced no polydata");
    }
    return poly;
}

/// Extracts the outer surface of a checked unstructured grid.
vtkSmartPointer<vtkPolyData> surfaceOf(vtkUnstructuredGrid* grid, const fs::path& file,
                                       const Progress& progress) {
    detail::checkUnstructuredGrid(grid, file);
    auto surface = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
    surface->SetInputData(grid);
    runAlgorithm(surface, file, "unstructured grid surface", progress, 0.7, 0.8,
                 "Extracting the surface");
    return polyDataOutput(surface, file, "surface");
}

vtkSmartPointer<vtkPolyData> readStl(const fs::path& file, const Progress& progress,
                                     const std::string& stage) {
    auto reader = vtkSmartPointer<vtkSTLReader>::New();
    reader->SetFileName(file.c_str());
    reader->MergingOff();  // merged below, after the coordinates are known finite
    reader->ScalarTagsOff();
    runAlgorithm(reader, file, "STL", progress, 0.1, 0.7, stage);
    auto raw = polyDataOutput(reader, file, "STL");
    if (raw->GetNumberOfPoints() == 0) {
        throw FormatError(file, "the STL file holds no triangles (empty mesh)");
    }
    for (vtkIdType i = 0; i < raw->GetNumberOfPoints(); ++i) {
        double p[3];
        raw->GetPoint(i, p);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
            throw FormatError(file,
                              "triangle " + std::to_string(i / 3) + " has a non-finite coordinate");
        }
    }
    // STL stores every triangle's corners separately: merge identical points.
    auto clean = vtkSmartPointer<vtkCleanPolyData>::New();
    clean->SetInputData(raw);
    clean->PointMergingOn();
    clean->SetTolerance(0.0);
    runAlgorithm(clean, file, "STL", progress, 0.7, 0.8, "Merging points");
    return polyDataOutput(clean, file, "STL");
}

vtkSmartPointer<vtkPolyData> readObj(const fs::path& file, const Progress& progress,
                                     const std::string& stage) {
    auto reader = vtkSmartPointer<vtkOBJReader>::New();
    reader->SetFileName(file.c_str());
    runAlgorithm(reader, file, "OBJ", progress, 0.1, 0.8, stage);
    return polyDataOutput(reader, file, "OBJ");
}

template <typename ArrayType>
vtkSmartPointer<vtkDataArray> plyExtraArray(const PlyExtra& extra) {
    auto array = vtkSmartPointer<ArrayType>::New();
    array->SetName(extra.name.c_str());
    array->SetNumberOfComponents(1);
    array->SetNumberOfTuples(static_cast<vtkIdType>(extra.values.size()));
    for (std::size_t i = 0; i < extra.values.size(); ++i) {
        array->SetValue(static_cast<vtkIdType>(i),
                        static_cast<typename ArrayType::ValueType>(extra.values[i]));
    }
    return array;
}

vtkSmartPointer<vtkPolyData> readPly(const fs::path& file, const PlyData& ply,
                                     const Progress& progress, const std::string& stage) {
    auto reader = vtkSmartPointer<vtkPLYReader>::New();
    reader->SetFileName(file.c_str());
    runAlgorithm(reader, file, "PLY", progress, 0.1, 0.8, stage);
    auto poly = polyDataOutput(reader, file, "PLY");
    if (static_cast<std::uint64_t>(poly->GetNumberOfPoints()) != ply.vertexCount) {
        throw FormatError(file,
                          "the PLY reader returned " + std::to_string(poly->GetNumberOfPoints()) +
                              " points but the file declares " + std::to_string(ply.vertexCount));
    }
    for (const auto& extra : ply.extras) {
        const bool onPoints = extra.element == "vertex";
        const bool fits =
            onPoints ? extra.values.size() == ply.vertexCount
                     : extra.values.size() == ply.faceCount &&
                           static_cast<std::uint64_t>(poly->GetNumberOfCells()) == ply.faceCount;
        if (!fits) {
            continue;  // faces VTK dropped: the per-face values no longer line up
        }
        // Integer properties with NaN-free values become int arrays (NaN cannot be an int).
        const bool asInt =
            extra.integer && std::all_of(extra.values.begin(), extra.values.end(), [](float v) {
                return std::isfinite(v) && std::abs(v) < 2.0e9F;
            });
        auto array =
            asInt ? plyExtraArray<vtkIntArray>(extra) : plyExtraArray<vtkFloatArray>(extra);
        if (onPoints) {
            poly->GetPointData()->AddArray(array);
        } else {
            poly->GetCellData()->AddArray(array);
        }
    }
    return poly;
}

vtkSmartPointer<vtkPolyData> readLegacy(const fs::path& file, LegacyDataset dataset,
                                        const Progress& progress, const std::string& stage) {
    const auto configure = [](auto* reader) {
        reader->ReadAllScalarsOn();
        reader->ReadAllVectorsOn();
        reader->ReadAllNormalsOn();
        reader->ReadAllTensorsOn();
        reader->ReadAllColorScalarsOn();
        reader->ReadAllTCoordsOn();
        reader->ReadAllFieldsOn();
    };
    if (dataset == LegacyDataset::PolyData) {
        auto reader = vtkSmartPointer<vtkPolyDataReader>::New();
        reader->SetFileName(file.c_str());
        configure(reader.Get());
        runAlgorithm(reader, file, "legacy VTK", progress, 0.1, 0.8, stage);
        return polyDataOutput(reader, file, "legacy VTK");
    }
    auto reader = vtkSmartPointer<vtkUnstructuredGridReader>::New();
    reader->SetFileName(file.c_str());
    configure(reader.Get());
    runAlgorithm(reader, file, "legacy VTK", progress, 0.1, 0.7, stage);
    auto* grid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutputDataObject(0));
    if (grid == nullptr) {
        throw FormatError(file, "the legacy VTK reader produced no unstructured grid");
    }
    return surfaceOf(grid, file, progress);
}

vtkSmartPointer<vtkPolyData> readVtp(const fs::path& file, const Progress& progress,
                                     const std::string& stage) {
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(file.c_str());
    runAlgorithm(reader, file, "VTP", progress, 0.1, 0.8, stage);
    return polyDataOutput(reader, file, "VTP");
}

vtkSmartPointer<vtkPolyData> readVtu(const fs::path& file, const Progress& progress,
                                     const std::string& stage) {
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    reader->SetFileName(file.c_str());
    runAlgorithm(reader, file, "VTU", progress, 0.1, 0.7, stage);
    auto* grid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutputDataObject(0));
    if (grid == nullptr) {
        throw FormatError(file, "the VTU reader produced no unstructured grid");
    }
    return surfaceOf(grid, file, progress);
}

// ---------------------------------------------------------------------------
// Mesh post-processing

/// vtkOBJReader always adds a float "GroupIds" cell array: drop it when the
/// file has a single group, else mark it as integer labels.
void tidyObjGroups(Mesh& mesh) {
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
void addPointArraysFromCells(Mesh& mesh, const Progress& progress) {
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
    std::vector<DataArray> converted;
    for (const auto& cell : mesh.cellArrays) {
        progress.throwIfCancelled();
        if (cell.components < 1 || cell.tupleCount() != triangles) {
            continue;
        }
        const auto comps = static_cast<std::size_t>(cell.components);
        DataArray out;
        out.name = detail::pointNameForCellArray(cell.name, taken);
        taken.push_back(out.name);
        out.unit = cell.unit;
        out.components = cell.components;
        out.integer = cell.integer;
        out.fromCells = true;
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
}

void scaleMesh(Mesh& mesh, double scale, const fs::path& file) {
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

Mesh loadMesh(const fs::path& file, const MeshLoadOptions& options, const Progress& progress) {
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
    PreflightTicker tick(progress, size, "Checking " + name);
    tick(0);
    const std::string stage = "Reading " + name;

    vtkSmartPointer<vtkPolyData> poly;
    switch (*format) {
        case Format::Stl:
            preflightStl(file, size);
            poly = readStl(file, progress, stage);
            break;
        case Format::Obj:
            preflightObj(file, tick);
            poly = readObj(file, progress, stage);
            break;
        case Format::Ply: {
            const PlyData ply = preflightPly(file, size, tick);
            poly = readPly(file, ply, progress, stage);
            break;
        }
        case Format::LegacyVtk: {
            const LegacyDataset dataset = preflightLegacyVtk(file, size, tick);
            poly = readLegacy(file, dataset, progress, stage);
            break;
        }
        case Format::Vtp:
            preflightXml(file, size, *format, tick);
            poly = readVtp(file, progress, stage);
            break;
        case Format::Vtu:
            preflightXml(file, size, *format, tick);
            poly = readVtu(file, progress, stage);
            break;
    }
    progress.report(0.8, "Converting " + name);
    Mesh mesh = detail::meshFromPolyData(poly, file);
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

Scene loadScene(const std::vector<fs::path>& files, const MeshLoadOptions& options,
                const Progress& progress) {
    Scene scene;
    scene.meshes.reserve(files.size());
    const double n = static_cast<double>(files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
        const double begin = static_cast<double>(i) / n;
        const double end = static_cast<double>(i + 1) / n;
        scene.meshes.push_back(loadMesh(files[i], options, progress.sub(begin, end)));
    }
    return scene;
}

}  // namespace vv::io
