// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/vss/Pfm.h"

#include <bit>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"

namespace vv::vss {

namespace {

bool isSpace(int c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/// Reads the next whitespace-separated header token (at most 64 characters).
std::string nextToken(std::istream& in, const std::filesystem::path& file, const char* what) {
    int c = in.get();
    while (c != EOF && isSpace(c)) {
        c = in.get();
    }
    std::string token;
    while (c != EOF && !isSpace(c)) {
        token.push_back(static_cast<char>(c));
        if (token.size() > 64) {
            throw FormatError(file, std::string("PFM header: the ") + what + " is not a number");
        }
        c = in.get();
    }
    if (token.empty()) {
        throw FormatError(file, std::string("PFM header ends before the ") + what);
    }
    if (c == EOF) {
        throw FormatError(file, std::string("PFM file ends after the ") + what + " (no data)");
    }
    return token;  // the single whitespace after it is consumed
}

int parseSize(const std::string& token, const std::filesystem::path& file, const char* what) {
    if (token.front() == '-') {
        throw FormatError(file, std::string("PFM header: negative ") + what + " '" + token + "'");
    }
    long long value = 0;
    const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ptr != token.data() + token.size() ||
        (ec != std::errc() && ec != std::errc::result_out_of_range)) {
        throw FormatError(file, std::string("PFM header: the ") + what + " '" + token +
                                    "' is not a whole number");
    }
    if (ec == std::errc::result_out_of_range || value > kPfmMaxSide) {
        throw FormatError(file, std::string("PFM header: the ") + what + " " + token +
                                    " is larger than " + std::to_string(kPfmMaxSide));
    }
    if (value == 0) {
        throw FormatError(file, std::string("PFM header: the ") + what + " is 0");
    }
    return static_cast<int>(value);
}

float byteSwapped(float v) {
    const auto u = std::bit_cast<std::uint32_t>(v);
    return std::bit_cast<float>((u >> 24) | ((u >> 8) & 0xff00U) | ((u << 8) & 0xff0000U) |
                                (u << 24));
}

}  // namespace

Image<float> readPfm(const std::filesystem::path& file) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) {
        throw IoError(file, "cannot read: it is a folder");
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw IoError(file, "cannot open for reading: " + std::string(std::strerror(errno)));
    }
    char magic[2] = {0, 0};
    in.read(magic, 2);
    if (in.gcount() != 2 || magic[0] != 'P' || (magic[1] != 'f' && magic[1] != 'F')) {
        throw FormatError(file, "not a PFM file (it does not start with 'Pf')");
    }
    if (magic[1] == 'F') {
        throw FormatError(file,
                          "colour PFM ('PF') is not supported: need a grayscale 'Pf' depth image");
    }
    const int next = in.peek();
    if (next == EOF || !isSpace(next)) {
        throw FormatError(file, "not a PFM file (no whitespace after 'Pf')");
    }
    const int width = parseSize(nextToken(in, file, "width"), file, "width");
    const int height = parseSize(nextToken(in, file, "height"), file, "height");
    if (static_cast<long long>(width) * height > kPfmMaxPixels) {
        throw FormatError(file, "PFM header: " + std::to_string(width) + "x" +
                                    std::to_string(height) + " is more than " +
                                    std::to_string(kPfmMaxPixels) + " pixels");
    }
    const std::string scaleText = nextToken(in, file, "scale");
    double scale = 0.0;
    {
        const auto [ptr, sec] =
            std::from_chars(scaleText.data(), scaleText.data() + scaleText.size(), scale);
        if (sec != std::errc() || ptr != scaleText.data() + scaleText.size() ||
            !std::isfinite(scale) || scale == 0.0) {
            throw FormatError(
                file, "PFM header: the scale '" + scaleText + "' is not a finite non-zero number");
        }
    }
    const bool littleEndian = scale < 0.0;
    const std::streamoff headerBytes = in.tellg();
    const auto dataBytes =
        static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height) * sizeof(float);
    // Check the size before allocating, when the file system knows it.
    const std::uintmax_t fileBytes = std::filesystem::file_size(file, ec);
    if (!ec && headerBytes >= 0) {
        const auto have = fileBytes - static_cast<std::uintmax_t>(headerBytes);
        if (have < dataBytes) {
            throw FormatError(file, "PFM data truncated: " + std::to_string(width) + "x" +
                                        std::to_string(height) + " needs " +
                                        std::to_string(dataBytes) + " bytes, the file has " +
                                        std::to_string(have));
        }
        if (have > dataBytes) {
            throw FormatError(file, "PFM file has " + std::to_string(have - dataBytes) +
                                        " bytes after the pixel data of a " +
                                        std::to_string(width) + "x" + std::to_string(height) +
                                        " image");
        }
    }
    Image<float> image(width, height);
    const bool swap = littleEndian != (std::endian::native == std::endian::little);
    for (int y = height - 1; y >= 0; --y) {  // the file's first row is the bottom one
        float* row = image.row(y);
        in.read(reinterpret_cast<char*>(row), static_cast<std::streamsize>(width * sizeof(float)));
        if (in.gcount() != static_cast<std::streamsize>(width * sizeof(float))) {
            if (in.bad()) {
                throw IoError(file, "read error");
            }
            throw FormatError(file, "PFM data truncated at row " + std::to_string(height - 1 - y) +
                                        " of " + std::to_string(height));
        }
        if (swap) {
            for (int x = 0; x < width; ++x) {
                row[x] = byteSwapped(row[x]);
            }
        }
    }
    if (in.peek() != EOF) {
        throw FormatError(file, "PFM file has bytes after the pixel data");
    }
    return image;
}

void writePfm(const std::filesystem::path& file, ImageView<const float> image) {
    if (image.empty()) {
        throw InvalidArgumentError(file, "cannot write an empty image as PFM");
    }
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) {
            throw IoError(file, "cannot open for writing: " + std::string(std::strerror(errno)));
        }
        out << "Pf\n" << image.width() << ' ' << image.height() << "\n-1.0\n";
        std::vector<float> row(static_cast<std::size_t>(image.width()));
        const bool swap = std::endian::native != std::endian::little;
        for (int y = image.height() - 1; y >= 0; --y) {
            const float* src = image.row(y);
            for (int x = 0; x < image.width(); ++x) {
                row[static_cast<std::size_t>(x)] = swap ? byteSwapped(src[x]) : src[x];
            }
            out.write(reinterpret_cast<const char*>(row.data()),
                      static_cast<std::streamsize>(row.size() * sizeof(float)));
        }
        out.close();
        if (!out) {
            throw IoError(file, "cannot write (disk full?)");
        }
    });
}

}  // namespace vv::vss
