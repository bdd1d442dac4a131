// SPDX-License-Identifier: GPL-3.0-or-later
#include "ByteReader.h"

#include <cerrno>
#include <limits>

#include "vv/core/Error.h"

namespace vv::meshio::detail {

namespace fs = std::filesystem;

ByteReader::ByteReader(const fs::path& file) : file_(file), fp_(std::fopen(file.c_str(), "rb")) {
    if (fp_ == nullptr) {
        const int err = errno;
        throw IoError(file, "cannot open the file for reading: " + std::string(std::strerror(err)));
    }
}

ByteReader::~ByteReader() {
    std::fclose(fp_);
}

bool ByteReader::seek(std::uint64_t offset) {
    if (offset > static_cast<std::uint64_t>(std::numeric_limits<long>::max()) ||
        std::fseek(fp_, static_cast<long>(offset), SEEK_SET) != 0) {
        return false;
    }
    pos_ = len_ = 0;
    consumed_ = offset;
    return true;
}

std::size_t ByteReader::readUpTo(char* out, std::size_t n) {
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

bool ByteReader::readLine(std::string& line, std::size_t maxKeep, bool& truncated) {
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

bool ByteReader::fill() {
    len_ = std::fread(buffer_.data(), 1, buffer_.size(), fp_);
    pos_ = 0;
    if (len_ == 0 && std::ferror(fp_) != 0) {
        throw IoError(file_, "read error while checking the file");
    }
    return len_ > 0;
}

}  // namespace vv::meshio::detail
