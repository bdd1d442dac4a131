// SPDX-License-Identifier: GPL-3.0-or-later
// What the DICOM network dialogs say for each typed failure of vv::pacs
// (app/gui/pacs/NetworkFailure.h): the node by its name and AE@host:port, what
// to check, and the module's English detail apart.
#include <gtest/gtest.h>

#include <QLocale>
#include <optional>
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
    EXPECT_EQ(failureOf<pacs::ConnectionClosedError>("x").kind, Kind::ConnectionClosed);
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
        {Kind::Refused, "refused the connection"},         {Kind::AssociationRejected, "AE title"},
        {Kind::Timeout, "did not answer in time"},         {Kind::Tls, "trusted CA certificate"},
        {Kind::PeerFailed, "reported a failure"},          {Kind::Other, "failed unexpectedly"},
        {Kind::ConnectionClosed, "closed the connection"},
    };
    for (const auto& c : cases) {
        const ProblemText problem =
            failureText({c.kind, "C-ECHO xyzzy", std::nullopt}, QStringLiteral("Radiology"), kNode);
        const std::string text = problem.summary.toStdString();
        EXPECT_NE(text.find("Radiology (PACS1@pacs.example:4242)"), std::string::npos) << text;
        EXPECT_NE(text.find(c.says), std::string::npos) << text;
        // The module's words apart, never inside the sentence.
        EXPECT_EQ(text.find("C-ECHO xyzzy"), std::string::npos) << text;
        EXPECT_EQ(problem.details, QStringLiteral("C-ECHO xyzzy"));
    }
    // Too many matches: our limit (the UI locale's digits) and what to do.
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    const NetworkFailure tooMany = classifyFailure(std::make_exception_ptr(
        pacs::TooManyMatchesError("C-FIND answer refused: more than 2000 matches", 2000)));
    ASSERT_EQ(tooMany.kind, Kind::TooManyMatches);
    const std::string tooManyText = failureText(tooMany, {}, kNode).summary.toStdString();
    EXPECT_NE(tooManyText.find("more than 2,000 matches"), std::string::npos) << tooManyText;
    EXPECT_NE(tooManyText.find("Narrow the search"), std::string::npos) << tooManyText;
    QLocale::setDefault(before);
}

/// A C-GET that `E` ended after `received` of `expected` images.
template <typename E>
NetworkFailure interrupted(std::size_t received, std::optional<std::size_t> expected) {
    E error(
        "PACS1@pacs.example:4242: C-GET failed: the peer closed the connection (Peer "
        "aborted Association (or never connected))");
    error.setTransfer({received, expected});
    return classifyFailure(std::make_exception_ptr(error));
}

TEST(NetworkFailureTest, AnInterruptedRetrieveSaysHowFarItCameWhatWasKeptAndWhatToDo) {
    const NetworkFailure closed = interrupted<pacs::ConnectionClosedError>(60, 400);
    ASSERT_EQ(closed.kind, Kind::ConnectionClosed);
    ASSERT_TRUE(closed.transfer.has_value());
    const std::string text =
        retrieveFailureText(closed, QStringLiteral("ORTHANC"), kNode, 0).summary.toStdString();
    EXPECT_EQ(text,
              "The transfer from ORTHANC stopped after 60 of 400 images: the PACS closed the "
              "connection. Nothing was kept. Try again, or ask the PACS administrator if it "
              "keeps happening.");
    // Stopped answering; before the first image; the total unknown; what was
    // kept unknown (not said).
    const std::string timeout =
        retrieveFailureText(interrupted<pacs::TimeoutError>(0, std::nullopt),
                            QStringLiteral("ORTHANC"), kNode, 0)
            .summary.toStdString();
    EXPECT_NE(timeout.find("stopped before the first image arrived: the PACS stopped answering."),
              std::string::npos)
        << timeout;
    const std::string unknownTotal =
        retrieveFailureText(interrupted<pacs::PeerFailedError>(60, std::nullopt),
                            QStringLiteral("ORTHANC"), kNode, std::nullopt)
            .summary.toStdString();
    EXPECT_NE(unknownTotal.find("after 60 image"), std::string::npos) << unknownTotal;
    EXPECT_EQ(unknownTotal.find("kept"), std::string::npos) << unknownTotal;
    // Without a node name the node's address, once.
    const std::string unnamed = retrieveFailureText(closed, {}, kNode, 0).summary.toStdString();
    EXPECT_EQ(unnamed.rfind("The transfer from PACS1@pacs.example:4242 stopped", 0), 0U) << unnamed;
    // A failure before the transfer began: the general message.
    const NetworkFailure refused = failureOf<pacs::ConnectionRefusedError>("x");
    EXPECT_EQ(retrieveFailureText(refused, QStringLiteral("ORTHANC"), kNode, 0).summary,
              failureText(refused, QStringLiteral("ORTHANC"), kNode).summary);
}

}  // namespace
}  // namespace vv::gui
