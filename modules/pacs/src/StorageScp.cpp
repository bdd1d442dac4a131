// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/pacs/StorageScp.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/diutil.h>
#include <dcmtk/dcmnet/scp.h>

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>

#include "Association.h"
#include "DatasetFields.h"
#include "ListenSocket.h"
#include "Tls.h"
#include "vv/core/Error.h"
#include "vv/core/Log.h"

namespace vv::pacs {

namespace {

constexpr log::Category kLog("vv.pacs");

/// "host:port" or "host" -> "host".
std::string hostOf(const char* presentationAddress) {
    std::string host = presentationAddress;
    const auto colon = host.rfind(':');
    if (colon != std::string::npos && host.find(':') == colon) {
        host.erase(colon);
    }
    return host;
}

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(' ');
    const auto e = s.find_last_not_of(' ');
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

class Scp : public DcmSCP {
  public:
    /// Called once: with "" when the socket is bound as configured, else the problem.
    using Started = std::function<void(const std::string& problem)>;

    Scp(LocalStore& store, const ListenerConfig& config, ListenerStats& stats, std::mutex& mutex,
        Started started)
        : store_(store),
          config_(config),
          stats_(stats),
          mutex_(mutex),
          started_(std::move(started)) {}

    std::atomic<bool> stopRequested{false};
    std::atomic<bool> listening{false};

  protected:
    OFCondition waitForAssociationRQ(T_ASC_Network* network) override {
        if (started_) {
            std::string problem;
            try {
                detail::rebindListenSocket(*network, config_.bindAddress, config_.port);
            } catch (const Error& e) {
                problem = e.problem();
                stopRequested = true;
            }
            Started started = std::move(started_);
            started_ = nullptr;
            started(problem);
            if (!problem.empty()) {
                return NET_EC_InvalidSCPAssociationProfile;
            }
        }
        return DcmSCP::waitForAssociationRQ(network);
    }

    void notifyAssociationRequest(const T_ASC_Parameters& params,
                                  DcmSCPActionType& action) override {
        callingAe_ = trimmed(params.DULparams.callingAPTitle);
        callingHost_ = hostOf(params.DULparams.callingPresentationAddress);
        action = DCMSCP_ACTION_UNDEFINED;
        if (!allowed()) {
            action = DCMSCP_ACTION_REFUSE_ASSOCIATION;
            refuse("not a configured node");
        }
    }
    OFBool checkCallingAETitleAccepted(const OFString& /*callingAE*/) override {
        return allowed() ? OFTrue : OFFalse;
    }
    OFBool checkCalledAETitleAccepted(const OFString& calledAE) override {
        if (trimmed(calledAE.c_str()) == config_.aeTitle) {
            return OFTrue;
        }
        refuse("called AE title \"" + trimmed(calledAE.c_str()) + "\" is not ours");
        return OFFalse;
    }
    void notifyAssociationAcknowledge() override {
        transaction_.emplace(store_.begin());
        bytes_ = 0;
        overCap_ = false;
        const std::lock_guard lock(mutex_);
        ++stats_.acceptedAssociations;
    }
    void notifyReleaseRequest() override {
        if (transaction_ && !overCap_) {
            const std::size_t n = transaction_->size();
            try {
                transaction_->commit();
                const std::lock_guard lock(mutex_);
                stats_.committedInstances += n;
                if (n > 0) {  // not for a C-ECHO
                    log::info(kLog, "stored " + std::to_string(n) + " instance(s) from " + peer());
                }
            } catch (const Error& e) {
                log::error(kLog, "cannot store what " + peer() + " sent: " + e.problem());
            }
        }
        finish();
    }
    void notifyAbortRequest() override { finish(); }
    void notifyAssociationTermination() override { finish(); }

