// SPDX-License-Identifier: GPL-3.0-or-later
#include "ListenerPeers.h"

#include <arpa/inet.h>
#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcistrmf.h>
#include <dcmtk/dcmdata/dcpixel.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "vv/pacs/LocalStore.h"

namespace vv::bench {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

sockaddr_in address(const std::string& ip, std::uint16_t port) {
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    if (::inet_pton(AF_INET, ip.c_str(), &a.sin_addr) != 1) {
        throw std::runtime_error("not an IPv4 address: " + ip);
    }
    return a;
}

/// Milliseconds left until `deadline` (at least 0), for poll().
int msLeft(Clock::time_point deadline) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    return left > 0 ? static_cast<int>(left) : 0;
}

/// Polls `fd` for `events` until `deadline`; true when it is ready.
bool ready(int fd, short events, Clock::time_point deadline) {
    pollfd p{fd, events, 0};
    for (;;) {
        const int n = ::poll(&p, 1, msLeft(deadline));
        if (n > 0) {
            return true;
        }
        if (n == 0 || errno != EINTR) {
            return false;
        }
    }
}

Clock::time_point after(int seconds) {
    return Clock::now() + std::chrono::seconds(seconds);
}

}  // namespace

Connection Connection::start(const std::string& from, std::uint16_t port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (fd < 0) {
        throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
    }
    Connection c(fd);
    const sockaddr_in source = address(from, 0);
    const sockaddr_in target = address("127.0.0.1", port);
    if (::bind(fd, reinterpret_cast<const sockaddr*>(&source), sizeof source) != 0) {
        throw std::runtime_error("cannot bind to " + from + ": " + std::strerror(errno));
    }
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&target), sizeof target) != 0 &&
        errno != EINPROGRESS) {
        throw std::runtime_error("cannot connect to port " + std::to_string(port) + ": " +
                                 std::strerror(errno));
    }
    return c;
}

Connection Connection::open(const std::string& from, std::uint16_t port, int seconds) {
    Connection c = start(from, port);
    int error = 0;
    socklen_t length = sizeof error;
    if (!ready(c.fd_, POLLOUT, after(seconds)) ||
        ::getsockopt(c.fd_, SOL_SOCKET, SO_ERROR, &error, &length) != 0 || error != 0) {
        throw std::runtime_error("no connection to port " + std::to_string(port) + " in " +
                                 std::to_string(seconds) + " s");
    }
    return c;
}

Connection::Connection(Connection&& other) noexcept : fd_(other.fd_) {
    other.fd_ = -1;
}

Connection& Connection::operator=(Connection&& other) noexcept {
    if (this != &other) {
        close();
        fd_ = other.fd_;
        other.fd_ = -1;
    }
    return *this;
}

Connection::~Connection() {
    close();
}

void Connection::close() noexcept {
    if (fd_ >= 0) {
        ::close(fd_);
        fd_ = -1;
    }
}

void Connection::send(const Bytes& bytes, int seconds) const {
    const auto deadline = after(seconds);
    std::size_t sent = 0;
    while (sent < bytes.size()) {
        const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
        if (n > 0) {
            sent += static_cast<std::size_t>(n);
        } else if (n < 0 && (errno == EAGAIN || errno == EINTR) && ready(fd_, POLLOUT, deadline)) {
            continue;
        } else {
            throw std::runtime_error("cannot send: " + std::string(std::strerror(errno)));
        }
    }
}

std::optional<Bytes> Connection::receive(std::size_t count, int seconds) const {
    const auto deadline = after(seconds);
    Bytes bytes(count);
    std::size_t got = 0;
    while (got < count) {
        if (!ready(fd_, POLLIN, deadline)) {
            return std::nullopt;
        }
        const ssize_t n = ::recv(fd_, bytes.data() + got, count - got, 0);
        if (n > 0) {
            got += static_cast<std::size_t>(n);
        } else if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
            return std::nullopt;
        }
    }
    return bytes;
}

bool Connection::closedByPeer(int seconds) const {
    const auto deadline = after(seconds);
    char buffer[4096];
    while (ready(fd_, POLLIN, deadline)) {
        const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
        if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) {
            return true;
        }
    }
    return false;
}

RawServer::RawServer() : fd_(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0)) {
    sockaddr_in a = address("127.0.0.1", 0);
    socklen_t length = sizeof a;
    if (fd_ < 0 || ::bind(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 ||
        ::listen(fd_, 4) != 0 ||
        ::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &length) != 0) {
        if (fd_ >= 0) {
            ::close(fd_);
        }
        throw std::runtime_error("cannot open a server socket");
    }
    port_ = ntohs(a.sin_port);
}

RawServer::~RawServer() {
    ::close(fd_);
}

Connection RawServer::accept(int seconds) const {
    if (!ready(fd_, POLLIN, after(seconds))) {
        throw std::runtime_error("no connection came in " + std::to_string(seconds) + " s");
    }
    const int fd = ::accept4(fd_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) {
        throw std::runtime_error(std::string("accept: ") + std::strerror(errno));
    }
    return Connection(fd);
}

std::vector<Connection> idleConnections(const std::string& from, std::uint16_t port, int count) {
    std::vector<Connection> connections;
    connections.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        connections.push_back(Connection::start(from, port));
    }
    return connections;
}

