// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli pacs echo|find|get|send|listen`: DICOM networking through
// vv::pacs. A peer that refuses or fails exits with 5 (kPeerFailed).
#include <chrono>
#include <csignal>
#include <cstdint>
#include <limits>
#include <optional>
#include <ostream>
#include <thread>
#include <utility>

#include "cli/Arguments.h"
#include "cli/Cli.h"
#include "cli/JsonWriter.h"
#include "vv/core/Error.h"
#include "vv/pacs/Echo.h"
#include "vv/pacs/Find.h"
#include "vv/pacs/PacsError.h"
#include "vv/pacs/Retrieve.h"
#include "vv/pacs/Send.h"
#include "vv/pacs/StorageScp.h"

namespace vv::cli {

namespace {

volatile std::sig_atomic_t gStop = 0;

extern "C" void onStopSignal(int /*signal*/) {
    gStop = 1;
}

/// "AE@HOST:PORT" -> Node.
pacs::Node parseNode(const std::string& text, const Arguments& a) {
    const auto at = text.find('@');
    const auto colon = text.rfind(':');
    if (at == std::string::npos || colon == std::string::npos || colon < at) {
        a.fail("a node is AE@HOST:PORT, not '" + text + "'");
    }
    pacs::Node node;
    node.aeTitle = text.substr(0, at);
    node.host = text.substr(at + 1, colon - at - 1);
    node.port = static_cast<std::uint16_t>(
        parseWholeNumber(text.substr(colon + 1), a.command() + " port", 1, 65535));
    pacs::validateNode(node);
    return node;
}

/// `option`'s value "BYTES", "NMB" or "NGB" (decimal: 1 GB = 10^9 bytes) in
/// bytes, at least `least` (`leastText`: how the message says it).
std::uint64_t parseBytes(const std::string& text, const std::string& option, std::uint64_t least,
                         const std::string& leastText, const Arguments& a) {
    std::string digits = text;
    std::uint64_t unit = 1;
    for (const auto& [suffix, factor] : {std::pair{"GB", 1000000000ULL}, {"MB", 1000000ULL}}) {
        const std::string s = suffix;
        if (digits.size() > s.size() && digits.ends_with(s)) {
            digits.resize(digits.size() - s.size());
            unit = factor;
        }
    }
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) {
        a.fail(option + " takes BYTES, NMB or NGB, not '" + text + "'");
    }
    const auto first = digits.find_first_not_of('0');
    const std::string significant = first == std::string::npos ? "0" : digits.substr(first);
    constexpr std::uint64_t kMost = std::numeric_limits<std::uint64_t>::max();
    if (significant.size() > 19 || std::stoull(significant) > kMost / unit) {
        a.fail(option + " '" + text + "' is too large");
    }
    const std::uint64_t bytes = std::stoull(significant) * unit;
    if (bytes < least) {
        a.fail(option + " must be at least " + leastText);
    }
    return bytes;
}

/// Takes the listener limit option `name` into `l` (a value out of the
/// limit's range is a usage error naming the option); false when `name` is
/// no limit option.
bool parseLimit(const std::string& name, Arguments& a, pacs::ListenerLimits& l) {
    const auto count = [&a, &name](int most) { return parseWholeNumber(a.value(), name, 1, most); };
    if (name == "--max-associations") {
        l.maxAssociations = count(pacs::ListenerLimits::kMaxAssociations);
    } else if (name == "--max-per-address") {
        l.maxConnectionsPerAddress = count(pacs::ListenerLimits::kMaxConnections);
    } else if (name == "--max-connections") {
        l.maxConnections = count(pacs::ListenerLimits::kMaxConnections);
    } else if (name == "--request-timeout") {
        l.requestSeconds = count(pacs::ListenerLimits::kMaxRequestSeconds);
    } else if (name == "--max-instance") {
        l.maxInstanceBytes =
            parseBytes(a.value(), name, pacs::ListenerLimits::kMinInstanceBytes, "1000 bytes", a);
    } else if (name == "--max-association") {
        l.maxAssociationBytes =
            parseBytes(a.value(), name, pacs::ListenerLimits::kMinInstanceBytes, "1000 bytes", a);
    } else {
        return false;
    }
    return true;
}

/// Limits that do not fit together are a usage error naming both options
/// (with the values in force: given or default); then validate() has the
/// last word.
void checkLimits(const pacs::ListenerLimits& l, const Arguments& a) {
    const auto conflict = [&a](const std::string& option, std::uint64_t value,
                               const std::string& rule, const std::string& other,
                               std::uint64_t otherValue) {
        a.fail(option + " (" + std::to_string(value) + ") must be " + rule + " " + other + " (" +
               std::to_string(otherValue) + ")");
    };
    if (l.maxConnections < l.maxAssociations) {
        conflict("--max-connections", l.maxConnections, "at least", "--max-associations",
                 l.maxAssociations);
    }
    if (l.maxConnectionsPerAddress > l.maxConnections) {
        conflict("--max-per-address", l.maxConnectionsPerAddress, "at most", "--max-connections",
                 l.maxConnections);
    }
    if (l.maxAssociationBytes < l.maxInstanceBytes) {
        conflict("--max-association", l.maxAssociationBytes, "at least", "--max-instance",
                 l.maxInstanceBytes);
    }
    try {
        l.validate();
    } catch (const InvalidArgumentError& e) {
        a.fail(std::string(e.what()) +
               " (--max-associations, --max-per-address, --max-connections, --request-timeout, "
               "--max-instance, --max-association)");
    }
}

/// The options every subcommand shares, and the ones only some take.
struct Options {
    pacs::LocalAe me;
    std::optional<pacs::Node> node;
    pacs::StudyQuery study;
    std::string studyUid;
    std::string seriesUid;
    std::filesystem::path store;
    std::vector<std::filesystem::path> files;
    std::vector<pacs::Node> allowed;
    pacs::TlsSettings tls;
    std::uint16_t port = 0;
    std::uint64_t storeLimit = 0;
    pacs::ListenerLimits limits;
    std::string limitOption;  ///< the first listener limit given ("" when none)
    std::string bind = "0.0.0.0";
    bool move = false;
    int seconds = 0;
};

Options parse(const std::string& sub, const std::vector<std::string>& args) {
    Options o;
    Arguments a("pacs " + sub, args, 1);
    while (a.next()) {
        const std::string& n = a.name();
        if (n == "--node") {
            o.node = parseNode(a.value(), a);
        } else if (n == "--aet") {
            o.me.aeTitle = a.value();
        } else if (n == "--timeout") {
            o.me.timeouts.responseSeconds =
                parseWholeNumber(a.value(), "--timeout", 1, pacs::Timeouts::kMaxSeconds);
        } else if (n == "--patient-name") {
            o.study.patientName = a.value();
        } else if (n == "--patient-id") {
            o.study.patientId = a.value();
        } else if (n == "--date-from") {
            o.study.studyDateFrom = a.value();
        } else if (n == "--date-to") {
            o.study.studyDateTo = a.value();
        } else if (n == "--modality") {
            o.study.modality = a.value();
        } else if (n == "--description") {
            o.study.studyDescription = a.value();
        } else if (n == "--accession") {
            o.study.accessionNumber = a.value();
        } else if (n == "--study") {
            o.studyUid = a.value();
        } else if (n == "--series") {
            o.seriesUid = a.value();
        } else if (n == "--store") {
            o.store = a.path();
        } else if (n == "--store-limit" && (sub == "get" || sub == "listen")) {
            o.storeLimit = parseBytes(a.value(), n, 1000000ULL, "1MB", a);
        } else if ((sub == "get" || sub == "listen") && parseLimit(n, a, o.limits)) {
            o.limitOption = o.limitOption.empty() ? n : o.limitOption;
        } else if (n == "--allow") {
            o.allowed.push_back(parseNode(a.value() + ":104", a));
        } else if (n == "--port") {
            o.port = static_cast<std::uint16_t>(parseWholeNumber(a.value(), "--port", 1, 65535));
        } else if (n == "--bind") {
            o.bind = a.value();
        } else if (n == "--move") {
            o.move = true;
        } else if (n == "--tls-ca") {
            o.tls.enabled = true;
            o.tls.trustedCertificates = a.path();
        } else if (n == "--tls-cert") {
            o.tls.certificate = a.path();
        } else if (n == "--tls-key") {
            o.tls.privateKey = a.path();
        } else if (n == "--for") {
            o.seconds = parseWholeNumber(a.value(), "--for", 1, 31 * 24 * 3600);
        } else if (!a.isOption() && sub == "send") {
            o.files.emplace_back(a.current());
        } else {
            a.fail("unknown option '" + a.current() + "'");
        }
    }
    if (sub != "listen" && !o.node) {
        a.fail("needs --node AE@HOST:PORT");
    }
    if (!o.tls.enabled && (!o.tls.certificate.empty() || !o.tls.privateKey.empty())) {
        a.fail("--tls-cert and --tls-key need --tls-ca");
    }
    if (o.tls.certificate.empty() != o.tls.privateKey.empty()) {
        a.fail("--tls-cert and --tls-key go together");
    }
    const bool listens = sub == "listen" || (sub == "get" && o.move);
    if (o.tls.enabled && listens && o.tls.certificate.empty()) {
        a.fail("a TLS listener needs --tls-cert and --tls-key");
    }
    if (!listens && !o.limitOption.empty()) {
        a.fail(o.limitOption + " needs --move: only our listener has limits");
    }
    checkLimits(o.limits, a);
    if (o.node) {
        o.node->tls = o.tls;
    }
    if ((sub == "get" || sub == "listen") && o.store.empty()) {
        a.fail("needs --store DIR");
    }
    if (sub == "get" && o.studyUid.empty()) {
        a.fail("needs --study UID");
    }
    if (((sub == "get" && o.move) || sub == "listen") && o.port == 0) {
        a.fail("needs --port P for our listener");
    }
    if (sub == "send" && o.files.empty()) {
        a.fail("needs at least one FILE");
    }
    return o;
}

/// Our listener as the options set it up, letting in `allowed`.
pacs::ListenerConfig listenerConfig(const Options& o, std::vector<pacs::Node> allowed) {
    pacs::ListenerConfig config;
    config.aeTitle = o.me.aeTitle;
    config.port = o.port;
    config.allowedPeers = std::move(allowed);
    config.bindAddress = o.bind;
    config.timeouts = o.me.timeouts;
    config.tls = o.tls;
    config.limits = o.limits;
    return config;
}

int find(const Options& o, std::ostream& out) {
    JsonWriter json(out);
    json.beginArray();
    if (o.studyUid.empty()) {
        for (const pacs::StudyResult& s : pacs::findStudies(o.me, *o.node, o.study)) {
            json.beginObject();
            json.member("studyInstanceUid", s.studyInstanceUid);
            json.member("patientName", s.patientName);
            json.member("patientId", s.patientId);
            json.member("studyDate", s.studyDate);
            json.member("studyDescription", s.studyDescription);
            json.member("accessionNumber", s.accessionNumber);
            json.member("modalities", s.modalitiesInStudy);
            json.member("series", s.numberOfSeries);
            json.endObject();
        }
    } else {
        const pacs::SeriesQuery query{o.studyUid, o.study.modality, o.study.studyDescription};
        for (const pacs::SeriesResult& s : pacs::findSeries(o.me, *o.node, query)) {
            json.beginObject();
            json.member("seriesInstanceUid", s.seriesInstanceUid);
            json.member("modality", s.modality);
            json.member("seriesDescription", s.seriesDescription);
            json.member("seriesNumber", s.seriesNumber);
            json.member("instances", s.numberOfInstances);
            json.endObject();
        }
    }
    json.endArray();
    json.finish();
    return kOk;
}

int get(const Options& o, std::ostream& out) {
    pacs::LocalStore store(o.store);
    store.setSizeLimit(o.storeLimit);
    const pacs::RetrieveRequest request{o.studyUid, o.seriesUid};
    std::size_t instances = 0;
    if (o.move) {
        const pacs::StorageScp listener(store, listenerConfig(o, {*o.node}));
        instances = pacs::moveTo(o.me.aeTitle, o.me, *o.node, request).instances;
        // The peer's storing association ends before its last C-MOVE response
        // in general; wait (bounded) until the listener has committed it.
        const auto deadline =
            std::chrono::steady_clock::now() + std::chrono::seconds(o.me.timeouts.responseSeconds);
        while (listener.stats().committedInstances < instances &&
               std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        if (listener.stats().committedInstances < instances) {
            throw pacs::TimeoutError("the moved instances did not all arrive in time");
        }
    } else {
        instances = pacs::getInto(store, o.me, *o.node, request).instances;
    }
    out << "retrieved " << instances << " instance(s) into " << o.store.string() << "\n";
    return kOk;
}

int send(const Options& o, std::ostream& out) {
    int refused = 0;
    for (const pacs::SendStatus& s : pacs::sendFiles(o.me, *o.node, o.files)) {
        char status[8];
        std::snprintf(status, sizeof status, "0x%04X", s.status);
        out << (s.accepted ? "accepted " : "refused  ") << status << " " << s.file.string() << "\n";
        refused += s.accepted ? 0 : 1;
    }
    return refused == 0 ? kOk : kPeerFailed;
}

int listen(const Options& o, std::ostream& out) {
    pacs::LocalStore store(o.store);
    store.setSizeLimit(o.storeLimit);
    gStop = 0;
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
    {
        const pacs::StorageScp listener(store, listenerConfig(o, o.allowed));
        out << "listening as " << o.me.aeTitle << " on " << o.bind << ":" << o.port << std::endl;
        const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(o.seconds);
        while (gStop == 0 && (o.seconds == 0 || std::chrono::steady_clock::now() < end)) {
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        out << "stored " << listener.stats().committedInstances << " instance(s)\n";
    }
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    return kOk;
}

}  // namespace

int pacsCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    if (args.empty()) {
        throw UsageError("pacs: needs echo, find, get, send or listen");
    }
    const std::string& sub = args.front();
    if (sub != "echo" && sub != "find" && sub != "get" && sub != "send" && sub != "listen") {
        throw UsageError("pacs: unknown subcommand '" + sub + "'");
    }
    const Options o = parse(sub, args);
    try {
        if (sub == "echo") {
            pacs::echo(o.me, *o.node);
            out << "C-ECHO " << pacs::describe(*o.node) << ": ok\n";
            return kOk;
        }
        if (sub == "find") {
            return find(o, out);
        }
        if (sub == "get") {
            return get(o, out);
        }
        if (sub == "send") {
            return send(o, out);
        }
        return listen(o, out);
    } catch (const pacs::NetworkError& e) {
        err << "vesselview-cli: " << e.what() << "\n";
        return kPeerFailed;
    }
}

}  // namespace vv::cli
