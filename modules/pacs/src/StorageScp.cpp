// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/pacs/StorageScp.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmnet/diutil.h>
#include <dcmtk/dcmnet/scpthrd.h>

#include <algorithm>
#include <mutex>
#include <optional>
#include <set>
#include <system_error>
#include <utility>

#include "AcceptorNetwork.h"
#include "Association.h"
#include "AssociationPool.h"
#include "ConnectionBudget.h"
#include "ConnectionGate.h"
#include "DatasetFields.h"
#include "ListenSocket.h"
#include "ReceiveInstance.h"
#include "RefusalLog.h"
#include "Tls.h"
#include "vv/core/Error.h"
#include "vv/core/Log.h"

namespace vv::pacs {

namespace {

constexpr log::Category kLog("vv.pacs");
/// The largest PDU we receive (the peer's data comes in PDUs of at most this).
constexpr long kMaxReceivePdu = 65536;

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(' ');
    const auto e = s.find_last_not_of(' ');
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

/// The counters, shared by the gate, the workers and stats().
class Book {
  public:
    void add(std::size_t ListenerStats::*counter, std::size_t n = 1) {
        const std::lock_guard lock(mutex_);
        stats_.*counter += n;
    }
    [[nodiscard]] ListenerStats stats() const {
        const std::lock_guard lock(mutex_);
        return stats_;
    }

  private:
    mutable std::mutex mutex_;
    ListenerStats stats_;
};

/// One association on a worker: DCMTK's SCP with our decisions. Each
/// association is one store transaction.
class Scp : public DcmThreadSCP {
  public:
    Scp(LocalStore& store, const ListenerConfig& config, Book& book, std::string address,
        T_ASC_Association* association)
        : store_(store),
          config_(config),
          book_(book),
          callingHost_(std::move(address)),
          association_(association) {}

