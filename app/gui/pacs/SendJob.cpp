// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/SendJob.h"

#include "vv/core/Error.h"
#include "vv/pacs/PacsError.h"

namespace vv::gui {

SendOutcome runSendJob(render::OffscreenRenderer& renderer, const scene::Scene& scene,
                       const SendRequest& request, const Progress& progress) {
    SendOutcome outcome;
    report::ReportJobOptions job = request.report;
    job.outputs = {};
    if (request.secondaryCapture) {
        job.outputs.dicomSc = request.folder / "report-image.dcm";
        outcome.items.push_back({SendKind::SecondaryCapture, job.outputs.dicomSc});
    }
    if (request.encapsulatedPdf) {
        job.outputs.dicomPdf = request.folder / "report-pdf.dcm";
        outcome.items.push_back({SendKind::EncapsulatedPdf, job.outputs.dicomPdf});
    }
    if (outcome.items.empty()) {
        throw InvalidArgumentError("nothing to send: choose the report image or the PDF");
    }
    (void)report::runReportJob(renderer, scene, job, progress.sub(0.0, kReportShare));
    std::vector<std::filesystem::path> files;
    for (const SendItem& item : outcome.items) {
        files.push_back(item.file);
    }
    const auto failed = [&outcome](SendFailure failure, const std::exception& e) {
        outcome.failure = failure;
        outcome.detail = e.what();
    };
    try {
        outcome.statuses =
            pacs::sendFiles(request.me, request.node, files, progress.sub(kReportShare, 1.0));
    } catch (const pacs::ConnectionRefusedError& e) {
        failed(SendFailure::Refused, e);
    } catch (const pacs::AssociationRejectedError& e) {
        failed(SendFailure::Rejected, e);
    } catch (const pacs::TimeoutError& e) {
        failed(SendFailure::Timeout, e);
    } catch (const pacs::TlsError& e) {
        failed(SendFailure::Tls, e);
    } catch (const pacs::NetworkError& e) {
        failed(SendFailure::PeerFailed, e);
    }
    return outcome;
}

}  // namespace vv::gui
