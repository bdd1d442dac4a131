// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/StoreLeases.h"

#include <QEvent>
#include <algorithm>
#include <utility>

#include "vv/core/Error.h"

namespace vv::gui {
namespace {

/// True when `file` is `folder` or lies under it.
bool holds(const std::filesystem::path& folder, const QString& file) {
    const std::string inside = std::filesystem::path(file.toStdString()).lexically_normal();
    const std::string study = folder.lexically_normal();
    return inside == study || inside.starts_with(study + '/');
}

}  // namespace

StoreLeases::StoreLeases(QObject* parent) : QObject(parent) {}

StoreLeases::~StoreLeases() {
    releaseAll();
}

void StoreLeases::Slot::drop() {
    const std::lock_guard lock(mutex);
    dropped = true;
    lease.reset();
}

void StoreLeases::open(const std::filesystem::path& root, const std::string& studyUid,
                       const QString& folder) {
    if (taking_) {
        taking_->drop();
    }
    taking_ = std::make_shared<Slot>();
    taker_.start(
        [root, studyUid, slot = taking_](const std::stop_token&) {
            try {
                pacs::LocalStore::OpenLease lease = pacs::LocalStore(root).open(studyUid);
                const std::lock_guard lock(slot->mutex);
                if (!slot->dropped) {
                    slot->lease.emplace(std::move(lease));
                }
                return QString();
            } catch (const InvalidArgumentError&) {
                return tr("This study is no longer in the local study store.");
            } catch (const Error&) {
                return tr(
                    "The study cannot be opened now: the local study store is "
                    "busy or cannot be read. Try again in a moment.");
            }
        },
        [this, folder = root / studyUid, open = folder](const QString& problem) {
            std::optional<pacs::LocalStore::OpenLease> lease;
            {
                const std::lock_guard lock(taking_->mutex);
                lease.swap(taking_->lease);
            }
            taking_.reset();
            if (!lease) {
                emit refused(problem);
                return;
            }
            held_.push_back({folder, std::move(*lease)});
            emit ready(open);
        });
}

void StoreLeases::documentShown(const QStringList& files) {
    // A lease joins held_ at ready(), when its data is opened: that abandons
    // any load in progress, so the next scene shown is its own unless the
    // user opens something else.
    std::erase_if(held_, [&files](const Held& h) {
        return std::none_of(files.begin(), files.end(),
                            [&h](const QString& file) { return holds(h.folder, file); });
    });
}

void StoreLeases::releaseAll() {
    taker_.cancel();
    if (taking_) {
        taking_->drop();
        taking_.reset();
    }
    held_.clear();
}

std::vector<std::string> StoreLeases::heldStudies() const {
    std::vector<std::string> uids;
    for (const Held& h : held_) {
        uids.push_back(h.lease.studyInstanceUid());
    }
    return uids;
}

bool StoreLeases::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Close) {
        releaseAll();
    }
    return QObject::eventFilter(watched, event);
}

}  // namespace vv::gui
