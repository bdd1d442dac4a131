// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A socket descriptor with one owner (closed when the owner goes), and the
// peer's IPv4 address of a connected socket.

#include <string>
#include <utility>

namespace vv::pacs::detail {

class OwnedSocket {
  public:
    OwnedSocket() = default;
    explicit OwnedSocket(int fd) noexcept : fd_(fd) {}
    OwnedSocket(OwnedSocket&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
    OwnedSocket& operator=(OwnedSocket&& other) noexcept {
        if (this != &other) {
            close();
            fd_ = std::exchange(other.fd_, -1);
        }
        return *this;
    }
    OwnedSocket(const OwnedSocket&) = delete;
    OwnedSocket& operator=(const OwnedSocket&) = delete;
    ~OwnedSocket() { close(); }

    [[nodiscard]] int get() const noexcept { return fd_; }
    [[nodiscard]] bool valid() const noexcept { return fd_ >= 0; }
    /// Gives the descriptor up (its new owner closes it).
    [[nodiscard]] int release() noexcept { return std::exchange(fd_, -1); }
    /// Closes the descriptor (an orderly close: the peer reads the end).
    void close() noexcept;
    /// Closes with a TCP reset (SO_LINGER 0): a refused connection leaves no
    /// TIME_WAIT behind on our side.
    void reset() noexcept;

  private:
    int fd_ = -1;
};

/// Sends small messages at once (TCP_NODELAY): DICOM's requests and answers
/// would otherwise wait for delayed ACKs (~40 ms each).
void sendAtOnce(int fd) noexcept;

/// Bounds every blocking read and write on `fd` to `seconds` (SO_RCVTIMEO,
/// SO_SNDTIMEO). Set after DCMTK's connection constructors, which set its
/// global 60 s.
void boundEachReadAndWrite(int fd, int seconds) noexcept;

/// The IPv4 address ("192.0.2.7") of the peer of the connected socket `fd`;
/// empty when it has none (closed meanwhile, not IPv4).
[[nodiscard]] std::string peerAddress(int fd);

}  // namespace vv::pacs::detail
