// SPDX-License-Identifier: GPL-3.0-or-later
// What the DICOM network dialogs say for each typed failure of vv::pacs
// (app/gui/pacs/NetworkFailure.h): the node as AE@host:port and what to check.
#include <gtest/gtest.h>

#include <stdexcept>

#include "gui/pacs/NetworkFailure.h"
#include "vv/core/Error.h"
#include "vv/pacs/PacsError.h"

namespace vv::gui {
namespace {

using Kind = NetworkFailure::Kind;

template <typename E>
NetworkFailure failureOf(const char* message) {
    return classifyFailure(std::make_exception_ptr(E(message)));
}

const pacs::Node kNode{"PACS1", "pacs.example", 4242, {}};

TEST(NetworkFailureTest, EachTypedErrorGetsItsKind) {
    EXPECT_EQ(classifyFailure(nullptr).kind, Kind::None);
    EXPECT_EQ(failureOf<pacs::ConnectionRefusedError>("x").kind, Kind::Refused);
    EXPECT_EQ(failureOf<pacs::AssociationRejectedError>("x").kind, Kind::AssociationRejected);
    EXPECT_EQ(failureOf<pacs::TimeoutError>("x").kind, Kind::Timeout);
    EXPECT_EQ(failureOf<pacs::TlsError>("x").kind, Kind::Tls);
    EXPECT_EQ(failureOf<pacs::PeerFailedError>("x").kind, Kind::PeerFailed);
    EXPECT_EQ(failureOf<pacs::ResponseError>("x").kind, Kind::Response);
    EXPECT_EQ(classifyFailure(std::make_exception_ptr(CancelledError())).kind, Kind::Cancelled);
    EXPECT_EQ(failureOf<InvalidArgumentError>("x").kind, Kind::InvalidInput);
    const NetworkFailure other = failureOf<std::runtime_error>("disk full");
    EXPECT_EQ(other.kind, Kind::Other);
    EXPECT_EQ(other.detail, "disk full");
}

TEST(NetworkFailureTest, TheMessageNamesTheNodeAndWhatToCheck) {
    const struct {
        Kind kind;
        const char* says;
    } cases[] = {
        {Kind::Refused, "refused the connection"}, {Kind::AssociationRejected, "AE title"},
        {Kind::Timeout, "did not answer in time"}, {Kind::Tls, "trusted CA certificate"},
        {Kind::PeerFailed, "during the transfer"}, {Kind::Other, "Failed with"},
    };
    for (const auto& c : cases) {
        const std::string text = failureText({c.kind, "detail"}, kNode).toStdString();
        EXPECT_NE(text.find("PACS1@pacs.example:4242"), std::string::npos) << text;
        EXPECT_NE(text.find(c.says), std::string::npos) << text;
    }
    // Too many matches: the peer's limit and what to do.
    const std::string tooMany =
        failureText({Kind::Response, "more than 2000 matches"}, kNode).toStdString();
    EXPECT_NE(tooMany.find("more than 2000 matches"), std::string::npos) << tooMany;
    EXPECT_NE(tooMany.find("Narrow the search"), std::string::npos) << tooMany;
}

}  // namespace
}  // namespace vv::gui
