// SPDX-License-Identifier: GPL-3.0-or-later
#include "ConnectionGate.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

#include "vv/core/Error.h"

namespace vv::pacs::detail {

namespace {

constexpr std::uint8_t kAssociateRqPdu = 0x01;  // PS3.8 9.3.2
constexpr std::size_t kPduHeader = 6;           // type, reserved, 32-bit length
constexpr std::uint8_t kTlsHandshake = 0x16;    // RFC 8446 5.1
constexpr std::size_t kTlsRecordHeader = 5;     // type, version, 16-bit length
constexpr int kAcceptsPerRound = 256;

/// Wakes poll() only when `bytes` have arrived (or the peer closed).
void wakeAt(int fd, std::size_t bytes) {
    const int lowat = static_cast<int>(bytes);
    ::setsockopt(fd, SOL_SOCKET, SO_RCVLOWAT, &lowat, sizeof lowat);
}

}  // namespace

ConnectionGate::ConnectionGate(OwnedSocket listening, Settings settings, ConnectionBudget& budget,
                               RefusalLog& log, Counters counters, Ready ready)
    : listening_(std::move(listening)),
      wake_(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)),
      spare_(::open("/dev/null", O_RDONLY | O_CLOEXEC)),
      settings_(settings),
      budget_(budget),
      log_(log),
      counters_(std::move(counters)),
      ready_(std::move(ready)) {
    if (!wake_.valid()) {
        throw IoError(std::string("cannot start the listener: ") + std::strerror(errno));
    }
    thread_ = std::thread([this] { run(); });
}

ConnectionGate::~ConnectionGate() {
    const std::uint64_t one = 1;
    [[maybe_unused]] const auto written = ::write(wake_.get(), &one, sizeof one);
    thread_.join();
}

void ConnectionGate::run() {
    std::vector<pollfd> fds;
    while (true) {
        fds.clear();
        fds.push_back({wake_.get(), POLLIN, 0});
        fds.push_back({listening_.get(), POLLIN, 0});
        auto next = std::chrono::steady_clock::time_point::max();
        for (const Pending& p : pending_) {
            fds.push_back({p.socket.get(), POLLIN | POLLRDHUP, 0});
            next = std::min(next, p.deadline);
        }
        int timeoutMs = -1;
        if (!pending_.empty()) {
            const auto left = std::chrono::ceil<std::chrono::milliseconds>(
                next - std::chrono::steady_clock::now());
            timeoutMs = static_cast<int>(std::max<std::int64_t>(0, left.count()));
        }
        const int n = ::poll(fds.data(), fds.size(), timeoutMs);
        if (n < 0 && errno != EINTR) {
            break;  // cannot happen with valid descriptors; never spin
        }
        if ((fds[0].revents & POLLIN) != 0) {
            break;
        }
        // Pending connections first (the ones accepted below are not in `fds`).
        std::vector<Pending> still;
        still.reserve(pending_.size());
        const auto now = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < pending_.size(); ++i) {
            Pending& p = pending_[i];
            if (n > 0 && fds[i + 2].revents != 0) {
                std::string why;
                switch (inspect(p, why)) {
                    case Verdict::Ready:
                        handOn(std::move(p), false);
                        continue;
                    case Verdict::ReadyBuffered:
                        handOn(std::move(p), true);
                        continue;
                    case Verdict::NotARequest:
                        drop(std::move(p), why);
                        continue;
                    case Verdict::Closed:
                        drop(std::move(p), {});
                        continue;
                    case Verdict::Wait:
                        // Part of a request, then the peer closed its side:
                        // nothing more will come (and poll() would not wait).
                        if ((fds[i + 2].revents & (POLLRDHUP | POLLHUP | POLLERR)) != 0) {
                            drop(std::move(p), "closed before its whole association request");
                            continue;
                        }
                        break;
                }
            }
            if (now >= p.deadline) {
                drop(std::move(p), "no association request within " +
                                       std::to_string(settings_.deadline.count()) + " s");
                continue;
            }
            still.push_back(std::move(p));
        }
        pending_ = std::move(still);
        if (n > 0 && (fds[1].revents & POLLIN) != 0) {
            acceptAll();
        }
    }
    pending_.clear();
    listening_.close();
}

