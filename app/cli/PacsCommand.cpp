// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli pacs echo|find|get|send|listen`: DICOM networking through
// vv::pacs. A peer that refuses or fails exits with 5 (kPeerFailed).
#include <chrono>
#include <csignal>
#include <cstdint>
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

/// "BYTES", "NMB" or "NGB" (decimal: 1 GB = 10^9 bytes) -> bytes; at least 1 MB.
std::uint64_t parseStoreLimit(const std::string& text, const Arguments& a) {
    std::string digits = text;
    std::uint64_t unit = 1;
    for (const auto& [suffix, factor] : {std::pair{"GB", 1000000000ULL}, {"MB", 1000000ULL}}) {
        const std::string s = suffix;
        if (digits.size() > s.size() && digits.ends_with(s)) {
            digits.resize(digits.size() - s.size());
            unit = factor;
        }
    }
    if (digits.empty() || digits.size() > 12 ||
        digits.find_first_not_of("0123456789") != std::string::npos) {
        a.fail("--store-limit takes BYTES, NMB or NGB, not '" + text + "'");
    }
    const std::uint64_t bytes = std::stoull(digits) * unit;
    if (bytes < 1000000ULL) {
        a.fail("--store-limit must be at least 1MB");
    }
    return bytes;
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
            o.me.timeouts.responseSeconds = parseWholeNumber(a.value(), "--timeout", 1, 3600);
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
            o.storeLimit = parseStoreLimit(a.value(), a);
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
        pacs::ListenerConfig config;
        config.aeTitle = o.me.aeTitle;
        config.port = o.port;
        config.allowedPeers = {*o.node};
        config.bindAddress = o.bind;
        config.timeouts = o.me.timeouts;
        config.tls = o.tls;
        const pacs::StorageScp listener(store, config);
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
    pacs::ListenerConfig config;
    config.aeTitle = o.me.aeTitle;
    config.port = o.port;
    config.allowedPeers = o.allowed;
    config.bindAddress = o.bind;
    config.timeouts = o.me.timeouts;
    config.tls = o.tls;
    gStop = 0;
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
    {
        const pacs::StorageScp listener(store, config);
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