ChildProcess::ChildProcess(const std::string& program, const std::vector<std::string>& arguments) {
    int toChild[2];
    int fromChild[2];
    if (::pipe2(toChild, O_CLOEXEC) != 0) {
        throw std::runtime_error("pipe");
    }
    if (::pipe2(fromChild, O_CLOEXEC) != 0) {
        ::close(toChild[0]);
        ::close(toChild[1]);
        throw std::runtime_error("pipe");
    }
    // execv() wants writable strings: copies, made before fork().
    std::vector<std::string> words = {program};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    argv.reserve(words.size() + 1);
    for (std::string& w : words) {
        argv.push_back(w.data());
    }
    argv.push_back(nullptr);
    pid_ = ::fork();
    if (pid_ == 0) {
        ::dup2(toChild[0], STDIN_FILENO);
        ::dup2(fromChild[1], STDOUT_FILENO);
        // Nothing else of ours (a listener's sockets) lives on in the child.
        ::close_range(3, ~0U, 0);
        ::execv(program.c_str(), argv.data());
        ::_exit(127);
    }
    ::close(toChild[0]);
    ::close(fromChild[1]);
    input_ = toChild[1];
    output_ = fromChild[0];
    if (pid_ < 0) {
        ::close(input_);
        ::close(output_);
        throw std::runtime_error("cannot start " + program);
    }
}

ChildProcess::~ChildProcess() {
    ::close(input_);
    (void)end(SIGKILL, 30);
    ::close(output_);
}

std::optional<std::string> ChildProcess::readLine(int seconds) {
    const auto deadline = after(seconds);
    for (;;) {
        const auto newline = pending_.find('\n');
        if (newline != std::string::npos) {
            std::string line = pending_.substr(0, newline);
            pending_.erase(0, newline + 1);
            return line;
        }
        if (!ready(output_, POLLIN, deadline)) {
            return std::nullopt;
        }
        char buffer[512];
        const ssize_t n = ::read(output_, buffer, sizeof buffer);
        if (n <= 0) {
            return std::nullopt;
        }
        pending_.append(buffer, static_cast<std::size_t>(n));
    }
}

void ChildProcess::signal(int signalNumber) const noexcept {
    if (pid_ > 0) {
        ::kill(pid_, signalNumber);
    }
}

bool ChildProcess::end(int signalNumber, int seconds) noexcept {
    if (pid_ <= 0) {
        return true;
    }
    signal(signalNumber);
    ::kill(pid_, SIGCONT);  // a stopped process acts on the signal once it runs again
    // Its pid descriptor turns readable when it ends.
    // (glibc 2.36's <sys/pidfd.h> lacks extern "C": the system call itself.)
    const auto exited = static_cast<int>(::syscall(SYS_pidfd_open, pid_, 0));
    if (exited < 0 || !ready(exited, POLLIN, after(seconds))) {
        if (exited >= 0) {
            ::close(exited);
        }
        return false;
    }
    ::close(exited);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    return true;
}

void writeLargeImage(const fs::path& model, const fs::path& out, int side) {
    if (side < 1 || side > 46340) {  // 2 side² bytes must fit a 32-bit length
        throw std::runtime_error("an image side must be 1 to 46340, not " + std::to_string(side));
    }
    DcmFileFormat file;
    if (file.loadFile(model.c_str()).bad() || file.loadAllDataIntoMemory().bad()) {
        throw std::runtime_error("cannot read " + model.string());
    }
    const auto bytes = static_cast<Uint32>(side) * static_cast<Uint32>(side) * 2U;
    const fs::path raw = out.string() + ".pixels";
    {
        std::error_code ec;
        fs::remove(raw, ec);
        std::FILE* f = std::fopen(raw.c_str(), "wb");
        if (f == nullptr) {
            throw std::runtime_error("cannot write " + raw.string());
        }
        std::fclose(f);
        fs::resize_file(raw, bytes);  // sparse: reads as zeros, takes no room
    }
    DcmDataset& data = *file.getDataset();
    auto pixels = std::make_unique<DcmPixelData>(DcmTag(DCM_PixelData, EVR_OW));
    OFCondition cond = pixels->createValueFromTempFile(
        new DcmInputFileStreamFactory(raw.c_str(), 0), bytes, EBO_LittleEndian);
    if (cond.good()) {
        cond = data.insert(pixels.release(), OFTrue);
    }
    if (cond.good()) {
        cond = data.putAndInsertUint16(DCM_Rows, static_cast<Uint16>(side));
    }
    if (cond.good()) {
        cond = data.putAndInsertUint16(DCM_Columns, static_cast<Uint16>(side));
    }
    if (cond.good()) {
        cond = file.saveFile(out.c_str(), EXS_LittleEndianExplicit);
    }
    std::error_code ec;
    fs::remove(raw, ec);
    if (cond.bad()) {
        throw std::runtime_error("cannot write " + out.string() + ": " + cond.text());
    }
}

std::size_t storedInstances(const vv::pacs::LocalStore& store) {
    std::size_t n = 0;
    for (const vv::pacs::StoredStudy& study : store.studies()) {
        for (const vv::pacs::StoredSeries& series : study.series) {
            n += static_cast<std::size_t>(series.instances);
        }
    }
    return n;
}

}  // namespace vv::bench