  protected:
    void notifyAssociationRequest(const T_ASC_Parameters& params,
                                  DcmSCPActionType& action) override {
        callingAe_ = trimmed(params.DULparams.callingAPTitle);
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
        book_.add(&ListenerStats::acceptedAssociations);
    }
    void notifyReleaseRequest() override {
        if (transaction_ && !overCap_) {
            const std::size_t n = transaction_->size();
            try {
                transaction_->commit();
                book_.add(&ListenerStats::committedInstances, n);
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
        if (request.DataSetType == DIMSE_DATASET_NULL) {
            return DIMSE_BADMESSAGE;
        }
        Uint16 status = STATUS_Success;
        const OFCondition cond = receive(request, info.presentationContextID, status);
        if (cond.bad()) {
            return cond;  // the association is broken: DCMTK aborts it, finish() discards
        }
        return sendSTOREResponse(info.presentationContextID, request, status);
    }

  private:
    [[nodiscard]] bool allowed() const {
        return std::any_of(config_.allowedPeers.begin(), config_.allowedPeers.end(),
                           [this](const Node& node) {
                               return node.aeTitle == callingAe_ && node.host == callingHost_;
                           });
    }
    [[nodiscard]] std::string peer() const { return callingAe_ + "@" + callingHost_; }
    void refuse(const std::string& why) {
        log::warning(kLog, "refused an association from " + peer() + ": " + why);
        book_.add(&ListenerStats::refusedAssociations);
    }
    void refuseInstance(const std::string& why) {
        log::warning(kLog, "refused an instance from " + peer() + ": " + why);
        book_.add(&ListenerStats::refusedInstances);
    }
    void finish() {
        const bool incomplete = transaction_ && (transaction_->size() > 0 || overCap_);
        transaction_.reset();  // removes what it staged, before the counters say so
        if (incomplete) {
            book_.add(&ListenerStats::discardedAssociations);
            log::warning(kLog, "discarded an incomplete transfer from " + peer());
        }
        overCap_ = false;
    }

    /// Receives the dataset of `request` into the transaction; sets the
    /// C-STORE status. A bad condition: the network failed.
    OFCondition receive(T_DIMSE_C_StoreRQ& request, T_ASC_PresentationContextID presId,
                        Uint16& status) {
        const ListenerLimits& limits = config_.limits;
        const int timeout = config_.timeouts.responseSeconds;
        if (!transaction_ || overCap_) {
            DIC_UL bytes = 0;
            DIC_UL pdvs = 0;
            const OFCondition cond =
                DIMSE_ignoreDataSet(association_, DIMSE_NONBLOCKING, timeout, &bytes, &pdvs);
            status = STATUS_STORE_Refused_OutOfResources;
            book_.add(&ListenerStats::refusedInstances);
            return cond;
        }
        const std::uint64_t associationLeft = limits.maxAssociationBytes - bytes_;
        const bool associationBinds = associationLeft < limits.maxInstanceBytes;
        const std::filesystem::path path = transaction_->stagingPath();
        detail::ReceivedInstance got;
        const OFCondition cond = detail::receiveInstance(
            association_, request, presId, path, std::min(limits.maxInstanceBytes, associationLeft),
            timeout, got);
        if (cond.bad()) {
            return cond;
        }
        bytes_ += got.bytes;
        status = STATUS_STORE_Refused_OutOfResources;
        switch (got.outcome) {
            case detail::ReceivedInstance::Outcome::OverCap:
                if (associationBinds) {
                    overCap_ = true;
                    refuseInstance("the association is over its cap of " +
                                   std::to_string(limits.maxAssociationBytes) +
                                   " bytes; it is refused and discarded");
                } else {
                    refuseInstance("over the cap of " + std::to_string(limits.maxInstanceBytes) +
                                   " bytes per instance");
                }
                return EC_Normal;
            case detail::ReceivedInstance::Outcome::WriteFailed:
                refuseInstance("it cannot be written to the study store");
                return EC_Normal;
            case detail::ReceivedInstance::Outcome::Stored:
                break;
        }
        try {
            transaction_->add(path, detail::fieldsOfFile(path, request.AffectedSOPInstanceUID,
                                                         request.AffectedSOPClassUID));
            status = STATUS_Success;
        } catch (const Error& e) {  // unreadable, not as announced, a malformed UID
            std::error_code ec;
            std::filesystem::remove(path, ec);
            status = STATUS_STORE_Error_CannotUnderstand;
            refuseInstance(e.problem());
        }
        return EC_Normal;
    }

    LocalStore& store_;
    const ListenerConfig& config_;
    Book& book_;
    std::string callingAe_;
    std::string callingHost_;  ///< the peer's IP address, as the gate accepted it
    T_ASC_Association* association_;
    std::optional<LocalStore::Transaction> transaction_;
    std::uint64_t bytes_ = 0;
    bool overCap_ = false;
};

/// The hosts of the allowed peers.
std::set<std::string> nodeAddresses(const ListenerConfig& config) {
    std::set<std::string> hosts;
    for (const Node& node : config.allowedPeers) {
        hosts.insert(node.host);
    }
    return hosts;
}

}  // namespace

void ListenerLimits::validate() const {
    const auto need = [](bool ok, const std::string& what) {
        if (!ok) {
            throw InvalidArgumentError("listener limits: " + what);
        }
    };
    need(maxAssociations >= 1 && maxAssociations <= kMaxAssociations,
         "simultaneous associations must be 1 to " + std::to_string(kMaxAssociations) + ", not " +
             std::to_string(maxAssociations));
    need(maxConnections >= maxAssociations && maxConnections <= kMaxConnections,
         "connections in all must be " + std::to_string(maxAssociations) +
             " (the simultaneous associations) to " + std::to_string(kMaxConnections) + ", not " +
             std::to_string(maxConnections));
    need(maxConnectionsPerAddress >= 1 && maxConnectionsPerAddress <= maxConnections,
         "connections per address must be 1 to " + std::to_string(maxConnections) +
             " (the connections in all), not " + std::to_string(maxConnectionsPerAddress));
    need(requestSeconds >= 1 && requestSeconds <= kMaxRequestSeconds,
         "the association request deadline must be 1 to " + std::to_string(kMaxRequestSeconds) +
             " s, not " + std::to_string(requestSeconds));
    need(maxInstanceBytes >= kMinInstanceBytes,
         "the largest instance must be at least " + std::to_string(kMinInstanceBytes) + " bytes");
    need(maxAssociationBytes >= maxInstanceBytes,
         "the largest association must be at least the largest instance");
}

struct StorageScp::Impl {
    Impl(LocalStore& storeIn, ListenerConfig configIn)
        : store(storeIn),
          config(std::move(configIn)),
          budget({config.limits.maxConnectionsPerAddress, config.limits.maxConnections,
                  ListenerLimits::kStrangerConnectionsPerAddress,
                  ListenerLimits::kStrangerConnections},
                 nodeAddresses(config)) {}

    void serve(detail::ReadyConnection&& connection,
               const std::shared_ptr<detail::AbortSwitch>& abortSwitch);
    void refuseBusy(detail::ReadyConnection&& connection);

