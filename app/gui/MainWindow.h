// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QList>
#include <QMainWindow>
#include <QSize>
#include <QString>
#include <QStringList>
#include <memory>
#include <optional>

#include "gui/DisplayPreset.h"
#include "gui/DocumentController.h"
#include "gui/MeasureTool.h"
#include "gui/Session.h"
#include "gui/SliceWorkspace.h"
#include "gui/ViewerWidget.h"
#include "gui/analysis/PlanningDocks.h"
#include "gui/analysis/PlanningReport.h"
#include "vv/report/ReportJob.h"
#include "vv/scene/Mesh.h"
#include "vv/scene/Volume.h"

class QAction;
class QComboBox;
class QDockWidget;
class QDoubleSpinBox;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QStackedWidget;

namespace vv::dicom {
struct DicomScanResult;
}  // namespace vv::dicom

namespace vv::gui {

class DicomMenu;
class CrossSectionView;
class CurvedReformation;
class DiameterProfile;
class ListenerService;
class PlanningOverlay;
class PlanningState;
class MeasureOverlay;
class ScreenshotMode;
class SeriesDialog;
class ViewerWidget;

namespace panels {
class AnalysisPanel;
class DataPanel;
class DisplayPanel;
class FunctionalPanel;
class SegmentationPanel;
class SidePanel;
class VssPanel;
}  // namespace panels

/// The main window: the 3-D viewer, File / View / DICOM / Help menus, a toolbar
/// (VSS on/off, ambient occlusion, colour-blind-safe mode), one side panel
/// (a dock, "sidePanelDock": panels::SidePanel) with the panels as sections
/// that fold ("Void Space Surface" and "Functional parameters" open at
/// first, "Display", "Data", "Segmentation" folded; which are open and the
/// dock's place are restored from QSettings), and a status bar with load
/// progress and Cancel.
///
/// What is shown and how it is opened — files, folders, sessions, recent
/// files, the load task, the last error — is the DocumentController's
/// (document()); the window forwards the calls below to it and shows what it
/// signals: the scene in the viewer and panels, progress in the status bar,
/// errors in a message box naming file and problem, the series chooser.
/// The viewer holds the settings: every control writes it and all controls
/// then show what it holds (syncControls()).
class MainWindow : public QMainWindow {
    Q_OBJECT

  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// What is shown and how it is opened (see the class comment).
    [[nodiscard]] DocumentController* document() const noexcept { return document_; }

    /// Loads `files` (one scene) on a worker; cancels a load in progress.
    void openFiles(const QStringList& files) { document_->openFiles(files); }
    /// File > Open Folder… and dropped folders / DICOM files: reads the DICOM
    /// headers under `path` (a folder, a DICOMDIR or a DICOM file) on a
    /// worker with progress and Cancel, then shows the series chooser
    /// (SeriesDialog, window-modal, not blocking; seriesDialogShown()) and,
    /// once accepted, loads the chosen series on a worker: segmented into
    /// vessel surfaces with the options chosen there. A path without any
    /// image series shows an error message naming it.
    void openDicom(const QString& path) { document_->openDicom(path); }
    /// Opens the demo: $VV_DEMO_FILE, else the bundled vessel-tree.vtp (build
    /// tree or installed), else generates it on a worker.
    void openDemo() { document_->openDemo(); }
    /// Says that the user interface is in English although another language
    /// was asked for (missingTranslation()): a message box (object name
    /// "languageProblemBox"; window-modal, not blocking; none in screenshot
    /// mode). The text is English: the translation is what is missing.
    void showLanguageProblem(const QString& note);
    /// Shows an already loaded scene (nullptr clears); `title` names it in the
    /// window title. Selects the default array (wss when present).
    void setScene(std::shared_ptr<const scene::Scene> scene, const QString& title) {
        document_->setScene(std::move(scene), title);
    }

