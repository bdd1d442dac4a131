// SPDX-License-Identifier: GPL-3.0-or-later
// The machine's IPv4 TCP sockets as the kernel lists them (/proc/net/tcp):
// lets a network test poll for a state of the wire (a client connected, its
// request arrived at a peer that never reads) instead of sleeping for it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace vv::test {

/// One line of /proc/net/tcp.
struct TcpSocket {
    std::uint16_t localPort = 0;
    std::uint16_t remotePort = 0;
    unsigned state = 0;            ///< 1: established, 10: listening (include/net/tcp_states.h)
    std::size_t receiveQueue = 0;  ///< bytes arrived and not yet read
};

inline constexpr unsigned kTcpEstablished = 1;

/// The IPv4 TCP sockets of this network namespace; empty when the table
/// cannot be read.
inline std::vector<TcpSocket> tcpSockets() {
    std::vector<TcpSocket> sockets;
    std::ifstream table("/proc/net/tcp");
    std::string line;
    std::getline(table, line);  // the header
    while (std::getline(table, line)) {
        // "sl local_address rem_address st tx_queue:rx_queue ...", addresses
        // as HEXIP:HEXPORT, the rest hexadecimal too.
        unsigned local = 0;
        unsigned remote = 0;
        unsigned state = 0;
        unsigned long transmit = 0;
        unsigned long receive = 0;
        if (std::sscanf(line.c_str(), " %*[^:]: %*[0-9A-Fa-f]:%x %*[0-9A-Fa-f]:%x %x %lx:%lx",
                        &local, &remote, &state, &transmit, &receive) == 5) {
            sockets.push_back({static_cast<std::uint16_t>(local),
                               static_cast<std::uint16_t>(remote), state,
                               static_cast<std::size_t>(receive)});
        }
    }
    return sockets;
}

/// The established connections whose far end is `port` (clients connected to it).
inline int connectionsTo(std::uint16_t port) {
    int count = 0;
    for (const TcpSocket& s : tcpSockets()) {
        count += (s.state == kTcpEstablished && s.remotePort == port) ? 1 : 0;
    }
    return count;
}

/// The bytes that arrived at established connections on `port` and that the
/// server has not read (a server that never reads, or a stopped one, keeps
/// them there).
inline std::size_t unreadBytesAt(std::uint16_t port) {
    std::size_t bytes = 0;
    for (const TcpSocket& s : tcpSockets()) {
        bytes += (s.state == kTcpEstablished && s.localPort == port) ? s.receiveQueue : 0U;
    }
    return bytes;
}

}  // namespace vv::test
