// SPDX-License-Identifier: GPL-3.0-or-later
// preflightObj (MeshPreflight.h): the OBJ line-by-line check.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
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

void preflightObj(const fs::path& file, PreflightTicker& tick) {
    ByteReader reader(file);
    std::string line;
    bool truncated = false;
    std::uint64_t lineNumber = 0;
    std::int64_t counts[3] = {0, 0, 0};  // v, vt, vn
    int faceForm = -1;                   // bit 0 vertex, 1 texture, 2 normal
    bool haveFaces = false;
    bool haveLinesOrPoints = false;
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
                const std::string_view text = words[c];
                const std::optional<double> v = parseDecimalNumber(text);
                if (!v) {
                    throw FormatError(file, "line " + std::to_string(lineNumber) + ": vertex " +
                                                std::to_string(counts[0] + 1) + " has '" +
                                                printable(text) + "' where a coordinate belongs");
                }
                if (!std::isfinite(*v)) {
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
                // A trailing '/' ("2/", "2//", "2/1/") makes vtkOBJReader read
                // texture coordinates or normals that do not exist (a crash).
                if (parts.size() > 3 || parts[0].empty() || parts.back().empty()) {
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
            // vtkOBJReader gives its cell arrays (GroupIds) one value per face
            // only, so with line or point elements as well, filters that copy
            // cell data read past their end (found by fuzzing).
            (key == "f" ? haveFaces : haveLinesOrPoints) = true;
            if (haveFaces && haveLinesOrPoints) {
                throw FormatError(file, "line " + std::to_string(lineNumber) +
                                            ": faces mixed with line ('l') or point ('p') "
                                            "elements are not supported");
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

}  // namespace vv::meshio::detail
