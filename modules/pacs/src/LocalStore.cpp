// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/pacs/LocalStore.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <set>
#include <system_error>
#include <utility>

#include "StoreCleanUp.h"
#include "StoreIndex.h"
#include "vv/core/Error.h"
#include "vv/core/Log.h"
#include "vv/pacs/Uid.h"

namespace fs = std::filesystem;

namespace vv::pacs {

namespace {

constexpr fs::perms kPrivate = fs::perms::owner_all;
constexpr log::Category kLog("vv.pacs");

/// Creates `folder` (and parents) and makes it 0700. Throws IoError.
void makePrivateFolder(const fs::path& folder) {
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (!ec) {
        fs::permissions(folder, kPrivate, fs::perm_options::replace, ec);
    }
    if (ec) {
        throw IoError(folder, "cannot create the folder: " + ec.message());
    }
}

fs::path indexFile(const fs::path& root) {
    return root / "index.sqlite";
}

int countFiles(const fs::path& folder) {
    int n = 0;
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (entry.is_regular_file() && entry.path().extension() == ".dcm") {
            ++n;
        }
    }
    return n;
}

}  // namespace

struct LocalStore::Transaction::State {
    fs::path root;
    fs::path staging;
    std::vector<std::pair<fs::path, InstanceFields>> instances;
    std::uint64_t sizeLimit = 0;
    unsigned next = 0;
    bool open = true;
};

LocalStore::LocalStore(fs::path root) : root_(std::move(root)) {
    makePrivateFolder(root_);
    makePrivateFolder(root_ / ".incoming");
    detail::createIndex(indexFile(root_));
    std::error_code ec;
    fs::permissions(indexFile(root_), fs::perms::owner_read | fs::perms::owner_write,
                    fs::perm_options::replace, ec);
}

LocalStore::LocalStore(const LocalStore& other)
    : root_(other.root_), sizeLimit_(other.sizeLimit()) {}

LocalStore& LocalStore::operator=(const LocalStore& other) {
    root_ = other.root_;
    sizeLimit_ = other.sizeLimit();
    return *this;
}

LocalStore::LocalStore(LocalStore&& other) noexcept
    : root_(std::move(other.root_)), sizeLimit_(other.sizeLimit()) {}

LocalStore& LocalStore::operator=(LocalStore&& other) noexcept {
    root_ = std::move(other.root_);
    sizeLimit_ = other.sizeLimit();
    return *this;
}

std::vector<StoredStudy> LocalStore::studies() const {
    std::vector<StoredStudy> studies = detail::readIndex(indexFile(root_));
    for (StoredStudy& study : studies) {
        study.folder = root_ / study.studyInstanceUid;
        for (StoredSeries& series : study.series) {
            series.folder = study.folder / series.seriesInstanceUid;
        }
    }
    return studies;
}

LocalStore::Transaction LocalStore::begin() const {
    static std::atomic<unsigned> counter{0};
    auto state = std::make_unique<Transaction::State>();
    state->root = root_;
    state->sizeLimit = sizeLimit_;
    const auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
    state->staging = root_ / ".incoming" /
                     (std::to_string(::getpid()) + "-" + std::to_string(ticks) + "-" +
                      std::to_string(counter.fetch_add(1)));
    makePrivateFolder(state->staging);
    return Transaction(std::move(state));
}

LocalStore::Transaction::Transaction(std::unique_ptr<State> state) : state_(std::move(state)) {}
LocalStore::Transaction::Transaction(Transaction&&) noexcept = default;

LocalStore::Transaction::~Transaction() {
    discard();
}

fs::path LocalStore::Transaction::stagingPath() {
    if (!state_ || !state_->open) {
        throw InvalidArgumentError("the store transaction is closed");
    }
    return state_->staging / ("instance" + std::to_string(state_->next++) + ".part");
}

void LocalStore::Transaction::add(const fs::path& staged, const InstanceFields& fields) {
    if (!state_ || !state_->open) {
        throw InvalidArgumentError("the store transaction is closed");
    }
    try {
        validateUid(fields.studyInstanceUid);
        validateUid(fields.seriesInstanceUid);
        validateUid(fields.sopInstanceUid);
    } catch (const InvalidArgumentError&) {
        std::error_code ec;
        fs::remove(staged, ec);
        throw;
    }
    state_->instances.emplace_back(staged, fields);
}

std::size_t LocalStore::Transaction::size() const noexcept {
    return state_ ? state_->instances.size() : 0;
}

void LocalStore::Transaction::commit() {
    if (!state_ || !state_->open) {
        throw InvalidArgumentError("the store transaction is closed");
    }
    const std::lock_guard lock(detail::storeMutex());
    const detail::FileLock storeLock = detail::lockStore(state_->root);
    std::map<std::string, detail::CommittedSeries> series;
    for (const auto& [staged, fields] : state_->instances) {
        const fs::path folder = state_->root / fields.studyInstanceUid / fields.seriesInstanceUid;
        makePrivateFolder(state_->root / fields.studyInstanceUid);
        makePrivateFolder(folder);
        std::error_code ec;
        fs::rename(staged, folder / (fields.sopInstanceUid + ".dcm"), ec);
        if (ec) {
            throw IoError(folder,
                          "cannot move a received instance into the store: " + ec.message());
        }
        series[fields.seriesInstanceUid].fields = fields;
    }
    std::vector<detail::CommittedSeries> committed;
    for (auto& [uid, one] : series) {
        one.instances = countFiles(state_->root / one.fields.studyInstanceUid / uid);
        committed.push_back(one);
    }
    detail::recordSeries(indexFile(state_->root), committed);
    state_->instances.clear();
    discard();
    if (state_->sizeLimit > 0) {
        std::set<std::string> studies;
        for (const detail::CommittedSeries& one : committed) {
            studies.insert(one.fields.studyInstanceUid);
        }
        try {
            detail::cleanUpLocked(state_->root, state_->sizeLimit,
                                  std::vector<std::string>(studies.begin(), studies.end()));
        } catch (const Error& e) {
            log::warning(kLog, "cannot clean the study store up: " + e.problem());
        }
    }
}

void LocalStore::Transaction::discard() noexcept {
    if (!state_ || !state_->open) {
        return;
    }
    state_->open = false;
    state_->instances.clear();
    std::error_code ec;
    fs::remove_all(state_->staging, ec);
}

}  // namespace vv::pacs
