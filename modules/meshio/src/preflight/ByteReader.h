// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::meshio: buffered sequential (and seekable) reading of a file for
// the preflight checks (MeshPreflight.h).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

namespace vv::meshio::detail {

/// Buffered sequential reading for the preflight checks. Every member that
/// reads throws IoError naming the file on a read error.
class ByteReader {
  public:
    /// Opens `file` for reading; throws IoError (with the system's reason) when it cannot.
    explicit ByteReader(const std::filesystem::path& file);
    /// Closes the file.
    ~ByteReader();
    /// Not copyable: it owns the open file.
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
    bool seek(std::uint64_t offset);

    /// Reads up to n bytes, fewer only at the end of the file; returns how many.
    std::size_t readUpTo(char* out, std::size_t n);

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
    bool readLine(std::string& line, std::size_t maxKeep, bool& truncated);

  private:
    /// Refills the buffer; false at end of file, throws IoError on a read error.
    bool fill();

    std::filesystem::path file_;
    std::FILE* fp_;
    std::array<char, 1 << 16> buffer_{};
    std::size_t pos_ = 0;
    std::size_t len_ = 0;
    std::uint64_t consumed_ = 0;
    bool lineEnded_ = false;
};

}  // namespace vv::meshio::detail
