// SPDX-License-Identifier: GPL-3.0-or-later
// vv_send_helper: a DICOM sender in another process, for the listener's load
// and abuse tests (ListenerLoadTest), which kill or stop it.
//   vv_send_helper PORT CALLED_AE CALLING_AE STALL_BYTES FILE...
// sends the FILEs to CALLED_AE@127.0.0.1:PORT as CALLING_AE in one
// association (vv::pacs::sendFiles), through a relay in this process that
// passes the bytes on. With STALL_BYTES above 0 the relay passes exactly that
// many bytes towards the listener, prints "stalled" and then passes nothing
// more, holding the connection open: the sender stalls there, at a point the
// test chose (in the middle of a dataset). Without a stall it prints
// "sent N accepted M" or "failed: WHY". Then it waits until its standard input
// closes (at most 120 s).
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "vv/pacs/Send.h"

namespace {

sockaddr_in loopback(std::uint16_t port) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = htons(port);
    return address;
}

bool writeAll(int fd, const char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::send(fd, data, size, MSG_NOSIGNAL);
        if (n <= 0) {
            return false;
        }
        data += n;
        size -= static_cast<std::size_t>(n);
    }
    return true;
}

void say(const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
}

/// Accepts one connection on `server`, connects to the listener at `port`
/// and passes bytes both ways until either side closes; towards the listener
/// at most `stallBytes` (0: no limit), then it says "stalled" and stops.
void relay(int server, std::uint16_t port, std::uint64_t stallBytes) {
    const int client = ::accept(server, nullptr, nullptr);
    const int upstream = ::socket(AF_INET, SOCK_STREAM, 0);
    const sockaddr_in target = loopback(port);
    if (client < 0 || upstream < 0 ||
        ::connect(upstream, reinterpret_cast<const sockaddr*>(&target), sizeof target) != 0) {
        say("failed: cannot reach the listener");
        return;  // the sender's association fails; the descriptors go with the process
    }
    std::uint64_t passed = 0;
    std::vector<char> buffer(std::size_t{64} * 1024);
    pollfd fds[2] = {{client, POLLIN, 0}, {upstream, POLLIN, 0}};
    while (::poll(fds, 2, -1) > 0) {
        if ((fds[1].revents & (POLLIN | POLLHUP | POLLERR)) != 0) {
            const ssize_t n = ::recv(upstream, buffer.data(), buffer.size(), 0);
            if (n <= 0 || !writeAll(client, buffer.data(), static_cast<std::size_t>(n))) {
                break;
            }
        }
        if ((fds[0].revents & (POLLIN | POLLHUP | POLLERR)) != 0) {
            std::size_t want = buffer.size();
            if (stallBytes > 0) {
                want = static_cast<std::size_t>(std::min<std::uint64_t>(want, stallBytes - passed));
            }
            const ssize_t n = ::recv(client, buffer.data(), want, 0);
            if (n <= 0 || !writeAll(upstream, buffer.data(), static_cast<std::size_t>(n))) {
                break;
            }
            passed += static_cast<std::uint64_t>(n);
            if (stallBytes > 0 && passed == stallBytes) {
                say("stalled");
                // Both connections stay open, nothing more passes.
                pollfd in{STDIN_FILENO, POLLIN, 0};
                (void)::poll(&in, 1, 120000);
                ::_exit(0);
            }
        }
    }
    ::close(client);
    ::close(upstream);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 6) {
        std::fprintf(stderr,
                     "usage: vv_send_helper PORT CALLED_AE CALLING_AE STALL_BYTES FILE...\n");
        return 2;
    }
    const auto port = static_cast<std::uint16_t>(std::stoul(argv[1]));
    const std::uint64_t stallBytes = std::stoull(argv[4]);
    const std::vector<std::filesystem::path> files(argv + 5, argv + argc);

    const int server = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address = loopback(0);
    socklen_t length = sizeof address;
    if (server < 0 || ::bind(server, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
        ::listen(server, 1) != 0 ||
        ::getsockname(server, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
        std::fprintf(stderr, "vv_send_helper: cannot open the relay\n");
        return 1;
    }
    std::thread relayThread(relay, server, port, stallBytes);
    try {
        // Long timeouts: the test, not our own timeout, ends a stalled transfer.
        const vv::pacs::LocalAe me{argv[3], vv::pacs::Timeouts{10, 120, 120}};
        const vv::pacs::Node listener{argv[2], "127.0.0.1", ntohs(address.sin_port), {}};
        const auto statuses = vv::pacs::sendFiles(me, listener, files);
        const auto accepted = std::count_if(statuses.begin(), statuses.end(),
                                            [](const auto& s) { return s.accepted; });
        say("sent " + std::to_string(statuses.size()) + " accepted " + std::to_string(accepted));
    } catch (const std::exception& e) {
        say(std::string("failed: ") + e.what());
    }
    relayThread.join();
    pollfd in{STDIN_FILENO, POLLIN, 0};
    (void)::poll(&in, 1, 120000);
    return 0;
}
