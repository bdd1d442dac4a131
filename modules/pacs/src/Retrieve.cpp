// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/pacs/Retrieve.h"

#include <dcmtk/dcmdata/dcdeftag.h>

#include <functional>
#include <optional>

#include "Association.h"
#include "DatasetFields.h"
#include "vv/core/Error.h"
#include "vv/pacs/PacsError.h"
#include "vv/pacs/Uid.h"

namespace vv::pacs {

namespace {

/// Progress reports from inside DCMTK's loops: never throws through DCMTK.
class Reporter {
  public:
    explicit Reporter(const Progress& progress) : progress_(progress) {}
    [[nodiscard]] bool stopped() const { return stopped_ || progress_.cancelled(); }
    void report(std::size_t done, std::size_t remaining) {
        const std::size_t total = done + remaining;
        try {
            progress_.report(total == 0 ? 0.0 : static_cast<double>(done) / total, "Retrieving");
        } catch (const CancelledError&) {
            stopped_ = true;
        }
    }

  private:
    const Progress& progress_;
    bool stopped_ = false;
};

void fillKeys(DcmDataset& keys, const RetrieveRequest& request) {
    validateUid(request.studyInstanceUid);
    keys.putAndInsertString(DCM_StudyInstanceUID, request.studyInstanceUid.c_str());
    if (request.seriesInstanceUid.empty()) {
        keys.putAndInsertString(DCM_QueryRetrieveLevel, "STUDY");
    } else {
        validateUid(request.seriesInstanceUid);
        keys.putAndInsertString(DCM_QueryRetrieveLevel, "SERIES");
        keys.putAndInsertString(DCM_SeriesInstanceUID, request.seriesInstanceUid.c_str());
    }
}

/// The last response's counts and status.
struct Outcome {
    Uint16 status = STATUS_Success;
    bool final = false;
    std::size_t completed = 0;
    std::size_t failed = 0;
    std::size_t warnings = 0;
    /// All sub-operations, as the last response that counted them said.
    std::optional<std::size_t> total;
    void take(const RetrieveResponse& r) {
        status = r.m_status;
        completed = r.m_numberOfCompletedSubops;
        failed = r.m_numberOfFailedSubops;
        warnings = r.m_numberOfWarningSubops;
        final = r.m_status != STATUS_Pending;
        if (!final) {  // remaining is only meaningful in pending responses
            total = completed + failed + warnings +
                    static_cast<std::size_t>(r.m_numberOfRemainingSubops);
        }
    }
};

/// Runs `step`, the part of a retrieve after its request went out: a
/// NetworkError it throws learns how far the transfer had come
/// (`received` instances, the outcome's total) before it goes on.
template <typename Step>
void duringTransfer(const Outcome& outcome, const std::function<std::size_t()>& received,
                    Step&& step) {
    try {
        step();
    } catch (NetworkError& e) {
        e.setTransfer({received(), outcome.total});
        throw;
    }
}

/// Throws for an outcome that is not a full success.
void checkOutcome(const Outcome& o, const Node& peer, const char* what) {
    if (!o.final) {
        // DCMTK's loop ended without the peer's last word: the connection went.
        throw ConnectionClosedError(describe(peer) + ": " + what +
                                    " ended without a final response (the connection closed)");
    }
    detail::checkStatus(o.status, peer, what);
    if (o.failed > 0 || o.status != STATUS_Success) {
        throw PeerFailedError(describe(peer) + ": " + what + ": " + std::to_string(o.failed) +
                              " instance(s) failed, " + std::to_string(o.warnings) +
                              " with warnings");
    }
}

class GetScu : public detail::Scu {
  public:
    GetScu(LocalStore::Transaction& transaction, Reporter& reporter)
        : transaction_(transaction), reporter_(reporter) {}

    Outcome outcome;
    std::optional<std::string> storeProblem;
    bool cancelled = false;

    OFCondition handleCGETResponse(const T_ASC_PresentationContextID /*presID*/,
                                   RetrieveResponse* response, OFBool& continueSession) override {
        continueSession = OFFalse;
        if (response == nullptr) {
            return EC_IllegalParameter;
        }
        outcome.take(*response);
        reporter_.report(transaction_.size(), response->m_numberOfRemainingSubops);
        continueSession = (!outcome.final && !stop()) ? OFTrue : OFFalse;
        return EC_Normal;
    }

