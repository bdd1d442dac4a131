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

#include "vv/pacs/Node.h"

namespace vv::test {

/// A TCP port nobody listens on right now (bound to 0, read back, closed).
std::uint16_t freePort();

class OrthancServer {
  public:
    /// Starts Orthanc and waits (at most 30 s) until it answers C-ECHO from
    /// `ourAe`; `ourPort` is where Orthanc sends C-MOVE results for `ourAe`.
    /// Throws std::runtime_error (with Orthanc's log) when it does not come up.
    OrthancServer(const std::string& ourAe, std::uint16_t ourPort);
    ~OrthancServer();
    OrthancServer(const OrthancServer&) = delete;
    OrthancServer& operator=(const OrthancServer&) = delete;

    [[nodiscard]] vv::pacs::Node node() const { return {"ORTHANC", "127.0.0.1", dicomPort_}; }
    /// Kills Orthanc at once (SIGKILL), as a crash would.
    void kill();
    [[nodiscard]] const std::filesystem::path& folder() const { return folder_; }

  private:
    void stop();
    std::filesystem::path folder_;
    std::uint16_t dicomPort_ = 0;
    pid_t pid_ = -1;
};

}  // namespace vv::test
