// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/SendJob.h"

#include "vv/core/Error.h"
#include "vv/dicom/Dicom.h"
#include "vv/dicom/DicomSegWriter.h"
#include "vv/pacs/PacsError.h"

namespace vv::gui {
namespace {

constexpr double kSegmentationStart = kReportShare * 0.8;  ///< the SEG after the report

/// Writes `request.segmentation` as a SEG into the study of the series the
/// report's source names (its patient, study and frame of reference).
void writeSegmentation(const SendRequest& request, const std::filesystem::path& file,
                       const Progress& progress) {
    const report::ReportSource& source = request.report.source;
    const dicom::DicomScanResult scan = dicom::scanDicom(source.dicomPath, progress);
    for (const dicom::DicomPatient& patient : scan.patients) {
        for (const dicom::DicomStudy& study : patient.studies) {
            for (const dicom::DicomSeries& series : study.series) {
                if (!source.seriesInstanceUid.empty() &&
                    series.seriesInstanceUid != source.seriesInstanceUid) {
                    continue;
                }
                dicom::ExportStudy target;
                target.studyInstanceUid = study.studyInstanceUid;
                target.studyDate = study.date;
                target.patient = dicom::ExportPatient{};
                target.patient->name = patient.name;
                target.patient->id = patient.id;
                dicom::ExportSeries written;
                written.description = "VesselView segmentation";
                written.seriesNumber = 901;
                written.softwareVersion = request.softwareVersion;
                (void)dicom::writeDicomSeg(file, *request.segmentation, target,
                                           series.frameOfReferenceUid, written);
                return;
            }
        }
    }
    throw FormatError(source.dicomPath, "the segmented series is no longer there");
}

}  // namespace

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
    if (request.measurementReport) {
        if (job.measurementGroups.empty()) {
            throw InvalidArgumentError("no measurements to send: find the centrelines first");
        }
        job.outputs.dicomSr = request.folder / "measurements-sr.dcm";
        outcome.items.push_back({SendKind::MeasurementReport, job.outputs.dicomSr});
    }
    if (request.segmentation) {
        outcome.items.push_back({SendKind::Segmentation, request.folder / "segmentation.dcm"});
    }
    if (outcome.items.empty()) {
        throw InvalidArgumentError("nothing to send: choose the report or the segmentation");
    }
    if (request.secondaryCapture || request.encapsulatedPdf || request.measurementReport) {
        (void)report::runReportJob(renderer, scene, job, progress.sub(0.0, kSegmentationStart));
    }
    if (request.segmentation) {
        writeSegmentation(request, outcome.items.back().file,
                          progress.sub(kSegmentationStart, kReportShare));
    }
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