    OFCondition handleIncomingCommand(T_DIMSE_Message* message,
                                      const DcmPresentationContextInfo& info) override {
        if (message->CommandField != DIMSE_C_STORE_RQ) {
            return DcmSCP::handleIncomingCommand(message, info);
        }
        T_DIMSE_C_StoreRQ& request = message->msg.CStoreRQ;
        DcmDataset* received = nullptr;
        const OFCondition cond = receiveSTORERequest(request, info.presentationContextID, received);
        std::unique_ptr<DcmDataset> dataset(received);
        if (cond.bad()) {
            return cond;
        }
        return sendSTOREResponse(info.presentationContextID, request, store(*dataset));
    }

    OFBool stopAfterConnectionTimeout() override { return stopRequested ? OFTrue : OFFalse; }
    OFBool stopAfterCurrentAssociation() override { return stopRequested ? OFTrue : OFFalse; }

  private:
    bool allowed() const {
        for (const Node& node : config_.allowedPeers) {
            if (node.aeTitle == callingAe_ && node.host == callingHost_) {
                return true;
            }
        }
        return false;
    }
    std::string peer() const { return callingAe_ + "@" + callingHost_; }
    void refuse(const std::string& why) {
        log::warning(kLog, "refused an association from " + peer() + ": " + why);
        const std::lock_guard lock(mutex_);
        ++stats_.refusedAssociations;
    }
    void finish() {
        const bool incomplete = transaction_ && transaction_->size() > 0;
        transaction_.reset();  // removes what it staged, before the counters say so
        if (incomplete) {
            const std::lock_guard lock(mutex_);
            ++stats_.discardedAssociations;
            log::warning(kLog, "discarded an incomplete transfer from " + peer());
        }
    }
    Uint16 store(DcmDataset& dataset) {
        if (!transaction_ || overCap_) {
            return STATUS_STORE_Refused_OutOfResources;
        }
        try {
            const std::filesystem::path path = transaction_->stagingPath();
            detail::writeInstance(dataset, path);
            bytes_ += std::filesystem::file_size(path);
            if (bytes_ > config_.limits.maxAssociationBytes) {
                overCap_ = true;
                log::warning(kLog, "refused the rest of an association from " + peer() +
                                       ": over the size cap");
                std::error_code ec;
                std::filesystem::remove(path, ec);
                return STATUS_STORE_Refused_OutOfResources;
            }
            transaction_->add(path, detail::fieldsOf(dataset));
            return STATUS_Success;
        } catch (const std::exception& e) {
            log::error(kLog, "cannot store an instance from " + peer() + ": " + e.what());
            return STATUS_STORE_Refused_OutOfResources;
        }
    }

