// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "common/SegmentationProvenance.h"
#include "gui/EngineTexts.h"
#include "gui/Session.h"
#include "vv/dicom/Dicom.h"
#include "vv/report/ReportJob.h"
#include "vv/scene/LabelMap.h"
#include "vv/scene/Mesh.h"
#include "vv/scene/Volume.h"
#include "vv/segmentation/SceneSource.h"

namespace vv::gui {

class MeshLoadTask;

/// What the main window shows, and how it gets there: "the document".
///
/// It owns the files being loaded and shown, the one load task
/// (MeshLoadTask: a new load abandons the one in progress, whose result then
/// never arrives), the DICOM scan that precedes the series chooser, the
/// session waiting for its files, the volume a DICOM scene was segmented
/// from, the shown series, the recent files (RecentFiles.h) and the last
/// error. It has no widgets and never touches the viewer or the panels: it
/// tells the window what to show through signals, which the window connects
/// directly (they are emitted in the order below, on the GUI thread):
///
///  - a load: loadStarted(), loadProgress()…, then one of
///    - volumeChanged(null), sceneChanged(), sessionReady() when a session
///      waited for these files, sceneShown(), volumeChanged(volume) for a
///      DICOM image series, recentFilesChanged(); sessionApplied() follows
///      from the event loop;
///    - failed() (the shown document stays);
///    - loadCancelled() (the shown document stays);
///    - seriesScanned() for openDicom(): the window shows the series chooser
///      and calls openSeries() with the user's choice;
///
///    and loadEnded() last.
///  - setScene() and showDerivedScene(): volumeChanged(null) (setScene only),
///    sceneChanged(), sceneShown() at once.
///
/// Message boxes and dialogs are the window's: failed() carries the title
/// and message to show, seriesScanned() the scan to choose from.
class DocumentController : public QObject {
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(DocumentController)

  public:
    explicit DocumentController(QObject* parent = nullptr);
    /// Cancels a load in progress (and waits for its worker).
    ~DocumentController() override;

    /// Loads `files` (one scene; empty names are ignored) on a worker. Paths
    /// that are DICOM sources load their only series with the modality's
    /// defaults (segmentation::isDicomSource).
    void openFiles(const QStringList& files);
    /// Reads the DICOM headers under `path` (a folder, a DICOMDIR or a DICOM
    /// file) on a worker, then seriesScanned(); a path without image series
    /// fails naming it and the number of files skipped.
    void openDicom(const QString& path);
    /// Loads the series of `path` chosen in the series chooser (after
    /// seriesScanned()), segmented with `options`. While it loads, the status
    /// bar names it `title` (SeriesDialog::seriesTitle(): what a clinician
    /// recognises the series by; the folder of a study store is only its UID;
    /// empty: after `path`); once loaded, the document is named by what the
    /// series says of itself (seriesName(), in the UI language).
    void openSeries(const QString& path, const segmentation::SceneSourceOptions& options,
                    const QString& title = {});
    /// Opens an entry of recentFiles() as it was opened: a series chosen in
    /// a folder (of several) is that series again, with the modality's
    /// defaults (openSeries()); anything else as openFiles(). A series no
    /// longer there fails as openSeries() does, naming the folder.
    void openRecent(const QString& file);
    /// The demo: findDemoFile() if there is one (not remembered in the recent
    /// files), else the demo tree generated on a worker.
    void openDemo();
    /// Reads the session at `path` (any supported version) and loads its
    /// files (DICOM: its series and segmentation, without the chooser, named
    /// by the session's series title when it has one — never by a folder
    /// that is only a UID);
    /// sessionReady() hands its camera, settings and layout over once they
    /// are shown. A session without files shows an empty document with it at
    /// once. Returns false after failed() when the session cannot be read;
    /// nothing changes then. A later load, a failure or a cancel drops the
    /// waiting session: it is never applied to other data.
    bool openSession(const QString& path);
    /// Writes `view` (the display settings, camera and layout the window
    /// captured; its files are ignored) with this document's files to `path`
    /// (.vvs, atomically). For a DICOM scene the series goes in too, and for
    /// a scene segmented from a volume the settings of the document's
    /// segmentation (loadedWith(): as loaded, or as last applied; never a
    /// preview's), so that the session reopens without asking what it
    /// shows, and its seriesTitle(). Returns false after failed() when
    /// writing fails.
    bool saveSession(const QString& path, Session view);
    /// Opens what was dropped: the first session file, else the mesh files,
    /// else the first folder or DICOM file (series chooser). False when none
    /// of `paths` can be opened (canOpen()).
    bool openDropped(const QStringList& paths);
    /// Whether openDropped() would open any of `paths`.
    [[nodiscard]] static bool canOpen(const QStringList& paths);