void ConnectionGate::acceptAll() {
    for (int round = 0; round < kAcceptsPerRound; ++round) {
        sockaddr_in from{};
        socklen_t length = sizeof from;
        // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the sockets API
        OwnedSocket socket(::accept4(listening_.get(), reinterpret_cast<sockaddr*>(&from), &length,
                                     SOCK_NONBLOCK | SOCK_CLOEXEC));
        if (!socket.valid()) {
            if (errno == EMFILE || errno == ENFILE) {
                // Out of descriptors: take one connection with the spare and
                // refuse it, so that the backlog does not wake poll() forever.
                spare_.close();
                OwnedSocket refused(::accept4(listening_.get(), nullptr, nullptr, SOCK_CLOEXEC));
                refused.reset();
                spare_ = OwnedSocket(::open("/dev/null", O_RDONLY | O_CLOEXEC));
                counters_.refused();
                log_.note("refused a connection", {}, "the listener is out of file descriptors");
                continue;
            }
            if (errno == EINTR || errno == ECONNABORTED) {
                continue;
            }
            return;  // EAGAIN: nothing more waiting
        }
        std::array<char, INET_ADDRSTRLEN> text{};
        const bool known =
            from.sin_family == AF_INET &&
            ::inet_ntop(AF_INET, &from.sin_addr, text.data(), text.size()) != nullptr;
        admit(std::move(socket), known ? std::string(text.data()) : std::string());
    }
}

void ConnectionGate::admit(OwnedSocket socket, const std::string& address) {
    std::string why;
    std::optional<ConnectionBudget::Slot> slot = budget_.take(address, &why);
    if (!slot) {
        socket.reset();
        counters_.refused();
        log_.note("refused a connection", address, why);
        return;
    }
    pending_.push_back(Pending{std::move(socket), std::move(*slot),
                               std::chrono::steady_clock::now() + settings_.deadline});
}

ConnectionGate::Verdict ConnectionGate::inspect(const Pending& pending, std::string& why) {
    const int fd = pending.socket.get();
    const ssize_t n = ::recv(fd, peek_.data(), peek_.size(), MSG_PEEK | MSG_DONTWAIT);
    if (n == 0) {
        return Verdict::Closed;
    }
    if (n < 0) {
        return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR ? Verdict::Wait
                                                                         : Verdict::Closed;
    }
    const auto got = static_cast<std::size_t>(n);
    const std::uint8_t type = peek_[0];
    if (settings_.tls && type != kTlsHandshake) {
        return Verdict::Ready;  // the TLS handshake fails at once, and says so
    }
    if (!settings_.tls && type != kAssociateRqPdu) {
        why = "not a DICOM association request";
        return Verdict::NotARequest;
    }
    const std::size_t header = settings_.tls ? kTlsRecordHeader : kPduHeader;
    if (got < header) {
        wakeAt(fd, header);
        return Verdict::Wait;
    }
    std::size_t body = 0;
    if (settings_.tls) {
        body = (std::size_t{peek_[3]} << 8U) | peek_[4];
    } else {
        const std::uint32_t length = (std::uint32_t{peek_[2]} << 24U) |
                                     (std::uint32_t{peek_[3]} << 16U) |
                                     (std::uint32_t{peek_[4]} << 8U) | peek_[5];
        if (length > kMaxRequestBytes) {
            why = "an association request of " + std::to_string(length) + " bytes";
            return Verdict::NotARequest;
        }
        body = length;
    }
    const std::size_t need = std::min(header + body, kPeekBytes);
    if (got < need) {
        wakeAt(fd, need);
        return Verdict::Wait;
    }
    return !settings_.tls && got >= header + body ? Verdict::ReadyBuffered : Verdict::Ready;
}

void ConnectionGate::handOn(Pending&& pending, bool buffered) {
    const int fd = pending.socket.get();
    wakeAt(fd, 1);
    sendAtOnce(fd);
    const int flags = ::fcntl(fd, F_GETFL);
    ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    ready_(ReadyConnection{std::move(pending.socket), std::move(pending.slot), buffered});
}

void ConnectionGate::drop(Pending&& pending, const std::string& why) {
    const std::string address = pending.slot.address();
    pending.socket.reset();
    counters_.dropped();
    if (!why.empty()) {  // a peer that connects and closes (a port check) is no news
        log_.note("dropped a connection", address, why);
    }
}

}  // namespace vv::pacs::detail
