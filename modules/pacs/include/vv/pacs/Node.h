// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A DICOM node: who we are (our AE title, timeouts) and who we talk to (the
// peer's AE title, host and port).

#include <cstdint>
#include <filesystem>
#include <string>

namespace vv::pacs {

/// How long each network wait may take. Every wait of vv::pacs has one of these.
struct Timeouts {
    /// The longest wait the front ends take for any of these (an hour; each from 1 s).
    static constexpr int kMaxSeconds = 3600;
    int connectSeconds = 5;     ///< TCP connect
    int associateSeconds = 10;  ///< association request / release (ACSE)
    int responseSeconds = 30;   ///< each DIMSE message (a response, a dataset)
};

/// Our own application entity.
struct LocalAe {
    std::string aeTitle = "VESSELVIEW";
    Timeouts timeouts;
};

/// DICOM over TLS (DCMTK's dcmtls with OpenSSL, BCP 195 profile). The peer's
/// certificate must chain to `trustedCertificates`; we show `certificate`
/// when the peer asks for one. All files PEM; the key unencrypted.
struct TlsSettings {
    bool enabled = false;
    std::filesystem::path trustedCertificates;  ///< CA certificate(s) we trust
    std::filesystem::path certificate;          ///< ours (optional)
    std::filesystem::path privateKey;           ///< the key of ours (with `certificate`)
};

/// A peer application entity (a PACS, a modality, a workstation).
struct Node {
    std::string aeTitle;
    std::string host;
    std::uint16_t port = 104;
    TlsSettings tls;
};

/// Throws InvalidArgumentError unless `aeTitle` is a valid AE title: 1 to 16
/// characters of printable ASCII without backslash, not only spaces.
void validateAeTitle(const std::string& aeTitle);

/// Throws InvalidArgumentError unless `node` has a valid AE title, a non-empty
/// host and a port above 0.
void validateNode(const Node& node);

/// "AE@host:port" for messages and logs (never patient data).
[[nodiscard]] std::string describe(const Node& node);

}  // namespace vv::pacs