    LocalStore& store;
    const ListenerConfig config;
    Book book;
    detail::RefusalLog refusals;
    detail::ConnectionBudget budget;
    DcmSharedSCPConfig scpConfig;
    std::unique_ptr<detail::TimedTlsLayer> tls;        ///< outlives the network
    std::unique_ptr<detail::AcceptorNetwork> network;  ///< outlives the pool and the gate
    std::unique_ptr<detail::AssociationPool> pool;     ///< outlives the gate (it offers to it)
    std::unique_ptr<detail::ConnectionGate> gate;      ///< stops first
};

void StorageScp::Impl::serve(detail::ReadyConnection&& connection,
                             const std::shared_ptr<detail::AbortSwitch>& abortSwitch) {
    const std::string address = connection.slot.address();
    T_ASC_Association* association = nullptr;
    const OFCondition cond =
        network->adopt(std::move(connection.socket), abortSwitch, kMaxReceivePdu, association);
    if (cond.bad()) {
        if (!(cond.module() == OFM_dcmnet &&
              cond.code() == DULC_TLSERROR)) {  // counted by the TLS layer
            book.add(&ListenerStats::droppedConnections);
            refusals.note("dropped a connection", address,
                          std::string("no valid association request (") + cond.text() + ")");
        }
        return;
    }
    Scp scp(store, config, book, address, association);
    scp.setSharedConfig(scpConfig);
    scp.run(association);  // negotiates, serves, and drops the association
}

void StorageScp::Impl::refuseBusy(detail::ReadyConnection&& connection) {
    book.add(&ListenerStats::refusedAssociations);
    refusals.note("refused an association", connection.slot.address(),
                  "all " + std::to_string(config.limits.maxAssociations) +
                      " associations the listener serves at once are busy");
    if (config.tls.enabled || !connection.requestBuffered) {
        connection.socket.reset();  // telling it so would wait on the peer
        return;
    }
    T_ASC_Association* association = nullptr;
    if (network
            ->adopt(std::move(connection.socket), std::make_shared<detail::AbortSwitch>(),
                    kMaxReceivePdu, association)
            .good()) {
        T_ASC_RejectParameters reject{ASC_RESULT_REJECTEDTRANSIENT,
                                      ASC_SOURCE_SERVICEPROVIDER_PRESENTATION_RELATED,
                                      ASC_REASON_SP_PRES_LOCALLIMITEXCEEDED};
        ASC_rejectAssociation(association, &reject);
        ASC_dropAssociation(association);
        ASC_destroyAssociation(&association);
    }
}

StorageScp::StorageScp(LocalStore& store, ListenerConfig config) {
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
    impl_ = std::make_unique<Impl>(store, std::move(config));
    Impl& impl = *impl_;
    const ListenerConfig& c = impl.config;
    if (c.tls.enabled) {
        impl.tls = std::make_unique<detail::TimedTlsLayer>(
            NET_ACCEPTOR, c.tls, c.limits.requestSeconds,
            [&impl](const std::string& host, const std::string& problem) {
                impl.book.add(&ListenerStats::refusedAssociations);
                impl.refusals.note("refused a connection", host,
                                   "TLS handshake failed (" + problem + ")");
            });
    }
    DcmSCPConfig& scp = *impl.scpConfig;
    scp.setAETitle(c.aeTitle.c_str());
    scp.setMaxReceivePDULength(static_cast<Uint32>(kMaxReceivePdu));
    scp.setACSETimeout(static_cast<Uint32>(c.timeouts.associateSeconds));
    scp.setDIMSEBlockingMode(DIMSE_NONBLOCKING);
    scp.setDIMSETimeout(static_cast<Uint32>(c.timeouts.responseSeconds));
    OFList<OFString> plain;
    plain.push_back(UID_LittleEndianExplicitTransferSyntax);
    plain.push_back(UID_LittleEndianImplicitTransferSyntax);
    scp.addPresentationContext(UID_VerificationSOPClass, plain);
    OFList<OFString> syntaxes;
    for (const char* ts : detail::receivableTransferSyntaxes()) {
        syntaxes.push_back(ts);
    }
    for (const char* sopClass : detail::usableStorageClasses()) {
        scp.addPresentationContext(sopClass, syntaxes);
    }
    detail::OwnedSocket listening = detail::openListenSocket(c.bindAddress, c.port);
    impl.network = std::make_unique<detail::AcceptorNetwork>(
        c.limits.requestSeconds, c.timeouts.responseSeconds, impl.tls.get());
    impl.pool = std::make_unique<detail::AssociationPool>(
        c.limits.maxAssociations, [&impl](detail::ReadyConnection&& connection,
                                          const std::shared_ptr<detail::AbortSwitch>& abortSwitch) {
            try {
                impl.serve(std::move(connection), abortSwitch);
            } catch (const std::exception& e) {
                log::error(kLog,
                           std::string("the listener could not serve an association: ") + e.what());
            }
        });
    impl.gate = std::make_unique<detail::ConnectionGate>(
        std::move(listening),
        detail::ConnectionGate::Settings{c.tls.enabled,
                                         std::chrono::seconds(c.limits.requestSeconds)},
        impl.budget, impl.refusals,
        detail::ConnectionGate::Counters{
            [&impl] { impl.book.add(&ListenerStats::refusedConnections); },
            [&impl] { impl.book.add(&ListenerStats::droppedConnections); }},
        [&impl](detail::ReadyConnection&& connection) {
            if (auto busy = impl.pool->offer(std::move(connection))) {
                impl.refuseBusy(std::move(*busy));
            }
        });
}

StorageScp::~StorageScp() {
    impl_->gate.reset();
    impl_->pool.reset();
}

ListenerStats StorageScp::stats() const {
    ListenerStats stats = impl_->book.stats();
    stats.openConnections = impl_->budget.open();
    stats.activeAssociations = impl_->pool->active();
    return stats;
}

}  // namespace vv::pacs
