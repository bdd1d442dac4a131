// SPDX-License-Identifier: GPL-3.0-or-later
#include "ListenSocket.h"

#include <arpa/inet.h>
#include <dcmtk/dcmnet/dulstruc.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "vv/core/Error.h"

namespace vv::pacs::detail {

namespace {

in_addr parse(const std::string& address) {
    in_addr result{};
    if (::inet_pton(AF_INET, address.c_str(), &result) != 1) {
        throw InvalidArgumentError("\"" + address + "\" is not an IPv4 address to listen on");
    }
    return result;
}

}  // namespace

void validateBindAddress(const std::string& address) {
    parse(address);
}

void rebindListenSocket(T_ASC_Network& network, const std::string& address, std::uint16_t port) {
    auto* key = static_cast<PRIVATE_NETWORKKEY*>(network.network);
    const int old = key->networkSpecific.TCP.listenSocket;
    const std::string where = address + ":" + std::to_string(port);
    ::close(old);
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) {
        throw IoError("cannot listen on " + where + ": " + std::strerror(errno));
    }
    const int reuse = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &reuse, sizeof reuse);
    sockaddr_in bound{};
    bound.sin_family = AF_INET;
    bound.sin_addr = parse(address);
    bound.sin_port = htons(port);
    if (::bind(fd, reinterpret_cast<sockaddr*>(&bound), sizeof bound) != 0 ||
        ::listen(fd, 64) != 0) {
        const std::string why = std::strerror(errno);
        ::close(fd);
        throw IoError("cannot listen on " + where + ": " + why);
    }
    // Keep the descriptor number DCMTK knows.
    if (fd != old) {
        if (::dup2(fd, old) < 0) {
            const std::string why = std::strerror(errno);
            ::close(fd);
            throw IoError("cannot listen on " + where + ": " + why);
        }
        ::close(fd);
        ::fcntl(old, F_SETFD, FD_CLOEXEC);
    }
}

}  // namespace vv::pacs::detail
