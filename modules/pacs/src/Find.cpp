// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/pacs/Find.h"

#include <dcmtk/dcmdata/dcdeftag.h>

#include <algorithm>
#include <functional>
#include <utility>

#include "Association.h"
#include "vv/core/Error.h"
#include "vv/pacs/PacsError.h"
#include "vv/pacs/Uid.h"

namespace vv::pacs {

namespace {

/// Validates one matching key: no backslash (that would make it multi-valued).
void checkKey(const std::string& value, const char* name) {
    if (value.find('\\') != std::string::npos) {
        throw InvalidArgumentError(std::string(name) + " must not contain a backslash");
    }
    if (value.size() > 64) {
        throw InvalidArgumentError(std::string(name) + " is longer than 64 characters");
    }
}

void checkDate(const std::string& date, const char* name) {
    const bool ok = date.empty() ||
                    (date.size() == 8 && std::all_of(date.begin(), date.end(),
                                                     [](char c) { return c >= '0' && c <= '9'; }));
    if (!ok) {
        throw InvalidArgumentError(std::string(name) + " must be YYYYMMDD");
    }
}

/// Collects C-FIND answers through a handler and stops at the limits.
class FindScu : public detail::Scu {
  public:
    using Handler = std::function<void(DcmDataset&)>;
    FindScu(const FindLimits& limits, Handler handler)
        : limits_(limits), handler_(std::move(handler)) {}

    std::string problem;   ///< set when a limit was hit; the session was cancelled
    bool tooMany = false;  ///< the limit hit was maxResults
    Uint16 finalStatus = STATUS_Success;

    OFCondition handleFINDResponse(const T_ASC_PresentationContextID presID, QRResponse* response,
                                   OFBool& waitForNextResponse) override {
        waitForNextResponse = OFFalse;
        if (response == nullptr) {
            return EC_IllegalParameter;
        }
        if (response->m_status == STATUS_Pending ||
            response->m_status == STATUS_FIND_Pending_WarningUnsupportedOptionalKeys) {
            waitForNextResponse = OFTrue;
            if (++count_ > limits_.maxResults) {
                tooMany = true;
                problem = "more than " + std::to_string(limits_.maxResults) +
                          " matches; refine the query";
            } else if (response->m_dataset == nullptr) {
                problem = "a pending response without an identifier";
            } else {
                try {
                    handler_(*response->m_dataset);
                } catch (const ResponseError& e) {
                    problem = e.problem();
                }
            }
            if (!problem.empty()) {
                sendCANCELRequest(presID);
                waitForNextResponse = OFFalse;
            }
            return EC_Normal;
        }
        finalStatus = response->m_status;
        return EC_Normal;
    }

