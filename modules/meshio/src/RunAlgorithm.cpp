// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/meshio/vtkext/RunAlgorithm.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkSmartPointer.h>

#include <exception>
#include <mutex>
#include <new>

#include "vv/core/Error.h"
#include "vv/meshio/vtkext/VtkConvert.h"

namespace vv::meshio::detail {

namespace fs = std::filesystem;

namespace {

/// Filters that run in parallel (vtkSMPTools) may report progress from their
/// worker threads: the relay is locked.
struct ProgressRelay {
    std::mutex mutex;
    const Progress* progress = nullptr;
    vtkAlgorithm* algorithm = nullptr;
    double begin = 0.0;
    double end = 1.0;
    std::string stage;
    bool cancelled = false;
    std::exception_ptr error;
};

void onProgress(vtkObject* /*caller*/, unsigned long /*event*/, void* clientData, void* callData) {
    auto* relay = static_cast<ProgressRelay*>(clientData);
    if (relay == nullptr || callData == nullptr) {
        return;
    }
    const std::scoped_lock lock(relay->mutex);
    if (relay->cancelled || relay->error) {
        return;
    }
    const double fraction = *static_cast<const double*>(callData);
    try {
        relay->progress->report(relay->begin + (relay->end - relay->begin) * fraction,
                                relay->stage);
    } catch (const CancelledError&) {
        relay->cancelled = true;
        relay->algorithm->AbortExecuteOn();
    } catch (...) {
        // Exceptions must not cross VTK's C-style pipeline; rethrown after Update().
        relay->error = std::current_exception();
        relay->algorithm->AbortExecuteOn();
    }
}

}  // namespace

void runAlgorithm(vtkAlgorithm* algorithm, const fs::path& file, const std::string& what,
                  const Progress& progress, double begin, double end, const std::string& stage) {
    progress.throwIfCancelled();
    detail::VtkMessageCapture capture;
    capture.observe(algorithm);
    ProgressRelay relay;
    relay.progress = &progress;
    relay.algorithm = algorithm;
    relay.begin = begin;
    relay.end = end;
    relay.stage = stage;
    auto command = vtkSmartPointer<vtkCallbackCommand>::New();
    command->SetCallback(&onProgress);
    command->SetClientData(&relay);
    struct ObserverGuard {
        vtkAlgorithm* algorithm;
        unsigned long tag;
        ~ObserverGuard() { algorithm->RemoveObserver(tag); }
    } guard{algorithm, algorithm->AddObserver(vtkCommand::ProgressEvent, command)};
    int ok = 0;
    try {
        ok = algorithm->GetExecutive()->Update();
    } catch (const std::bad_alloc&) {
        throw FormatError(file, "not enough memory to read the " + what +
                                    " content (corrupt counts in the file?)");
    } catch (const std::exception& e) {
        throw FormatError(
            file, "cannot read the " + what + " content (corrupt file?): " + std::string(e.what()));
    }
    if (relay.error) {
        std::rethrow_exception(relay.error);
    }
    if (relay.cancelled || progress.cancelled()) {
        throw CancelledError();
    }
    if (ok == 0 || capture.hasErrors()) {
        std::string message = capture.summary();
        if (message.empty()) {
            message = "the reader failed without saying why";
        }
        throw FormatError(
            file, "cannot read the " + what + " content (corrupt or truncated?): " + message);
    }
}

}  // namespace vv::meshio::detail