    OFCondition handleSTORERequest(const T_ASC_PresentationContextID /*presID*/,
                                   DcmDataset* incoming, OFBool& continueSession,
                                   Uint16& status) override {
        // DcmSCU hands over the dataset: we delete it.
        std::unique_ptr<DcmDataset> dataset(incoming);
        continueSession = OFTrue;
        status = STATUS_Success;
        if (stop() || !dataset) {
            continueSession = OFFalse;
            status = STATUS_STORE_Refused_OutOfResources;
            return EC_Normal;
        }
        try {
            const std::filesystem::path path = transaction_.stagingPath();
            detail::writeInstance(*dataset, path);
            transaction_.add(path, detail::fieldsOf(*dataset));
        } catch (const Error& e) {
            storeProblem = e.what();
            status = STATUS_STORE_Refused_OutOfResources;
            continueSession = OFFalse;
        }
        return EC_Normal;
    }

  private:
    bool stop() {
        if (reporter_.stopped()) {
            cancelled = true;
        }
        return cancelled;
    }
    LocalStore::Transaction& transaction_;
    Reporter& reporter_;
};

class MoveScu : public detail::Scu {
  public:
    explicit MoveScu(Reporter& reporter) : reporter_(reporter) {}
    Outcome outcome;
    bool cancelled = false;

    OFCondition handleMOVEResponse(const T_ASC_PresentationContextID /*presID*/,
                                   RetrieveResponse* response, OFBool& waitForNext) override {
        waitForNext = OFFalse;
        if (response == nullptr) {
            return EC_IllegalParameter;
        }
        outcome.take(*response);
        reporter_.report(response->m_numberOfCompletedSubops, response->m_numberOfRemainingSubops);
        if (reporter_.stopped()) {
            cancelled = true;
        }
        waitForNext = (!outcome.final && !cancelled) ? OFTrue : OFFalse;
        return EC_Normal;
    }

  private:
    Reporter& reporter_;
};

}  // namespace

RetrieveResult getInto(LocalStore& store, const LocalAe& me, const Node& peer,
                       const RetrieveRequest& request, const Progress& progress) {
    DcmDataset keys;
    fillKeys(keys, request);
    LocalStore::Transaction transaction = store.begin();
    Reporter reporter(progress);
    GetScu scu(transaction, reporter);
    detail::configure(scu, me, peer);
    scu.abortOn(progress.stopToken());
    detail::propose(scu, UID_GETStudyRootQueryRetrieveInformationModel);
    for (const char* sopClass : detail::usableStorageClasses()) {
        OFList<OFString> syntaxes;
        for (const char* ts : detail::receivableTransferSyntaxes()) {
            syntaxes.push_back(ts);
        }
        scu.addPresentationContext(sopClass, syntaxes, ASC_SC_ROLE_SCP);
    }
    detail::open(scu, peer);
    const T_ASC_PresentationContextID id =
        detail::contextFor(scu, peer, UID_GETStudyRootQueryRetrieveInformationModel);
    const OFCondition cond = scu.sendCGETRequest(id, &keys, nullptr);
    if (scu.cancelled) {
        scu.abortAssociation();
        throw CancelledError();
    }
    if (scu.storeProblem) {
        scu.abortAssociation();
        throw IoError(*scu.storeProblem);
    }
    duringTransfer(
        scu.outcome, [&] { return transaction.size(); },
        [&] {
            if (cond.bad()) {
                scu.throwIfStopped();
                detail::fail(cond, peer, "C-GET");
            }
            checkOutcome(scu.outcome, peer, "C-GET");
        });
    detail::release(scu);
    const std::size_t received = transaction.size();
    transaction.commit();
    return {received};
}

RetrieveResult moveTo(const std::string& destination, const LocalAe& me, const Node& peer,
                      const RetrieveRequest& request, const Progress& progress) {
    validateAeTitle(destination);
    DcmDataset keys;
    fillKeys(keys, request);
    Reporter reporter(progress);
    MoveScu scu(reporter);
    detail::configure(scu, me, peer);
    scu.abortOn(progress.stopToken());
    detail::propose(scu, UID_MOVEStudyRootQueryRetrieveInformationModel);
    detail::open(scu, peer);
    const T_ASC_PresentationContextID id =
        detail::contextFor(scu, peer, UID_MOVEStudyRootQueryRetrieveInformationModel);
    const OFCondition cond = scu.sendMOVERequest(id, destination.c_str(), &keys, nullptr);
    if (scu.cancelled) {
        scu.abortAssociation();
        throw CancelledError();
    }
    duringTransfer(
        scu.outcome, [&] { return scu.outcome.completed; },
        [&] {
            if (cond.bad()) {
                scu.throwIfStopped();
                detail::fail(cond, peer, "C-MOVE");
            }
            checkOutcome(scu.outcome, peer, "C-MOVE");
        });
    detail::release(scu);
    return {scu.outcome.completed};
}

}  // namespace vv::pacs
