// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The peers of the DICOM listener's load and abuse tests
// (tests/pacs/ListenerLoadTest.cpp) and of bench/listener_load: raw TCP
// connections from a chosen loopback address (idle, garbage, replayed
// PDUs), a child process talking through pipes (a sender to kill or stop, a
// listener to measure), a DICOM image too large to hold in memory, and what
// they ask of the store and the time. Every wait here is bounded; failures
// throw std::runtime_error.

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vv::pacs {
class LocalStore;
}

namespace vv::bench {

using Bytes = std::vector<std::uint8_t>;

/// One TCP connection from a source address of this host (e.g. 127.0.0.2:
/// loopback traffic from an address that is no configured node) to
/// 127.0.0.1:`port`; closed on destruction.
class Connection {
  public:
    /// Starts connecting without waiting: a listener that accepts nothing
    /// does not hold the caller up (the kernel finishes the connection).
    static Connection start(const std::string& from, std::uint16_t port);
    /// Connects and waits at most `seconds` until the connection is made.
    static Connection open(const std::string& from, std::uint16_t port, int seconds);

    Connection(Connection&& other) noexcept;
    Connection& operator=(Connection&& other) noexcept;
    Connection(const Connection&) = delete;
    Connection& operator=(const Connection&) = delete;
    ~Connection();

    /// Sends all of `bytes` (within `seconds`).
    void send(const Bytes& bytes, int seconds = 10) const;
    /// Exactly `count` bytes within `seconds`; nullopt when the peer closes
    /// or the time runs out first.
    [[nodiscard]] std::optional<Bytes> receive(std::size_t count, int seconds) const;
    /// Waits at most `seconds` until the peer closes (or resets) the
    /// connection, throwing away what it sends; true when it did.
    [[nodiscard]] bool closedByPeer(int seconds) const;
    void close() noexcept;

  private:
    friend class RawServer;
    explicit Connection(int fd) noexcept : fd_(fd) {}
    int fd_ = -1;
};

/// A TCP socket listening on 127.0.0.1 at a port the kernel chose (to see
/// what a DICOM client sends); closed on destruction.
class RawServer {
  public:
    RawServer();
    RawServer(const RawServer&) = delete;
    RawServer& operator=(const RawServer&) = delete;
    ~RawServer();
    [[nodiscard]] std::uint16_t port() const noexcept { return port_; }
    /// The next connection, within `seconds`.
    [[nodiscard]] Connection accept(int seconds) const;

  private:
    int fd_ = -1;
    std::uint16_t port_ = 0;
};

/// `count` connections from `from` to 127.0.0.1:`port` that send nothing,
/// all started without waiting (Connection::start).
[[nodiscard]] std::vector<Connection> idleConnections(const std::string& from, std::uint16_t port,
                                                      int count);

/// A program run as a child process, its standard input and output piped to
/// us (standard error is ours). The destructor closes its input, kills it
/// (SIGKILL) if it still runs and reaps it.
class ChildProcess {
  public:
    ChildProcess(const std::string& program, const std::vector<std::string>& arguments);
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;
    ~ChildProcess();

    [[nodiscard]] pid_t pid() const noexcept { return pid_; }
    /// Its next line of output (without the newline) within `seconds`;
    /// nullopt when it closes its output or the time runs out first.
    [[nodiscard]] std::optional<std::string> readLine(int seconds);
    /// Sends `signalNumber` (SIGSTOP, SIGKILL, ...) unless it has ended.
    void signal(int signalNumber) const noexcept;
    /// Sends `signalNumber`, then waits at most `seconds` for the process to
    /// end; true when it did (then it is reaped).
    bool end(int signalNumber, int seconds) noexcept;

  private:
    pid_t pid_ = -1;
    int input_ = -1;
    int output_ = -1;
    std::string pending_;
};

/// Writes the DICOM image `model` again as `out` with a `side` x `side`
/// pixel array of 16-bit zeros, the rest unchanged (`out` may be `model`).
/// The pixel data is never held in memory: DCMTK copies it from a sparse
/// temporary file beside `out` while writing, so the file may be gigabytes.
void writeLargeImage(const std::filesystem::path& model, const std::filesystem::path& out,
                     int side);

/// The instances of all complete studies of `store` (its index).
[[nodiscard]] std::size_t storedInstances(const vv::pacs::LocalStore& store);

}  // namespace vv::bench
