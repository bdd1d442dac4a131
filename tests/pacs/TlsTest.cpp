// SPDX-License-Identifier: GPL-3.0-or-later
// DICOM over TLS against Orthanc speaking TLS only (certificates made with
// the openssl tool): echo and find over TLS; a peer certificate from a CA we
// do not trust, a missing client certificate, unreadable files, plain TCP
// to the TLS port and a TLS port that never answers are each a clear error.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <stop_token>

#include "OrthancServer.h"
#include "PacsTestUtil.h"
#include "vv/pacs/Echo.h"
#include "vv/pacs/Find.h"
#include "vv/pacs/PacsError.h"

namespace tls_test {

namespace fs = std::filesystem;
using namespace vv::pacs;
using vv::test::OrthancServer;

namespace {

constexpr const char* kOurAe = "VVTLS";

LocalAe me() {
    return LocalAe{kOurAe, Timeouts{2, 5, 10}};
}

class TlsTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        const fs::path folder = fs::path(VV_TEST_TMP) / ("pacs-tls-" + std::to_string(::getpid()));
        fs::remove_all(folder);
        certificates_ = vv::test::makeCertificates(folder);
        orthanc_ = std::make_unique<OrthancServer>(kOurAe, vv::test::freePort(), &certificates_);
    }
    static void TearDownTestSuite() { orthanc_.reset(); }

    static vv::test::TestCertificates certificates_;
    static std::unique_ptr<OrthancServer> orthanc_;
};

vv::test::TestCertificates TlsTest::certificates_;
std::unique_ptr<OrthancServer> TlsTest::orthanc_;

}  // namespace

TEST_F(TlsTest, EchoAndFindOverTls) {
    EXPECT_NO_THROW(echo(me(), orthanc_->node()));
    EXPECT_TRUE(findStudies(me(), orthanc_->node(), StudyQuery{}).empty());
}

TEST_F(TlsTest, EchoAndFindOverTlsThatCanBeStoppedWorkAndUntrustedIsStillRefused) {
    const std::stop_source stop;  // never requested: the abortable layer wraps the TLS one
    EXPECT_NO_THROW(echo(me(), orthanc_->node(), stop.get_token()));
    EXPECT_TRUE(findStudies(me(), orthanc_->node(), StudyQuery{}, {}, stop.get_token()).empty());
    Node untrusted = orthanc_->node();
    untrusted.tls.trustedCertificates = certificates_.otherCa;
    EXPECT_THROW(echo(me(), untrusted, stop.get_token()), TlsError);
}

TEST_F(TlsTest, UntrustedServerCertificateIsTlsError) {
    Node node = orthanc_->node();
    node.tls.trustedCertificates = certificates_.otherCa;
    EXPECT_THROW(echo(me(), node), TlsError);
}

TEST_F(TlsTest, MissingClientCertificateFails) {
    Node node = orthanc_->node();
    node.tls.certificate.clear();
    node.tls.privateKey.clear();
    EXPECT_THROW(echo(me(), node), NetworkError);
}

TEST_F(TlsTest, UnreadableCertificateFileIsTlsError) {
    Node node = orthanc_->node();
    node.tls.trustedCertificates = "/nonexistent/ca.pem";
    try {
        echo(me(), node);
        FAIL() << "echo with a missing CA file succeeded";
    } catch (const TlsError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/ca.pem"), std::string::npos) << e.what();
    }
}

TEST_F(TlsTest, ATlsPortThatNeverAnswersTimesOut) {
    const vv::test::SilentPeer port;  // never answers the TLS handshake
    Node silent = orthanc_->node();
    silent.port = port.port();
    // Without the timeout the handshake would wait for ever (ctest's limit ends the test).
    EXPECT_THROW(echo(LocalAe{kOurAe, Timeouts{2, 2, 2}}, silent), TimeoutError);
}

TEST_F(TlsTest, PlainConnectionToTlsPortFails) {
    Node node = orthanc_->node();
    node.tls = {};
    EXPECT_THROW(echo(me(), node), NetworkError);
}

}  // namespace tls_test
