// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>

namespace vv::gui {

class ViewerWidget;

/// `vesselview --screenshot OUT.png`: once the viewer shows data — with the
/// VSS on, the frame with the solved surface and its occlusion — its frame is
/// saved to the target (PNG, written atomically) and the application quits
/// with exit code 0; with 1 and a message on stderr when fail() is called
/// (loading, rendering or saving failed) or no frame was saved within ten
/// minutes. The window shows no message boxes meanwhile.
class ScreenshotMode : public QObject {
    Q_OBJECT

  public:
    /// Starts waiting for the frame of `viewer` to save to `path`.
    ScreenshotMode(ViewerWidget& viewer, QString path, QObject* parent);

    [[nodiscard]] const QString& path() const noexcept { return path_; }

    /// The viewer drew a frame: saves it when it shows the data as it will stay.
    void frameRendered();
    /// Gives up: `message` on stderr, exit code 1.
    void fail(const QString& message);

  private:
    /// Prints `message` (stdout when ok, else stderr) and quits with 0 or 1.
    void finish(bool ok, const QString& message);

    ViewerWidget& viewer_;
    QString path_;
    bool pending_ = true;
};

}  // namespace vv::gui