    /// Screenshot mode: the default display settings (not the remembered
    /// ones; see ViewSettings.h); once data is shown, save the viewer's frame to `path`
    /// (PNG, written atomically) and quit the application with exit code 0,
    /// or 1 (message on stderr) when loading, rendering or saving fails.
    /// Message boxes are not shown in this mode.
    void setScreenshotTarget(const QString& path);

    /// The bundled demo file, when one exists: $VV_DEMO_FILE if set (even if
    /// missing, so the error names it), else <exe dir>/../resources/demo/
    /// vessel-tree.vtp, else <exe dir>/../share/vesselview/demo/vessel-tree.vtp.
    [[nodiscard]] static std::optional<QString> findDemoFile() {
        return DocumentController::findDemoFile();
    }

    /// The File > Open dialog's name filters, from supportedMeshExtensions().
    /// The window's first placement, before any saved geometry exists.
    struct FirstGeometry {
        QSize size;              ///< the (normal) client size
        bool maximized = false;  ///< whether the window opens maximized
    };
    /// 1280 x 800 where that window, with a window manager's frame around it
    /// (up to `kFrameAllowance`), fits into `available` (the screen's free
    /// area). On a smaller screen (1280 x 800, 1280 x 720) the window opens
    /// maximized, its normal size the free area less the frame allowance: a
    /// client of the whole free area put the title bar above it and the status
    /// bar below the screen's edge, and window managers then moved it down.
    /// An invalid `available` gives 1280 x 800, not maximized.
    [[nodiscard]] static FirstGeometry firstGeometry(const QSize& available);
    /// Room a window manager's frame (title bar and borders) takes at most.
    static constexpr QSize kFrameAllowance{16, 48};
    [[nodiscard]] static QString meshFileFilter() { return DocumentController::meshFileFilter(); }

    /// File > Save Session: the shown files, camera, display settings and
    /// panel layout to `path` (.vvs, written atomically). Returns false after
    /// showing an error (message box naming the file) when that fails.
    bool saveSessionTo(const QString& path);
    /// File > Open Session: reads `path` (any supported version), loads its
    /// files and then applies its camera and settings (sessionApplied()).
    /// Returns false after showing an error naming the file when the session
    /// cannot be read; nothing changes then.
    bool openSession(const QString& path) { return document_->openSession(path); }
    /// The files of the scene on screen (absolute; the demo's file too).
    [[nodiscard]] const QStringList& shownFiles() const noexcept { return document_->shownFiles(); }

    /// Recently opened files (most recent first, at most 8), from QSettings.
    [[nodiscard]] static QStringList recentFiles() { return DocumentController::recentFiles(); }

