// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QMainWindow>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <memory>
#include <optional>

#include "vv/io/Mesh.h"

class QAction;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QStackedWidget;

namespace vv::gui {

class MeshLoadTask;
class ViewerWidget;

/// The main window: the 3-D viewer, File / View / Help menus, a toolbar with
/// the point-array and colour-map choosers and the VSS controls (on/off, p,
/// depth scale), and a status bar with load
/// progress and Cancel. Loading and demo generation run on a worker
/// (MeshLoadTask); errors are shown in a message box naming file and problem.
class MainWindow : public QMainWindow {
    Q_OBJECT

  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Loads `files` (one scene) on a worker; cancels a load in progress.
    void openFiles(const QStringList& files);
    /// Opens the demo: $VV_DEMO_FILE, else the bundled vessel-tree.vtp (build
    /// tree or installed), else generates it on a worker.
    void openDemo();
    /// Shows an already loaded scene (nullptr clears); `title` names it in the
    /// window title. Selects the default array (wss when present).
    void setScene(std::shared_ptr<const io::Scene> scene, const QString& title);

    /// Screenshot mode: once data is shown, save the viewer's frame to `path`
    /// (PNG, written atomically) and quit the application with exit code 0,
    /// or 1 (message on stderr) when loading, rendering or saving fails.
    /// Message boxes are not shown in this mode.
    void setScreenshotTarget(const QString& path);

    /// The bundled demo file, when one exists: $VV_DEMO_FILE if set (even if
    /// missing, so the error names it), else <exe dir>/../resources/demo/
    /// vessel-tree.vtp, else <exe dir>/../share/vesselview/demo/vessel-tree.vtp.
    [[nodiscard]] static std::optional<QString> findDemoFile();

    /// The File > Open dialog's name filters, from supportedMeshExtensions().
    [[nodiscard]] static QString meshFileFilter();

    /// Recently opened files (most recent first, at most 8), from QSettings.
    [[nodiscard]] static QStringList recentFiles();

    [[nodiscard]] ViewerWidget* viewer() const noexcept { return viewer_; }
    [[nodiscard]] QComboBox* arrayChooser() const noexcept { return arrayCombo_; }
    [[nodiscard]] QComboBox* colorMapChooser() const noexcept { return colorMapCombo_; }
    /// The toolbar's VSS controls: on/off (checked = on), the IDW power p and
    /// the depth colour scale.
    [[nodiscard]] QAction* vssToggle() const noexcept { return vssAction_; }
    [[nodiscard]] QDoubleSpinBox* vssPowerBox() const noexcept { return vssPowerBox_; }
    [[nodiscard]] QComboBox* depthScaleChooser() const noexcept { return depthScaleCombo_; }
    /// The depth cue on the vessels (toolbar; item data = VesselCue as int).
    [[nodiscard]] QComboBox* vesselCueChooser() const noexcept { return cueCombo_; }
    /// View > Show Legends (checked = legends drawn).
    [[nodiscard]] QAction* legendsToggle() const noexcept { return legendsAction_; }
    /// The status bar's VSS quality: "VSS: preview", "VSS: exact, N ms", …
    [[nodiscard]] QLabel* vssQualityLabel() const noexcept { return vssLabel_; }
    [[nodiscard]] bool isLoading() const noexcept { return !task_.isNull(); }
    /// The message of the last load error ("file: problem"); empty if none.
    [[nodiscard]] const QString& lastError() const noexcept { return lastError_; }

  signals:
    /// A scene was put on screen (after setScene or a successful load).
    void sceneShown();
    /// A load finished with an error (after the message box was opened).
    void loadFailed(const QString& message);

  protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void closeEvent(QCloseEvent* event) override;

  private:
    void buildMenus();
    void buildToolBar();
    void buildStatusBar();
    void startTask(MeshLoadTask* task, const QStringList& files);
    void taskFinished();
    void showError(const QString& title, const QString& message);
    void addRecentFiles(const QStringList& files);
    void rebuildRecentMenu();
    void applyStyle();
    void applyVss();
    void updateRangeLabel();
    void onFrameRendered();
    void updateVssLabel();
    void finishScreenshot(bool ok, const QString& message);
    void showAbout();

    QStackedWidget* stack_ = nullptr;
    ViewerWidget* viewer_ = nullptr;
    std::unique_ptr<ViewerWidget> detachedViewer_;  ///< owns viewer_ when GL is unavailable
    QLabel* glMessage_ = nullptr;
    QComboBox* arrayCombo_ = nullptr;
    QComboBox* colorMapCombo_ = nullptr;
    QAction* vssAction_ = nullptr;
    QDoubleSpinBox* vssPowerBox_ = nullptr;
    QComboBox* depthScaleCombo_ = nullptr;
    QComboBox* cueCombo_ = nullptr;
    QAction* legendsAction_ = nullptr;
    QLabel* vssLabel_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QLabel* statusLabel_ = nullptr;
    QLabel* rangeLabel_ = nullptr;
    QProgressBar* progressBar_ = nullptr;
    QPushButton* cancelButton_ = nullptr;
    QPointer<MeshLoadTask> task_;
    QString lastError_;
    QString screenshotPath_;
    bool screenshotPending_ = false;
};

}  // namespace vv::gui
