// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Keeps the studies of the local store that the window shows open
// (LocalStore::OpenLease), so that neither the size limit's clean-up nor
// Local Studies' Delete removes them while they are on screen.

#include <QObject>
#include <QString>
#include <QStringList>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "gui/LatestRun.h"
#include "vv/pacs/LocalStore.h"

namespace vv::gui {

/// Owned by the main window (a child). open() takes a lease on a study on a
/// worker (LocalStore::open may wait up to 10 s for a removal in progress and
/// reads SQLite: never on the GUI thread) and then asks to open its data
/// (ready()); the lease is held until a document from elsewhere replaces the
/// scene (documentShown() with files outside the study's folder) or the
/// window closes (releaseAll(), the Close event of the object it watches, or
/// its destruction).
class StoreLeases : public QObject {
    Q_OBJECT

  public:
    explicit StoreLeases(QObject* parent = nullptr);
    /// Ends every lease; waits for a lease being taken (at most about 10 s).
    ~StoreLeases() override;
    StoreLeases(const StoreLeases&) = delete;
    StoreLeases& operator=(const StoreLeases&) = delete;
    StoreLeases(StoreLeases&&) = delete;
    StoreLeases& operator=(StoreLeases&&) = delete;

    /// Takes a lease on the study `studyUid` of the store at `root` on a
    /// worker, then emits ready(`folder`) (the study's or one of its series'
    /// folders, to open) — or refused() when the study is no longer in the
    /// store or its lock cannot be had. A newer open() supersedes one still
    /// taking its lease (that one's outcome is dropped).
    void open(const std::filesystem::path& root, const std::string& studyUid,
              const QString& folder);
    /// The scene on screen now comes from `files` (as opened; empty for a
    /// scene without files): ends the leases of studies whose folder holds
    /// none of them. The study of the last ready() keeps its lease until a
    /// scene is shown (also when the user cancels the series chooser).
    void documentShown(const QStringList& files);
    /// Ends every lease.
    void releaseAll();
    /// The Study Instance UIDs held open now, oldest lease first.
    [[nodiscard]] std::vector<std::string> heldStudies() const;
    [[nodiscard]] bool isTaking() const { return taker_.isRunning(); }

  signals:
    /// The study is held open: open `folder` now.
    void ready(const QString& folder);
    /// The study could not be held open (translated, names no patient data).
    void refused(const QString& message);

  protected:
    /// Ends every lease when the watched window closes.
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    /// Where the worker puts the lease it took, unless the GUI thread dropped
    /// it meanwhile (a newer open(), releaseAll()): the lease never waits in
    /// a finished future, where nobody could end it.
    struct Slot {
        std::mutex mutex;
        std::optional<pacs::LocalStore::OpenLease> lease;
        bool dropped = false;
        void drop();
    };
    struct Held {
        std::filesystem::path folder;  ///< the study's folder
        pacs::LocalStore::OpenLease lease;
    };

    std::vector<Held> held_;
    std::shared_ptr<Slot> taking_;  ///< of the lease being taken; null when none
    LatestRun<QString, AtDestruction::Wait> taker_{this};  ///< last: stopped before the leases go
};

}  // namespace vv::gui
