// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <filesystem>
#include <memory>
#include <stop_token>
#include <vector>

#include "gui/EngineTexts.h"
#include "gui/WorkerRun.h"
#include "vv/scene/Mesh.h"
#include "vv/segmentation/SceneSource.h"

namespace vv::gui {

/// Loads mesh files (vv::meshio::loadScene), DICOM sources — a folder, a DICOMDIR
/// or a DICOM file, segmented into vessel surfaces (vv::segmentation::loadSceneSource)
/// — or generates the demo tree (vv::demo::generateDemoMesh) on a worker
/// thread, never on the GUI thread.
///
/// Progress arrives through progressChanged() (queued to the GUI thread,
/// throttled); exactly one of loaded() (scanned() for a
/// scanDicom task), failed() or cancelled() follows,
/// emitted on the GUI thread, then finished(). cancel() asks the worker to
/// stop at its next progress report (std::stop_source). The destructor
/// cancels and waits for the worker.
class MeshLoadTask : public QObject {
    Q_OBJECT

  public:
    /// A task that loads `files` into one scene, in order. Paths that are
    /// DICOM sources (vv::segmentation::isDicomSource) go through loadSceneSource()
    /// with `dicomOptions` (default: the only series, modality defaults);
    /// when there are none, the meshes load with loadScene() as one batch.
    static MeshLoadTask* loadFiles(std::vector<std::filesystem::path> files,
                                   QObject* parent = nullptr);
    static MeshLoadTask* loadFiles(std::vector<std::filesystem::path> files,
                                   segmentation::SceneSourceOptions dicomOptions, QObject* parent);
    /// A task that reads the DICOM headers under `path` (vv::dicom::scanDicom)
    /// and delivers them through scanned() instead of loaded().
    static MeshLoadTask* scanDicom(std::filesystem::path path, QObject* parent = nullptr);
    /// A task that generates the synthetic demo vessel tree.
    static MeshLoadTask* generateDemo(QObject* parent = nullptr);

    ~MeshLoadTask() override;

    /// Starts the worker; a second call does nothing.
    void start();
    /// Asks the worker to stop; cancelled() follows (unless the result was
    /// already delivered), and a result that arrives anyway is discarded.
    void cancel();
    [[nodiscard]] bool isRunning() const;

    /// What the task does, for the status bar ("Loading vessel.vtp").
    [[nodiscard]] const QString& description() const noexcept { return description_; }
    /// Names what it loads `name` in description() ("Loading Run-off CTA")
    /// instead of by its file (a series whose folder is only a UID).
    void describeAs(const QString& name);
    /// The files to load (empty for the demo).
    [[nodiscard]] const std::vector<std::filesystem::path>& files() const noexcept {
        return files_;
    }
    /// The DICOM options the task loads with.
    [[nodiscard]] const segmentation::SceneSourceOptions& dicomOptions() const noexcept {
        return dicomOptions_;
    }
    /// From loaded() on: what loading the last DICOM source did, with the
    /// volume an image series was segmented from (volume null for a DICOM
    /// SEG; all empty when only meshes were loaded).
    [[nodiscard]] const segmentation::SceneSourceReport& dicomReport() const noexcept {
        return dicomReport_;
    }

  signals:
    /// `fraction` in [0, 1] of the work done, and the current stage.
    void progressChanged(double fraction, const QString& stage);
    /// The DICOM headers are read (scanDicom tasks).
    void scanned(std::shared_ptr<const vv::dicom::DicomScanResult> scan);
    /// The scene is ready.
    void loaded(std::shared_ptr<const vv::scene::Scene> scene);
    /// Loading (or scanning) failed; `file` is the file concerned (may be empty), `problem` the
    /// reason (describeProblem()).
    void failed(const QString& file, const vv::gui::ProblemText& problem);
    void cancelled();
    /// After loaded(), scanned(), failed() or cancelled().
    void finished();

  private:
    struct Result {
        std::shared_ptr<const scene::Scene> scene;
        std::shared_ptr<const dicom::DicomScanResult> scan;
        segmentation::SceneSourceReport dicomReport;
        QString file;
        ProblemText problem;
        bool cancelled = false;
    };

    MeshLoadTask(std::vector<std::filesystem::path> files, bool demo,
                 segmentation::SceneSourceOptions dicomOptions, QObject* parent);
    [[nodiscard]] Result work(std::stop_token stop);
    void deliver();

    std::vector<std::filesystem::path> files_;
    bool demo_ = false;
    bool scan_ = false;
    segmentation::SceneSourceOptions dicomOptions_;
    segmentation::SceneSourceReport dicomReport_;
    QString description_;
    WorkerRun<Result> run_;  ///< last: waits for the worker before the members it reads go
};

}  // namespace vv::gui
