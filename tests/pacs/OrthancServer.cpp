// SPDX-License-Identifier: GPL-3.0-or-later
#include "OrthancServer.h"

#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>

#include "FileLock.h"
#include "WaitUntil.h"
#include "vv/pacs/Echo.h"

namespace fs = std::filesystem;

namespace vv::test {

std::pair<int, int> ephemeralPorts() {
    std::ifstream in("/proc/sys/net/ipv4/ip_local_port_range");
    int first = 0;
    int last = 0;
    if (in >> first >> last && first > 0 && first <= last && last <= 65535) {
        return {first, last};
    }
    return {32768, 60999};
}

namespace {

/// The ports tests listen on: outside the ephemeral range, so that no
/// connection made meanwhile (by this test, Orthanc, or a test running beside
/// it) can take the port between its choice and its listener's bind.
std::pair<int, int> testPorts() {
    constexpr int kLowest = 10000;
    constexpr int kEnough = 1000;
    const auto [first, last] = ephemeralPorts();
    if (first - 1 - kLowest >= kEnough) {
        return {kLowest, first - 1};
    }
    if (65535 - (last + 1) >= kEnough) {
        return {last + 1, 65535};
    }
    return {1024, 65535};  // no room outside: the checks below still hold
}

/// True when nothing uses `port` on any address right now: a bind without
/// SO_REUSEADDR fails for a listener, a connection or a TIME_WAIT on it.
bool unused(int port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) {
        return false;
    }
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_ANY);
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    const bool bound = ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
    ::close(fd);
    return bound;
}

/// Reserves `port` among this user's test processes until this process
/// ends: an exclusive flock on a file named after it, never released (the
/// kernel releases it at exit, also after a crash), also when the port
/// turns out to be in use. Tests run side by side under ctest -j, each its
/// own process.
bool reserve(int port) {
    auto lock =
        vv::pacs::detail::FileLock::tryExclusive(portLockFile(static_cast<std::uint16_t>(port)));
    if (!lock) {
        return false;
    }
    (void)lock->release();  // the descriptor stays open: the lock is held until exit
    return true;
}

}  // namespace

fs::path portLockFile(std::uint16_t port) {
    static const fs::path folder = [] {
        fs::path path =
            fs::temp_directory_path() / ("vesselview-test-ports-" + std::to_string(::getuid()));
        std::error_code ignored;
        fs::create_directories(path, ignored);
        return path;
    }();
    return folder / (std::to_string(port) + ".lock");
}

std::uint16_t freePort() {
    static std::mutex mutex;
    const std::lock_guard lock(mutex);
    const auto [first, last] = testPorts();
    const int count = last - first + 1;
    // Start at a different place in each process, so that processes started
    // together seldom contend for the same lock files.
    static int next = static_cast<int>(
        (static_cast<unsigned>(::getpid()) * 2654435761U +
         static_cast<unsigned>(std::chrono::steady_clock::now().time_since_epoch().count())) %
        static_cast<unsigned>(count));
    for (int tried = 0; tried < count; ++tried) {
        const int port = first + next;
        next = (next + 1) % count;
        // Reserved first, then checked: no other test can take it in between. A
        // port this process gave out earlier stays reserved by it, so it fails
        // here too (flock: another open file of the same process is refused).
        if (reserve(port) && unused(port)) {
            return static_cast<std::uint16_t>(port);
        }
    }
    throw std::runtime_error("no free port between " + std::to_string(first) + " and " +
                             std::to_string(last));
}