    [[nodiscard]] ViewerWidget* viewer() const noexcept { return viewer_; }
    /// The DICOM menu: network preferences and the PACS browser.
    [[nodiscard]] DicomMenu* dicomMenu() const noexcept { return dicomMenu_; }
    /// The central area: the 3-D viewer and, for DICOM scenes, the slice views.
    [[nodiscard]] SliceWorkspace* sliceWorkspace() const noexcept { return slices_; }
    /// The "Functional parameters" panel's array chooser (item 0 "None" with
    /// empty data, then the point arrays, data = array name) and colour map.
    [[nodiscard]] QComboBox* arrayChooser() const;
    [[nodiscard]] QComboBox* colorMapChooser() const;
    /// The VSS on/off toggle (toolbar and menu; checked = on), and the VSS
    /// panel's IDW power p and depth colour scale.
    [[nodiscard]] QAction* vssToggle() const noexcept { return vssAction_; }
    [[nodiscard]] QDoubleSpinBox* vssPowerBox() const;
    [[nodiscard]] QComboBox* depthScaleChooser() const;
    /// The depth cue on the vessels (Display panel; item data = VesselCue as int).
    [[nodiscard]] QComboBox* vesselCueChooser() const;
    /// View > Colour-Blind-Safe Mode (Ctrl+Shift+B; also on the toolbar):
    /// checking it applies colorBlindSafe() to the view, unchecking restores
    /// the depth scale, colour map and cue from before. It shows checked
    /// whenever the view is colour-blind safe (isColorBlindSafe()).
    [[nodiscard]] QAction* colorBlindSafeToggle() const noexcept { return cvdAction_; }
    [[nodiscard]] panels::VssPanel* vssPanel() const noexcept { return vssPanel_; }
    [[nodiscard]] panels::FunctionalPanel* functionalPanel() const noexcept {
        return functionalPanel_;
    }
    [[nodiscard]] panels::DisplayPanel* displayPanel() const noexcept { return displayPanel_; }
    [[nodiscard]] panels::DataPanel* dataPanel() const noexcept { return dataPanel_; }
    /// The "Segmentation" panel: re-segments volume() (disabled without one).
    [[nodiscard]] panels::SegmentationPanel* segmentationPanel() const noexcept {
        return segmentationPanel_;
    }
    /// The volume the shown scene was segmented from (a DICOM image series),
    /// kept for re-segmenting without reading the files; null otherwise.
    [[nodiscard]] const std::shared_ptr<const scene::Volume>& volume() const noexcept {
        return document_->volume();
    }
    /// The "Analysis" panel (centrelines, path, landmarks, measurements) and
    /// the planning work it shows (issue 35).
    [[nodiscard]] panels::AnalysisPanel* analysisPanel() const noexcept { return analysisPanel_; }
    [[nodiscard]] PlanningState* planning() const noexcept { return planning_; }
    /// The views along the chosen path, in a dock under the views
    /// ("diameterProfileDock", "Along the Path"), shown when an analysis
    /// arrives: the diameter profile, the curved reformation over it (scenes
    /// from an image series), the cross-section at the cursor beside them.
    [[nodiscard]] DiameterProfile* diameterProfile() const noexcept {
        return planningDocks_->profile();
    }
    [[nodiscard]] CurvedReformation* curvedReformation() const noexcept {
        return planningDocks_->reformation();
    }
    [[nodiscard]] CrossSectionView* crossSection() const noexcept {
        return planningDocks_->crossSection();
    }
    /// The planning marks over the 3-D view.
    [[nodiscard]] PlanningOverlay* planningOverlay() const noexcept {
        return planningDocks_->overlay();
    }
    [[nodiscard]] QDockWidget* diameterProfileDock() const noexcept {
        return planningDocks_->profileDock();
    }
    /// The measurement tables (AnalysisPanel::measurementTables()) in a dock
    /// beside it ("measurementsDock"), shown with the analysis.
    [[nodiscard]] QDockWidget* measurementsDock() const noexcept {
        return planningDocks_->measurementsDock();
    }
    /// The planning work for a report or a PACS (planningReport()); nullopt
    /// without an analysis, or when it cannot be put together (the status
    /// bar says why).
    [[nodiscard]] std::optional<PlanningReport> plannedReport();
    /// The side panel (scrolls vertically; its sections hold the panels).
    [[nodiscard]] panels::SidePanel* sidePanel() const noexcept { return sidePanel_; }
    /// Shows the side panel and opens and scrolls to the section holding
    /// `panel` (one of the panels above).
    void revealPanel(const QWidget* panel);
    /// View > Panels > Reset Layout: the side panel and its sections (which
    /// are open) as in a fresh window.
    void resetLayout();
    /// View > Reset to Defaults: the display settings of a fresh viewer
    /// (resetViewSettings()) and the default layout. Data, array and range stay.
    void resetToDefaults();
    /// Help > Keyboard Shortcuts: every menu action with a shortcut, and the
    /// mouse, as an HTML table.
    [[nodiscard]] QString shortcutSummary() const;
    /// Help > About: versions of VesselView, OpenGL, Qt, VTK and DCMTK (HTML).
    [[nodiscard]] QString aboutText() const;
    /// View > Show Legends (checked = legends drawn).
    [[nodiscard]] QAction* legendsToggle() const noexcept { return legendsAction_; }
    [[nodiscard]] QAction* smoothCoarseToggle() const noexcept { return smoothAction_; }
    /// The status bar's VSS quality: "VSS: preview", "VSS: exact, N ms", …
    [[nodiscard]] QLabel* vssQualityLabel() const noexcept { return vssLabel_; }
    [[nodiscard]] QLabel* smoothCopyLabel() const noexcept { return smoothLabel_; }
    /// View > Measure (M): while checked, left clicks on vessels pick points
    /// (Ctrl + click always does). Two picked points give their 3-D distance
    /// and depth difference in measureLabel(); a third click starts anew.
    [[nodiscard]] QAction* measureToggle() const noexcept { return measureAction_; }
    [[nodiscard]] QLabel* measureLabel() const noexcept { return measureLabel_; }
    /// The markers of the picked points over the viewer.
    [[nodiscard]] MeasureOverlay* measureOverlay() const noexcept { return measure_->overlay(); }
    /// The picked points of the measurement in progress (0, 1 or 2).
    [[nodiscard]] const QList<ProbeResult>& measurePoints() const noexcept {
        return measure_->points();
    }
    /// Adds a picked point (what a click on the viewer does).
    void addMeasurePoint(const ProbeResult& point) { measure_->addPoint(point); }
    void clearMeasurement() { measure_->clear(); }
    /// File > Export Image… (Ctrl+E) and File > Export Report… (Ctrl+Shift+E):
    /// open ExportImageDialog / ReportDialog; disabled, with a tooltip saying
    /// why, while no scene is shown.
    [[nodiscard]] QAction* exportImageAction() const noexcept { return exportImageAction_; }
    [[nodiscard]] QAction* exportReportAction() const noexcept { return exportReportAction_; }
    [[nodiscard]] QAction* exportSurfaceAction() const noexcept { return exportSurfaceAction_; }
    /// Where the shown scene came from, for the report: the shown files and,
    /// for DICOM data, the path and series it was loaded from.
    [[nodiscard]] report::ReportSource reportSource() const { return document_->reportSource(); }
    /// Why exporting, reporting and sending are off while the Segmentation
    /// panel shows a preview that was not applied (their tooltip).
    [[nodiscard]] static QString previewNotApplied();
    [[nodiscard]] bool isLoading() const noexcept { return document_->isLoading(); }
    /// The DICOM listener (started from the PACS settings; DICOM menu,
    /// gui/pacs/LocalStudyActions.h). Give it new settings with apply().
    [[nodiscard]] ListenerService* listenerService() const noexcept { return listener_; }
    /// The message of the last load error ("file: problem"); empty if none.
    [[nodiscard]] const QString& lastError() const noexcept { return document_->lastError(); }

