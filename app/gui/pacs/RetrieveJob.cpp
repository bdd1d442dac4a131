// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/RetrieveJob.h"

#include <chrono>
#include <optional>
#include <thread>

#include "vv/core/Progress.h"
#include "vv/pacs/LocalStore.h"

namespace vv::gui {

namespace {

/// The folder of what `request` names once the store holds it complete with
/// at least `instances` instances (series) or the study at all.
std::optional<std::filesystem::path> storedFolder(const pacs::LocalStore& store,
                                                  const pacs::RetrieveRequest& request,
                                                  std::size_t instances) {
    for (const pacs::StoredStudy& study : store.studies()) {
        if (study.studyInstanceUid != request.studyInstanceUid) {
            continue;
        }
        std::size_t total = 0;
        for (const pacs::StoredSeries& series : study.series) {
            total += static_cast<std::size_t>(series.instances);
            if (series.seriesInstanceUid == request.seriesInstanceUid) {
                return static_cast<std::size_t>(series.instances) >= instances
                           ? std::optional(series.folder)
                           : std::nullopt;
            }
        }
        if (!request.seriesInstanceUid.empty() || total < instances) {
            return std::nullopt;
        }
        return study.series.size() == 1 ? study.series.front().folder : study.folder;
    }
    return std::nullopt;
}

/// The instances of what `request` names that the store holds complete.
std::size_t storedInstances(const pacs::LocalStore& store, const pacs::RetrieveRequest& request) {
    std::size_t total = 0;
    for (const pacs::StoredStudy& study : store.studies()) {
        if (study.studyInstanceUid != request.studyInstanceUid) {
            continue;
        }
        for (const pacs::StoredSeries& series : study.series) {
            if (request.seriesInstanceUid.empty() ||
                series.seriesInstanceUid == request.seriesInstanceUid) {
                total += static_cast<std::size_t>(series.instances);
            }
        }
    }
    return total;
}

}  // namespace

RetrieveOutcome runRetrieve(const RetrieveJob& job, RetrieveControl& control) {
    RetrieveOutcome outcome;
    std::optional<pacs::LocalStore> opened;
    std::size_t before = 0;
    try {
        opened.emplace(openStore(job.settings));
        pacs::LocalStore& store = *opened;
        before = storedInstances(store, job.request);
        const pacs::LocalAe& me = job.settings.me;
        const Progress progress(
            [&control](double fraction, std::string_view) { control.fraction = fraction; },
            control.stop.get_token());
        const pacs::RetrieveResult result =
            job.move ? pacs::moveTo(me.aeTitle, me, job.node, job.request, progress)
                     : pacs::getInto(store, me, job.node, job.request, progress);
        outcome.instances = result.instances;
        // C-GET has committed when it returns; C-MOVE's instances arrive at our
        // listener, which commits when Orthanc releases its association.
        const auto deadline =
            std::chrono::steady_clock::now() + std::chrono::seconds(job.listenerWaitSeconds);
        std::optional<std::filesystem::path> folder =
            storedFolder(store, job.request, result.instances);
        while (job.move && !folder && std::chrono::steady_clock::now() < deadline) {
            progress.throwIfCancelled();
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
            folder = storedFolder(store, job.request, result.instances);
        }
        if (folder) {
            outcome.folder = *folder;
        } else {
            outcome.notStoredByListener = true;
        }
    } catch (...) {
        outcome.failure = classifyFailure(std::current_exception());
        // What the failed transfer left in the store, so that its message
        // is true: a C-GET's transaction is discarded; our listener commits
        // a C-MOVE's instances per association the peer released.
        try {
            if (opened) {
                const std::size_t after = storedInstances(*opened, job.request);
                outcome.kept = after > before ? after - before : 0;
            }
        } catch (const std::exception&) {
            outcome.kept.reset();  // the store cannot be read: unknown
        }
    }
    return outcome;
}

}  // namespace vv::gui