    /// Shows an already loaded scene (nullptr: nothing) named `title`: a
    /// document without files, series or volume. A load in progress goes on.
    void setScene(std::shared_ptr<const scene::Scene> scene, const QString& title);
    /// A scene derived from this document's data (the Segmentation panel's
    /// result, or its ray-cast display) in place of the shown one: files,
    /// title, series, volume and the applied segmentation stay. `preview`:
    /// the scene is a segmentation preview that was not applied
    /// (showsPreview()).
    void showDerivedScene(std::shared_ptr<const scene::Scene> scene, bool preview = false);
    /// The Segmentation panel applied a segmentation of volume(): `scene`
    /// (its surface at full resolution), `labelMap` and what made it become
    /// the document's segmentation — what the slice overlay, Export Surface,
    /// the report's slice page and Send to PACS (its DICOM SEG) use from now
    /// on. Emits segmentationApplied(); the scene is shown by
    /// showDerivedScene().
    /// `options` and `surface` (what the panel segmented with) become
    /// loadedWith()'s, which sessions save.
    void applySegmentation(std::shared_ptr<const scene::Scene> scene,
                           std::shared_ptr<const scene::LabelMap> labelMap,
                           app::SegmentationProvenance provenance,
                           const segmentation::SegmentationOptions& options,
                           const segmentation::SurfaceOptions& surface);
    /// True while the scene on screen is a segmentation preview that was not
    /// applied: it is never exported or sent (the window disables Export
    /// Surface, Export Report and Send to PACS until it is applied).
    [[nodiscard]] bool showsPreview() const noexcept { return preview_; }

    /// Asks the load in progress to stop (loadCancelled() follows unless its
    /// result was already delivered); false when nothing is loading.
    bool cancelLoad();
    [[nodiscard]] bool isLoading() const noexcept { return !task_.isNull(); }

