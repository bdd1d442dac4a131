// SPDX-License-Identifier: GPL-3.0-or-later
#include "ListenSocket.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

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

OwnedSocket openListenSocket(const std::string& address, std::uint16_t port) {
    const std::string where = address + ":" + std::to_string(port);
    OwnedSocket fd(::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
    if (!fd.valid()) {
        throw IoError("cannot listen on " + where + ": " + std::strerror(errno));
    }
    const int reuse = 1;
    ::setsockopt(fd.get(), SOL_SOCKET, SO_REUSEADDR, &reuse, sizeof reuse);
    sockaddr_in bound{};
    bound.sin_family = AF_INET;
    bound.sin_addr = parse(address);
    bound.sin_port = htons(port);
    // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the sockets API
    if (::bind(fd.get(), reinterpret_cast<sockaddr*>(&bound), sizeof bound) != 0 ||
        ::listen(fd.get(), SOMAXCONN) != 0) {
        throw IoError("cannot listen on " + where + ": " + std::strerror(errno));
    }
    return fd;
}

}  // namespace vv::pacs::detail
