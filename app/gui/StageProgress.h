// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <functional>
#include <stop_token>

#include "vv/core/Progress.h"

namespace vv::gui {

/// A Progress for an engine call on a worker thread (the GUI's tasks:
/// SegmentationTask, AnalysisTask): `report(fraction, stage)` with the
/// fraction clamped to [0, 1] and the stage in the UI language
/// (translatedStage()), at most every 50 ms per stage (a new stage at
/// once), called from whichever thread reports (serialised); stopped
/// through `stop`. `report` typically emits a queued signal.
[[nodiscard]] Progress stageProgress(std::function<void(double, const QString&)> report,
                                     std::stop_token stop);

}  // namespace vv::gui