SilentPeer::SilentPeer() : fd_(::socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (fd_ < 0 || ::bind(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
        ::listen(fd_, 4) != 0 ||
        ::getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
        if (fd_ >= 0) {
            ::close(fd_);
        }
        throw std::runtime_error("cannot open a silent peer's socket");
    }
    port_ = ntohs(address.sin_port);
}

SilentPeer::~SilentPeer() {
    ::close(fd_);
}

TestCertificates makeCertificates(const fs::path& folder) {
    fs::create_directories(folder);
    const std::string d = folder.string() + "/";
    const auto run = [](const std::string& command) {
        if (std::system((command + " >/dev/null 2>&1").c_str()) != 0) {
            throw std::runtime_error("failed: " + command);
        }
    };
    const std::string key = " -newkey rsa:2048 -nodes -days 2";
    run("openssl req -x509" + key + " -keyout " + d + "ca.key -out " + d +
        "ca.pem -subj /CN=vv-ca");
    run("openssl req -x509" + key + " -keyout " + d + "other.key -out " + d +
        "other.pem -subj /CN=vv-other-ca");
    for (const std::string name : {"server", "client"}) {
        run("openssl req" + key + " -keyout " + d + name + ".key -out " + d + name +
            ".csr -subj /CN=" + name);
        run("openssl x509 -req -days 2 -in " + d + name + ".csr -CA " + d + "ca.pem -CAkey " + d +
            "ca.key -CAcreateserial -out " + d + name + ".pem");
    }
    return {folder / "ca.pem",     folder / "server.pem", folder / "server.key",
            folder / "client.pem", folder / "client.key", folder / "other.pem"};
}

OrthancServer::OrthancServer(const std::string& ourAe, std::uint16_t ourPort,
                             const TestCertificates* tls) {
    if (tls != nullptr) {
        tls_ = {true, tls->ca, tls->clientCert, tls->clientKey};
    }
    static std::atomic<int> counter{0};
    folder_ = fs::path(VV_TEST_TMP) /
              ("orthanc-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    // A port taken by another process between choosing and binding makes
    // Orthanc exit at once: then again with other ports (three tries).
    for (int attempt = 1;; ++attempt) {
        const std::string problem = start(ourAe, ourPort, tls);
        if (problem.empty()) {
            return;
        }
        if (attempt == 3 || pid_ != -2) {
            pid_ = -1;
            throw std::runtime_error(problem);
        }
        pid_ = -1;
    }
}

std::string OrthancServer::start(const std::string& ourAe, std::uint16_t ourPort,
                                 const TestCertificates* tls) {
    fs::remove_all(folder_);
    fs::create_directories(folder_ / "storage");
    dicomPort_ = freePort();
    const std::uint16_t httpPort = freePort();
    {
        std::ofstream config(folder_ / "orthanc.json");
        config << "{\n"
               << "  \"Name\": \"vv-test\",\n"
               << "  \"StorageDirectory\": \"" << (folder_ / "storage").string() << "\",\n"
               << "  \"IndexDirectory\": \"" << (folder_ / "storage").string() << "\",\n"
               << "  \"Plugins\": [],\n"
               << "  \"HttpServerEnabled\": true,\n"
               << "  \"HttpPort\": " << httpPort << ",\n"
               << "  \"RemoteAccessAllowed\": false,\n"
               << "  \"AuthenticationEnabled\": false,\n"
               << "  \"DicomServerEnabled\": true,\n"
               << "  \"DicomAet\": \"ORTHANC\",\n"
               << "  \"DicomPort\": " << dicomPort_ << ",\n"
               << "  \"DicomCheckCalledAet\": true,\n"
               << "  \"DicomAlwaysAllowEcho\": false,\n"
               << "  \"DicomAlwaysAllowStore\": false,\n"
               << "  \"DicomCheckModalityHost\": true,\n"
               << "  \"DicomAssociationCloseDelay\": 0,\n"
               << "  \"DicomScuTimeout\": 10,\n"
               << "  \"DicomScpTimeout\": 10,\n"
               << "  \"SaveJobs\": false,\n";
        if (tls != nullptr) {
            config << "  \"DicomTlsEnabled\": true,\n"
                   << "  \"DicomTlsCertificate\": \"" << tls->serverCert.string() << "\",\n"
                   << "  \"DicomTlsPrivateKey\": \"" << tls->serverKey.string() << "\",\n"
                   << "  \"DicomTlsTrustedCertificates\": \"" << tls->ca.string() << "\",\n"
                   << "  \"DicomTlsRemoteCertificateRequired\": true,\n";
        }
        config << "  \"DicomModalities\": { \"vv\": { \"AET\": \"" << ourAe
               << "\", \"Host\": \"127.0.0.1\", \"Port\": " << ourPort
               << ", \"AllowEcho\": true, \"AllowFind\": true, \"AllowGet\": true,"
               << " \"AllowMove\": true, \"AllowStore\": true"
               << (tls != nullptr ? ", \"UseDicomTls\": true" : "") << " } }\n"
               << "}\n";
    }
    const std::string log = (folder_ / "orthanc.log").string();
    const std::string configFile = (folder_ / "orthanc.json").string();
    pid_ = ::fork();
    if (pid_ == 0) {
        const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        ::dup2(out, 1);
        ::dup2(out, 2);
        ::execl("/usr/sbin/Orthanc", "Orthanc", configFile.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    vv::pacs::LocalAe me{ourAe, {1, 2, 5}};
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    std::string lastError;
    while (true) {
        try {
            vv::pacs::echo(me, node());
            return {};
        } catch (const std::exception& e) {
            lastError = e.what();
            int status = 0;
            const bool exited = ::waitpid(pid_, &status, WNOHANG) == pid_;
            if (exited) {
                pid_ = -1;
            }
            if (exited || std::chrono::steady_clock::now() > deadline) {
                stop();
                if (exited) {
                    pid_ = -2;  // exited by itself: worth another try
                }
                std::ifstream in(log);
                std::stringstream text;
                text << in.rdbuf();
                return "Orthanc did not come up (" + lastError + "):\n" + text.str();
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    }
}

OrthancServer::~OrthancServer() {
    stop();
}

void OrthancServer::kill() {
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
        pid_ = -1;
    }
}

void OrthancServer::pause() {
    if (pid_ > 0) {
        ::kill(pid_, SIGSTOP);
    }
}

void OrthancServer::resume() {
    if (pid_ > 0) {
        ::kill(pid_, SIGCONT);
    }
}

void OrthancServer::stop() {
    if (pid_ <= 0) {
        return;
    }
    ::kill(pid_, SIGCONT);  // a paused Orthanc cannot stop
    ::kill(pid_, SIGTERM);
    if (vv::test::pollUntil([this] { return ::waitpid(pid_, nullptr, WNOHANG) == pid_; },
                            std::chrono::seconds(10))) {
        pid_ = -1;
        return;
    }
    kill();
}

}  // namespace vv::test