    /// The scene on screen (null when none) and its title.
    [[nodiscard]] const std::shared_ptr<const scene::Scene>& scene() const noexcept {
        return scene_;
    }
    [[nodiscard]] const QString& title() const noexcept { return title_; }
    /// True when the scene on screen is the demo data (the bundled file or
    /// the generated tree, and what segmentation derived from it).
    [[nodiscard]] bool showsDemo() const noexcept { return demo_; }
    /// The files the user opened for the scene on screen, as given (the Data
    /// panel lists them; empty for the demo and for setScene()).
    [[nodiscard]] const QStringList& openedFiles() const noexcept { return openedFiles_; }
    /// The files the scene on screen was read from, absolute (the demo's file
    /// too): what sessions and reports name.
    [[nodiscard]] const QStringList& shownFiles() const noexcept { return shownFiles_; }
    /// The first of openedFiles() that is a DICOM source; empty if none.
    [[nodiscard]] QString dicomSource() const;
    /// The DICOM series shown (image series or SEG); empty for meshes.
    [[nodiscard]] const std::string& seriesUid() const noexcept { return seriesUid_; }
    /// The name of the shown DICOM series (seriesName() of what the loaded
    /// series says of itself, in the UI language); empty for files shown
    /// under their own names. Saved in sessions: their reopening names the
    /// series by it while it loads.
    [[nodiscard]] const QString& seriesTitle() const noexcept { return seriesTitle_; }
    /// The document's segmentation of volume(): the one the series was
    /// loaded with, or the last one applied (applySegmentation()); never a
    /// preview. The slice overlay, the report's slice page and the DICOM SEG
    /// sent to a PACS. Null without a volume.
    [[nodiscard]] const std::shared_ptr<const scene::LabelMap>& labelMap() const noexcept {
        return labelMap_;
    }
    /// The surface of the document's segmentation (the series as loaded, or
    /// the last applied segmentation; a SEG's segments), whatever the viewer
    /// shows (a preview, the ray-cast display); null for meshes.
    [[nodiscard]] const std::shared_ptr<const scene::Scene>& segmentedScene() const noexcept {
        return segmentedScene_;
    }
    /// What made segmentedScene(): the series and the settings (as loaded, or
    /// of the last Apply) with the cut-off vessels found.
    [[nodiscard]] const app::SegmentationProvenance& segmentation() const noexcept {
        return segmentation_;
    }
    /// What loading the shown DICOM series reported (its identity, the
    /// segmentation's range, correction, components and cut-off vessels)
    /// and the options it was loaded with; empty for meshes.
    [[nodiscard]] const segmentation::SceneSourceReport& loadedReport() const noexcept {
        return loadedReport_;
    }
    /// The options the shown DICOM series was loaded with, its segmentation
    /// and surface options those of the last applySegmentation() if any.
    [[nodiscard]] const segmentation::SceneSourceOptions& loadedWith() const noexcept {
        return loadedWith_;
    }
    /// The volume the shown scene was segmented from (a DICOM image series),
    /// kept for re-segmenting without reading the files; null otherwise.
    [[nodiscard]] const std::shared_ptr<const scene::Volume>& volume() const noexcept {
        return volume_;
    }
    /// Where the shown scene came from, for the report: the shown files and,
    /// for DICOM data, the path and series it was loaded from; for an image
    /// series the document's segmentation (its settings and cut-off warning).
    [[nodiscard]] report::ReportSource reportSource() const;
    /// The findings last entered for the data on screen (Export Report, Send
    /// to PACS), to start the next report with; empty once other data is
    /// shown (another file or series: findings belong to one patient's data).
    /// Kept in memory only.
    [[nodiscard]] QString findings() const;
    void setFindings(const QString& findings);
    /// The PDF report last exported for the data on screen (absolute path)
    /// and the findings in it, which Send to PACS offers to send as it is;
    /// empty once other data is shown, as findings().
    struct ExportedReport {
        QString pdf;
        QString findings;
    };
    [[nodiscard]] ExportedReport exportedReport() const;
    void setExportedReport(const ExportedReport& report);
    /// The message of the last error ("file: problem"); empty after a scene
    /// was shown.
    [[nodiscard]] const QString& lastError() const noexcept { return lastError_; }

    /// Recently opened files, most recent first (RecentFiles.h).
    [[nodiscard]] static QStringList recentFiles();
    void clearRecentFiles();

    /// The bundled demo file, when one exists: $VV_DEMO_FILE if set (even if
    /// missing, so the error names it), else <exe dir>/../resources/demo/
    /// vessel-tree.vtp, else <exe dir>/../share/vesselview/demo/vessel-tree.vtp.
    [[nodiscard]] static std::optional<QString> findDemoFile();
    /// File > Open's name filters, from meshio::supportedMeshExtensions().
    [[nodiscard]] static QString meshFileFilter();