  private:
    FindLimits limits_;
    Handler handler_;
    std::size_t count_ = 0;
};

std::string text(DcmDataset& ds, const DcmTagKey& tag, const FindLimits& limits) {
    OFString value;
    if (ds.findAndGetOFStringArray(tag, value).bad()) {
        return {};
    }
    if (value.length() > limits.maxValueLength) {
        throw ResponseError("attribute " + std::string(DcmTag(tag).getTagName()) + " longer than " +
                            std::to_string(limits.maxValueLength) + " characters");
    }
    return std::string(value.c_str(), value.length());
}

int number(DcmDataset& ds, const DcmTagKey& tag, const FindLimits& limits) {
    const std::string value = text(ds, tag, limits);
    if (value.empty()) {
        return -1;
    }
    try {
        std::size_t used = 0;
        const int n = std::stoi(value, &used);
        return n >= 0 ? n : -1;
    } catch (const std::exception&) {
        throw ResponseError("attribute " + std::string(DcmTag(tag).getTagName()) +
                            " is not a number");
    }
}

std::string requiredUid(DcmDataset& ds, const DcmTagKey& tag, const FindLimits& limits) {
    std::string uid = text(ds, tag, limits);
    try {
        validateUid(uid);
    } catch (const InvalidArgumentError&) {
        throw ResponseError("a match without a valid " + std::string(DcmTag(tag).getTagName()));
    }
    return uid;
}

/// Runs one C-FIND with `keys` and hands each match to `handler`.
void runFind(const LocalAe& me, const Node& peer, DcmDataset& keys, const FindLimits& limits,
             std::stop_token stop, const FindScu::Handler& handler) {
    FindScu scu(limits, handler);
    detail::configure(scu, me, peer);
    scu.abortOn(std::move(stop));
    detail::propose(scu, UID_FINDStudyRootQueryRetrieveInformationModel);
    detail::open(scu, peer);
    const T_ASC_PresentationContextID id =
        detail::contextFor(scu, peer, UID_FINDStudyRootQueryRetrieveInformationModel);
    const OFCondition cond = scu.sendFINDRequest(id, &keys, nullptr);
    if (!scu.problem.empty()) {
        scu.abortAssociation();
        const std::string message = describe(peer) + ": C-FIND answer refused: " + scu.problem;
        if (scu.tooMany) {
            throw TooManyMatchesError(message, limits.maxResults);
        }
        throw ResponseError(message);
    }
    if (cond.bad()) {
        scu.throwIfStopped();
        detail::fail(cond, peer, "C-FIND");
    }
    detail::checkStatus(scu.finalStatus, peer, "C-FIND");
    detail::release(scu);
}

std::string dateRange(const std::string& from, const std::string& to) {
    if (from.empty() && to.empty()) {
        return {};
    }
    return from == to ? from : from + "-" + to;
}

}  // namespace

std::vector<StudyResult> findStudies(const LocalAe& me, const Node& peer, const StudyQuery& query,
                                     const FindLimits& limits, std::stop_token stop) {
    checkKey(query.patientName, "patient name");
    checkKey(query.patientId, "patient ID");
    checkKey(query.modality, "modality");
    checkKey(query.studyDescription, "study description");
    checkKey(query.accessionNumber, "accession number");
    checkDate(query.studyDateFrom, "study date from");
    checkDate(query.studyDateTo, "study date to");

    DcmDataset keys;
    keys.putAndInsertString(DCM_QueryRetrieveLevel, "STUDY");
    keys.putAndInsertString(DCM_StudyInstanceUID, "");
    keys.putAndInsertString(DCM_PatientName, query.patientName.c_str());
    keys.putAndInsertString(DCM_PatientID, query.patientId.c_str());
    keys.putAndInsertString(DCM_StudyDate,
                            dateRange(query.studyDateFrom, query.studyDateTo).c_str());
    keys.putAndInsertString(DCM_ModalitiesInStudy, query.modality.c_str());
    keys.putAndInsertString(DCM_StudyDescription, query.studyDescription.c_str());
    keys.putAndInsertString(DCM_AccessionNumber, query.accessionNumber.c_str());
    keys.putAndInsertString(DCM_NumberOfStudyRelatedSeries, "");

    std::vector<StudyResult> results;
    runFind(me, peer, keys, limits, std::move(stop), [&](DcmDataset& ds) {
        StudyResult r;
        r.studyInstanceUid = requiredUid(ds, DCM_StudyInstanceUID, limits);
        r.patientName = text(ds, DCM_PatientName, limits);
        r.patientId = text(ds, DCM_PatientID, limits);
        r.studyDate = text(ds, DCM_StudyDate, limits);
        r.studyDescription = text(ds, DCM_StudyDescription, limits);
        r.accessionNumber = text(ds, DCM_AccessionNumber, limits);
        r.modalitiesInStudy = text(ds, DCM_ModalitiesInStudy, limits);
        r.numberOfSeries = number(ds, DCM_NumberOfStudyRelatedSeries, limits);
        results.push_back(std::move(r));
    });
    return results;
}

std::vector<SeriesResult> findSeries(const LocalAe& me, const Node& peer, const SeriesQuery& query,
                                     const FindLimits& limits, std::stop_token stop) {
    validateUid(query.studyInstanceUid);
    checkKey(query.modality, "modality");
    checkKey(query.seriesDescription, "series description");

    DcmDataset keys;
    keys.putAndInsertString(DCM_QueryRetrieveLevel, "SERIES");
    keys.putAndInsertString(DCM_StudyInstanceUID, query.studyInstanceUid.c_str());
    keys.putAndInsertString(DCM_SeriesInstanceUID, "");
    keys.putAndInsertString(DCM_Modality, query.modality.c_str());
    keys.putAndInsertString(DCM_SeriesDescription, query.seriesDescription.c_str());
    keys.putAndInsertString(DCM_SeriesNumber, "");
    keys.putAndInsertString(DCM_NumberOfSeriesRelatedInstances, "");

    std::vector<SeriesResult> results;
    runFind(me, peer, keys, limits, std::move(stop), [&](DcmDataset& ds) {
        SeriesResult r;
        r.studyInstanceUid = query.studyInstanceUid;
        r.seriesInstanceUid = requiredUid(ds, DCM_SeriesInstanceUID, limits);
        r.modality = text(ds, DCM_Modality, limits);
        r.seriesDescription = text(ds, DCM_SeriesDescription, limits);
        r.seriesNumber = number(ds, DCM_SeriesNumber, limits);
        r.numberOfInstances = number(ds, DCM_NumberOfSeriesRelatedInstances, limits);
        results.push_back(std::move(r));
    });
    return results;
}

}  // namespace vv::pacs
