// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The work behind DICOM > Send to PACS…, run on an ExportWorker: make the
// report's DICOM outputs in a folder, then C-STORE them to a node.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/pacs/Node.h"
#include "vv/pacs/Send.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/report/ReportJob.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Mesh.h"

namespace vv::gui {

/// One DICOM instance the job makes and sends.
enum class SendKind { SecondaryCapture, EncapsulatedPdf, Segmentation, MeasurementReport };

struct SendItem {
    SendKind kind;
    std::filesystem::path file;
};

/// How the network part failed; None when the node answered for every file.
enum class SendFailure { None, Refused, Rejected, Timeout, Tls, PeerFailed };

struct SendRequest {
    /// The report (view, source, disclaimer, slice...); its outputs are set by the job.
    report::ReportJobOptions report;
    bool secondaryCapture = true;  ///< the view as DICOM Secondary Capture
    bool encapsulatedPdf = true;   ///< the PDF report as DICOM Encapsulated PDF
    /// The segmentation of a DICOM scene as DICOM SEG, in the source series'
    /// study and frame of reference (report.source names the series).
    std::shared_ptr<const scene::LabelMap> segmentation;
    /// The planning measurements (report.measurementGroups) as a DICOM TID
    /// 1500 Structured Report, in the source series' study when it has one.
    bool measurementReport = false;
    std::string softwareVersion;  ///< of the SEG's equipment module
    pacs::LocalAe me;
    pacs::Node node;
    std::filesystem::path folder;  ///< where the outputs are made (exists)
};

struct SendOutcome {
    std::vector<SendItem> items;             ///< what was made, in sending order
    std::vector<pacs::SendStatus> statuses;  ///< one per item unless failure != None
    SendFailure failure = SendFailure::None;
    std::string detail;  ///< the network error's message (peer, no patient data)
};

/// The share of the progress given to making the report (the rest: sending).
inline constexpr double kReportShare = 0.7;

/// Makes the chosen outputs of `request.report` for `scene` in
/// `request.folder` with `renderer` (of the calling thread) — and the SEG,
/// after reading the source series' headers for its study — and sends them
/// to `request.node` in one association. A network failure is returned in
/// the outcome (failure, detail), never thrown. Throws InvalidArgumentError
/// when nothing is chosen, what report::runReportJob throws, what
/// dicom::scanDicom / writeDicomSeg throw, FormatError when the source series
/// is not found or from sending, and CancelledError.
[[nodiscard]] SendOutcome runSendJob(render::OffscreenRenderer& renderer, const scene::Scene& scene,
                                     const SendRequest& request, const Progress& progress);

}  // namespace vv::gui
