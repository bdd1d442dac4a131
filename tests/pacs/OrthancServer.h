// SPDX-License-Identifier: GPL-3.0-or-later
// A real Orthanc (Debian's `orthanc` package) for the networking tests: its
// own temporary folder, free ports chosen at run time, a configuration written
// here (our AE title known as a modality, HTTP on localhost only, called AE
// title checked), started in the constructor and stopped in the destructor.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>

#include "vv/pacs/Node.h"

namespace vv::test {

/// A TCP port nobody uses right now, for a listener the test starts next:
/// outside the kernel's ephemeral range (so no connection takes it
/// meanwhile), never given twice in this process, and reserved against the
/// user's other test processes until this one ends. Throws
/// std::runtime_error when none is left.
std::uint16_t freePort();

/// The file whose flock reserves `port` for the process that holds it.
std::filesystem::path portLockFile(std::uint16_t port);

/// The ports the kernel gives a connection's local end
/// (net.ipv4.ip_local_port_range); 32768-60999 when that cannot be read.
std::pair<int, int> ephemeralPorts();

/// A peer that never answers: a socket listening on 127.0.0.1 that the
/// kernel accepts connections for (its backlog) but nobody reads; closed in
/// the destructor. Throws std::runtime_error when it cannot be opened.
class SilentPeer {
  public:
    SilentPeer();
    ~SilentPeer();
    SilentPeer(const SilentPeer&) = delete;
    SilentPeer& operator=(const SilentPeer&) = delete;
    [[nodiscard]] std::uint16_t port() const noexcept { return port_; }

  private:
    int fd_ = -1;
    std::uint16_t port_ = 0;
};

/// Test certificates made with the openssl tool: a CA, a server and a client
/// certificate signed by it, and a second CA that signed neither (PEM files).
struct TestCertificates {
    std::filesystem::path ca, serverCert, serverKey, clientCert, clientKey, otherCa;
};

/// Writes the certificates into `folder`; throws std::runtime_error.
TestCertificates makeCertificates(const std::filesystem::path& folder);

class OrthancServer {
  public:
    /// Starts Orthanc and waits (at most 30 s) until it answers C-ECHO from
    /// `ourAe`; `ourPort` is where Orthanc sends C-MOVE results for `ourAe`.
    /// Throws std::runtime_error (with Orthanc's log) when it does not come up.
    /// With `tls`, Orthanc speaks DICOM only over TLS (server certificate and
    /// key, trusting `tls->ca`, client certificates required), and sends
    /// C-MOVE results to `ourPort` over TLS too.
    OrthancServer(const std::string& ourAe, std::uint16_t ourPort,
                  const TestCertificates* tls = nullptr);
    ~OrthancServer();
    OrthancServer(const OrthancServer&) = delete;
    OrthancServer& operator=(const OrthancServer&) = delete;

    /// Orthanc as a node (with our TLS client settings when it speaks TLS).
    [[nodiscard]] vv::pacs::Node node() const { return {"ORTHANC", "127.0.0.1", dicomPort_, tls_}; }
    /// Kills Orthanc at once (SIGKILL), as a crash would.
    void kill();
    /// Freezes Orthanc (SIGSTOP): it holds its connections and answers nothing.
    void pause();
    /// Lets a paused Orthanc go on (SIGCONT).
    void resume();
    [[nodiscard]] const std::filesystem::path& folder() const { return folder_; }

  private:
    /// One try: writes the configuration with new ports, starts Orthanc and
    /// waits for C-ECHO. "" when it answers, else the problem and Orthanc's
    /// log; pid_ is -2 when Orthanc exited by itself.
    std::string start(const std::string& ourAe, std::uint16_t ourPort, const TestCertificates* tls);
    void stop();
    std::filesystem::path folder_;
    std::uint16_t dicomPort_ = 0;
    pid_t pid_ = -1;
    vv::pacs::TlsSettings tls_;
};

}  // namespace vv::test