  signals:
    /// A load started; `description` says what it does ("Loading tree.vtp").
    void loadStarted(const QString& description);
    /// `fraction` in [0, 1] of the load done; `status` is "description:
    /// stage", empty when the stage did not change.
    void loadProgress(double fraction, const QString& status);
    /// The load in progress ended (after its outcome's signals).
    void loadEnded();
    /// The load was cancelled; the shown document stays.
    void loadCancelled();
    /// Something could not be opened or saved: `title` for a message box,
    /// `problem` what went wrong (its line() is lastError()). The shown
    /// document stays.
    void failed(const QString& title, const vv::gui::ProblemText& problem);
    /// openDicom() read the headers under `path`: choose a series of `scan`
    /// and call openSeries().
    void seriesScanned(std::shared_ptr<const vv::dicom::DicomScanResult> scan, const QString& path);
    /// The document's scene changed: show `scene` (may be null) named `title`,
    /// opened from `files` (openedFiles()).
    void sceneChanged(std::shared_ptr<const vv::scene::Scene> scene, const QString& title,
                      const QStringList& files);
    /// A session's files are shown (sceneChanged() came first): apply its
    /// camera, display settings and layout. sessionApplied() follows.
    void sessionReady(const vv::app::Session& session);
    /// The document is on screen (after sceneChanged() and sessionReady()).
    void sceneShown();
    /// From the event loop after sessionReady() was handled.
    void sessionApplied();
    /// The volume behind the shown scene changed (null: none): `loadedWith`
    /// and `range` are the segmentation the scene was made with.
    void volumeChanged(const std::shared_ptr<const vv::scene::Volume>& volume,
                       const vv::segmentation::SceneSourceOptions& loadedWith,
                       const vv::segmentation::ThresholdRange& range);
    /// recentFiles() changed.
    void recentFilesChanged();
    /// applySegmentation() replaced labelMap(), segmentedScene() and segmentation().
    void segmentationApplied();

  private:
    /// Stops listening to the load in progress and cancels it (it deletes
    /// itself), dropping a waiting session; false when nothing was loading.
    bool abandonTask();
    /// Starts `task`, abandoning the one in progress and any waiting session;
    /// `opened` are the files as the user named them (title, recent files);
    /// `title`, when given, names the load in the status bar.
    void startTask(MeshLoadTask* task, const QStringList& opened, const QString& title = {});
    void taskLoaded(MeshLoadTask* task, const QStringList& opened,
                    std::shared_ptr<const scene::Scene> scene);
    void taskFinished(MeshLoadTask* task);
    /// Shows `scene` as the document; applies `session` to it when given.
    void show(std::shared_ptr<const scene::Scene> scene, const QString& title,
              std::optional<Session> session);
    void setVolume(std::shared_ptr<const scene::Volume> volume,
                   const segmentation::SceneSourceOptions& loadedWith,
                   const segmentation::ThresholdRange& range);
    void fail(const QString& title, const ProblemText& problem);

    QPointer<MeshLoadTask> task_;
    QPointer<MeshLoadTask> demoTask_;        ///< the load openDemo() started
    bool demo_ = false;                      ///< showsDemo()
    std::optional<Session> pendingSession_;  ///< applied once task_'s files are shown
    std::shared_ptr<const scene::Scene> scene_;
    QString title_;
    /// What findings_ were entered for (documentKey()).
    [[nodiscard]] QString documentKey() const;
    QString findings_;
    QString findingsFor_;
    ExportedReport exportedReport_;
    QString exportedReportFor_;
    QStringList openedFiles_;
    QStringList shownFiles_;
    std::string seriesUid_;
    QString seriesTitle_;  ///< seriesTitle()
    std::shared_ptr<const scene::Volume> volume_;
    std::shared_ptr<const scene::LabelMap> labelMap_;
    std::shared_ptr<const scene::Scene> segmentedScene_;
    app::SegmentationProvenance segmentation_;
    bool preview_ = false;
    segmentation::SceneSourceReport loadedReport_;
    segmentation::SceneSourceOptions loadedWith_;
    QString lastError_;
};

}  // namespace vv::gui