    LocalStore& store_;
    const ListenerConfig& config_;
    ListenerStats& stats_;
    std::mutex& mutex_;
    Started started_;
    std::optional<LocalStore::Transaction> transaction_;
    std::string callingAe_;
    std::string callingHost_;
    std::size_t bytes_ = 0;
    bool overCap_ = false;
};

}  // namespace

void ListenerLimits::validate() const {
    const auto need = [](bool ok, const std::string& what) {
        if (!ok) {
            throw InvalidArgumentError("listener limits: " + what);
        }
    };
    need(maxAssociations >= 1 && maxAssociations <= 256,
         "simultaneous associations must be 1 to 256, not " + std::to_string(maxAssociations));
    need(maxConnections >= maxAssociations && maxConnections <= 1024,
         "connections in all must be " + std::to_string(maxAssociations) +
             " (the simultaneous associations) to 1024, not " + std::to_string(maxConnections));
    need(maxConnectionsPerAddress >= 1 && maxConnectionsPerAddress <= maxConnections,
         "connections per address must be 1 to " + std::to_string(maxConnections) +
             " (the connections in all), not " + std::to_string(maxConnectionsPerAddress));
    need(requestSeconds >= 1 && requestSeconds <= 120,
         "the association request deadline must be 1 to 120 s, not " +
             std::to_string(requestSeconds));
    need(maxInstanceBytes >= 1000, "the largest instance must be at least 1 kB");
    need(maxAssociationBytes >= maxInstanceBytes,
         "the largest association must be at least the largest instance");
}

struct StorageScp::Impl {
    ListenerConfig config;
    ListenerStats stats;
    mutable std::mutex mutex;
    std::unique_ptr<detail::TimedTlsLayer> tls;  ///< outlives scp (its network uses it)
    std::unique_ptr<Scp> scp;
    std::thread worker;
    std::mutex startMutex;
    std::condition_variable started;
    std::optional<std::string> startError;
    bool startDone = false;
};

StorageScp::StorageScp(LocalStore& store, ListenerConfig config) : impl_(std::make_unique<Impl>()) {
    validateAeTitle(config.aeTitle);
    config.limits.validate();
    if (config.port == 0) {
        throw InvalidArgumentError("the listener needs a port");
    }
    for (const Node& node : config.allowedPeers) {
        validateAeTitle(node.aeTitle);
    }
    detail::validateBindAddress(config.bindAddress);
    detail::quietDcmtk();
    impl_->config = std::move(config);
    Impl& impl = *impl_;
    const auto started = [&impl](const std::string& problem) {
        {
            const std::lock_guard lock(impl.startMutex);
            if (!problem.empty()) {
                impl.startError = problem;
            }
            impl.startDone = true;
        }
        impl.started.notify_all();
    };
    impl_->scp = std::make_unique<Scp>(store, impl_->config, impl_->stats, impl_->mutex, started);
    DcmSCPConfig& c = impl_->scp->getConfig();
    if (impl_->config.tls.enabled) {
        impl_->tls = std::make_unique<detail::TimedTlsLayer>(
            NET_ACCEPTOR, impl_->config.tls, impl_->config.timeouts.associateSeconds,
            [&impl](const std::string& host, const std::string& problem) {
                log::warning(kLog, "refused a connection from " + host +
                                       ": TLS handshake failed (" + problem + ")");
                const std::lock_guard lock(impl.mutex);
                ++impl.stats.refusedAssociations;
            });
        c.setTransportLayer(impl_->tls.get());
    }
    c.setAETitle(impl_->config.aeTitle.c_str());
    c.setPort(impl_->config.port);
    c.setHostLookupEnabled(OFFalse);
    c.setConnectionBlockingMode(DUL_NOBLOCK);
    c.setConnectionTimeout(1);
    c.setACSETimeout(static_cast<Uint32>(impl_->config.timeouts.associateSeconds));
    c.setDIMSEBlockingMode(DIMSE_NONBLOCKING);
    c.setDIMSETimeout(static_cast<Uint32>(impl_->config.timeouts.responseSeconds));
    OFList<OFString> plain;
    plain.push_back(UID_LittleEndianExplicitTransferSyntax);
    plain.push_back(UID_LittleEndianImplicitTransferSyntax);
    c.addPresentationContext(UID_VerificationSOPClass, plain);
    OFList<OFString> syntaxes;
    for (const char* ts : detail::receivableTransferSyntaxes()) {
        syntaxes.push_back(ts);
    }
    for (const char* sopClass : detail::usableStorageClasses()) {
        c.addPresentationContext(sopClass, syntaxes);
    }

    impl.worker = std::thread([&impl, started] {
        const OFCondition cond = impl.scp->openListenPort();
        if (cond.bad()) {
            started("cannot listen on port " + std::to_string(impl.config.port) + ": " +
                    cond.text());
            return;
        }
        impl.scp->acceptAssociations();
    });
    std::unique_lock lock(impl.startMutex);
    impl.started.wait(lock, [&impl] { return impl.startDone; });
    if (impl.startError) {
        lock.unlock();
        impl.worker.join();
        throw IoError(*impl.startError);
    }
}

StorageScp::~StorageScp() {
    impl_->scp->stopRequested = true;
    if (impl_->worker.joinable()) {
        impl_->worker.join();
    }
}

ListenerStats StorageScp::stats() const {
    const std::lock_guard lock(impl_->mutex);
    return impl_->stats;
}

}  // namespace vv::pacs
