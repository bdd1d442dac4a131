// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// C-FIND (Study Root Query/Retrieve) at study and series level. Results are
// plain structs; the peer's answers are held to limits, so a malformed or
// huge response is a ResponseError, never a crash or unbounded memory.

#include <cstddef>
#include <stop_token>
#include <string>
#include <vector>

#include "vv/pacs/Node.h"
#include "vv/pacs/StudyFields.h"

namespace vv::pacs {

/// Study-level matching keys; empty = any. DICOM matching: `patientName`,
/// `patientId`, `studyDescription` may hold * and ? wildcards; dates are
/// YYYYMMDD (an open end stays empty).
struct StudyQuery {
    std::string patientName;
    std::string patientId;
    std::string studyDateFrom;
    std::string studyDateTo;
    std::string modality;  ///< one modality, matched against Modalities in Study
    std::string studyDescription;
    std::string accessionNumber;
};

struct StudyResult : StudyFields {
    std::string modalitiesInStudy;  ///< backslash-separated, as sent
    int numberOfSeries = -1;        ///< -1 when the peer did not say
};

/// Series-level matching keys within one study.
struct SeriesQuery {
    std::string studyInstanceUid;  ///< required
    std::string modality;
    std::string seriesDescription;
};

struct SeriesResult {
    std::string studyInstanceUid;
    std::string seriesInstanceUid;
    std::string modality;
    std::string seriesDescription;
    int seriesNumber = -1;       ///< -1 when absent
    int numberOfInstances = -1;  ///< -1 when the peer did not say
};

/// What a C-FIND answer may be at most.
struct FindLimits {
    std::size_t maxResults = 2000;     ///< more matches: ResponseError (refine the query)
    std::size_t maxValueLength = 256;  ///< characters of one returned attribute
};

/// Finds the studies matching `query` on `peer`. A stop of `stop` (from any
/// thread) aborts the association at once and throws CancelledError (the TCP
/// connect itself runs to its own timeout first). Throws InvalidArgumentError
/// for a malformed key (backslash, a date not YYYYMMDD), the NetworkError
/// family (vv/pacs/PacsError.h) for connection and peer failures, and
/// ResponseError when the answer exceeds `limits` or lacks a Study Instance UID
/// (TooManyMatchesError, a ResponseError, for more than limits.maxResults matches).
std::vector<StudyResult> findStudies(const LocalAe& me, const Node& peer, const StudyQuery& query,
                                     const FindLimits& limits = {}, std::stop_token stop = {});

/// Finds the series of one study; the stop and errors as findStudies
/// (InvalidArgumentError also for an empty or malformed Study Instance UID).
std::vector<SeriesResult> findSeries(const LocalAe& me, const Node& peer, const SeriesQuery& query,
                                     const FindLimits& limits = {}, std::stop_token stop = {});

}  // namespace vv::pacs
