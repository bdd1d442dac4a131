// SPDX-License-Identifier: GPL-3.0-or-later
// A plain TCP connection from 127.0.0.1 that never sends a byte, for the
// tests of the listener's connection limits: is it open, or did the listener
// close it?
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>

namespace vv::test {

class IdleConnection {
  public:
    /// Connects to 127.0.0.1:`port` (connected() tells whether it could).
    explicit IdleConnection(std::uint16_t port) : fd_(::socket(AF_INET, SOCK_STREAM, 0)) {
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        address.sin_port = htons(port);
        // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the sockets API
        connected_ = fd_ >= 0 && ::connect(fd_, reinterpret_cast<const sockaddr*>(&address),
                                           sizeof address) == 0;
    }
    ~IdleConnection() {
        if (fd_ >= 0) {
            ::close(fd_);
        }
    }
    IdleConnection(const IdleConnection&) = delete;
    IdleConnection& operator=(const IdleConnection&) = delete;
    IdleConnection(IdleConnection&&) = delete;
    IdleConnection& operator=(IdleConnection&&) = delete;

    [[nodiscard]] bool connected() const noexcept { return connected_; }

    /// True once the listener closed (or reset) the connection, waiting at
    /// most `waitMs` for it (0: looks without waiting). Whatever the listener
    /// sent before closing does not count as open.
    [[nodiscard]] bool closedByPeer(int waitMs = 0) const {
        if (!connected_) {
            return true;
        }
        pollfd what{fd_, POLLRDHUP, 0};
        return ::poll(&what, 1, waitMs) == 1 &&
               (what.revents & (POLLRDHUP | POLLHUP | POLLERR)) != 0;
    }

  private:
    int fd_;
    bool connected_ = false;
};

}  // namespace vv::test