  signals:
    /// A scene was put on screen (after setScene or a successful load).
    void sceneShown();
    /// A load finished with an error (after the message box was opened).
    void loadFailed(const QString& message);
    /// A session's camera and settings were applied (after its files loaded).
    void sessionApplied();
    /// The series chooser of openDicom() is open.
    void seriesDialogShown(vv::gui::SeriesDialog* dialog);

  protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void closeEvent(QCloseEvent* event) override;

  private:
    void buildDocks();
    /// The planning views (PlanningDocks) and their messages.
    void buildPlanning();
    /// File, View, DICOM and Help, in the menu bar's order.
    void buildMenus();
    void buildFileMenu();
    void buildViewMenu();
    void buildToolBar();
    void buildStatusBar();
    /// Every control shows the viewer's current settings.
    void syncControls();
    /// Shows how far the smooth copy moves the wall in the status bar while
    /// the view shows it (the last frame drew it); hides it otherwise.
    void showSmoothCopyNote();
    void setColorBlindSafe(bool on);
    /// The document's signals to the viewer, panels and status bar.
    void connectDocument();
    /// The document's scene in the viewer and panels (DocumentController::sceneChanged).
    void showScene(const std::shared_ptr<const scene::Scene>& scene, const QString& title,
                   const QStringList& files);
    /// Controls, title and status bar once the document is shown.
    void sceneWasShown();
    /// A scene from the Segmentation panel in place of the shown one; the camera stays.
    void showSegmentedScene(std::shared_ptr<const scene::Scene> scene, const QString& status);
    /// The series chooser for a DICOM scan (window-modal, not blocking).
    void chooseSeries(const std::shared_ptr<const dicom::DicomScanResult>& scan,
                      const QString& path);
    void showError(const QString& title, const ProblemText& problem);
    /// The Segmentation section on top and open while a volume's scene is
    /// shown (`volumeShown`), else at the bottom.
    void placeSegmentationSection(bool volumeShown);
    void rebuildRecentMenu();
    void updateRangeLabel();
    void onFrameRendered();
    void updateVssLabel();
    void showAbout();
    void showShortcuts();

    QStackedWidget* stack_ = nullptr;
    ViewerWidget* viewer_ = nullptr;
    SliceWorkspace* slices_ = nullptr;
    std::unique_ptr<ViewerWidget> detachedViewer_;  ///< owns viewer_ when GL is unavailable
    QLabel* glMessage_ = nullptr;
    panels::VssPanel* vssPanel_ = nullptr;
    panels::FunctionalPanel* functionalPanel_ = nullptr;
    panels::DisplayPanel* displayPanel_ = nullptr;
    panels::DataPanel* dataPanel_ = nullptr;
    panels::SegmentationPanel* segmentationPanel_ = nullptr;
    panels::SidePanel* sidePanel_ = nullptr;
    DocumentController* document_ = nullptr;
    DicomMenu* dicomMenu_ = nullptr;
    QList<QDockWidget*> docks_;
    PlanningState* planning_ = nullptr;
    panels::AnalysisPanel* analysisPanel_ = nullptr;
    PlanningDocks* planningDocks_ = nullptr;
    QByteArray defaultLayout_;  ///< saveState() before the saved layout was restored
    QAction* vssAction_ = nullptr;
    QAction* aoAction_ = nullptr;
    QAction* cvdAction_ = nullptr;
    /// The display before the colour-blind-safe mode was switched on.
    std::optional<DisplayState> beforeColorBlindSafe_;
    QAction* legendsAction_ = nullptr;
    QAction* markerAction_ = nullptr;    ///< View > Show Orientation Marker
    QAction* scaleBarAction_ = nullptr;  ///< View > Show Scale Bar
    QAction* smoothAction_ = nullptr;    ///< View > Smooth Coarse Meshes Up Close
    QLabel* vssLabel_ = nullptr;
    /// How far the smooth copy of a coarse scene moves the wall, while drawn.
    QLabel* smoothLabel_ = nullptr;
    QAction* measureAction_ = nullptr;
    QLabel* measureLabel_ = nullptr;
    MeasureTool* measure_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QLabel* statusLabel_ = nullptr;
    QLabel* rangeLabel_ = nullptr;
    QProgressBar* progressBar_ = nullptr;
    QPushButton* cancelButton_ = nullptr;
    QAction* exportImageAction_ = nullptr;
    QAction* exportReportAction_ = nullptr;
    QAction* exportSurfaceAction_ = nullptr;
    void updateExportActions();
    /// File > Export Surface…: the dialog over what the document and the
    /// Segmentation panel show (ExportSurfaceDialog).
    void exportSurface();
    ScreenshotMode* screenshot_ = nullptr;  ///< see setScreenshotTarget()
    ListenerService* listener_ = nullptr;
};

}  // namespace vv::gui
