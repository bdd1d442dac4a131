// SPDX-License-Identifier: GPL-3.0-or-later
#include "StoreIndex.h"

#include <QDateTime>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QString>
#include <QVariant>
#include <algorithm>
#include <atomic>
#include <map>
#include <utility>

#include "vv/core/Error.h"

namespace vv::pacs::detail {

namespace {

QString q(const std::string& s) {
    return QString::fromStdString(s);
}

std::string s(const QVariant& v) {
    return v.toString().toStdString();
}

/// One connection for the lifetime of the object; removed afterwards.
class Connection {
  public:
    explicit Connection(const std::filesystem::path& database) : file_(database) {
        static std::atomic<unsigned> counter{0};
        name_ = QStringLiteral("vv.pacs.index.%1").arg(counter.fetch_add(1));
        {
            QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), name_);
            db.setDatabaseName(QString::fromStdString(database.string()));
            db.setConnectOptions(QStringLiteral("QSQLITE_BUSY_TIMEOUT=10000"));
            if (!db.open()) {
                const std::string why = db.lastError().text().toStdString();
                db = QSqlDatabase();
                QSqlDatabase::removeDatabase(name_);
                throw IoError(database, "cannot open the store index: " + why);
            }
        }
    }
    Connection(const Connection&) = delete;
    Connection& operator=(const Connection&) = delete;
    ~Connection() {
        QSqlDatabase::database(name_, false).close();
        QSqlDatabase::removeDatabase(name_);
    }
    [[nodiscard]] QSqlDatabase db() const { return QSqlDatabase::database(name_, false); }

    /// Runs `sql` (prepared with `values`); throws IoError on failure.
    QSqlQuery run(const QString& sql, const QVariantList& values = {}) const {
        QSqlQuery query(db());
        if (!query.prepare(sql)) {
            throw IoError(file_, "store index: " + query.lastError().text().toStdString());
        }
        for (const QVariant& v : values) {
            query.addBindValue(v);
        }
        if (!query.exec()) {
            throw IoError(file_, "store index: " + query.lastError().text().toStdString());
        }
        return query;
    }

  private:
    std::filesystem::path file_;
    QString name_;
};

/// An SQL transaction on `c`, rolled back unless commit() was reached.
class Transaction {
  public:
    Transaction(const Connection& c, std::filesystem::path database)
        : db_(c.db()), file_(std::move(database)) {
        if (!db_.transaction()) {
            throw IoError(file_, "store index: " + db_.lastError().text().toStdString());
        }
    }
    Transaction(const Transaction&) = delete;
    Transaction& operator=(const Transaction&) = delete;
    Transaction(Transaction&&) = delete;
    Transaction& operator=(Transaction&&) = delete;
    ~Transaction() {
        if (!done_) {
            db_.rollback();
        }
    }
    void commit() const {
        if (!db_.commit()) {
            throw IoError(file_, "store index: " + db_.lastError().text().toStdString());
        }
        done_ = true;
    }

  private:
    mutable QSqlDatabase db_;
    std::filesystem::path file_;
    mutable bool done_ = false;
};

/// The time of a use (ms since the epoch), later than every use recorded so
/// far, so that the order of uses is strict even within one millisecond.
qlonglong nextUse(const Connection& c) {
    QSqlQuery last = c.run(QStringLiteral("SELECT coalesce(max(last_used), 0) FROM studies"));
    const qlonglong now = QDateTime::currentMSecsSinceEpoch();
    return last.next() ? std::max(now, last.value(0).toLongLong() + 1) : now;
}

}  // namespace

void createIndex(const std::filesystem::path& database) {
    const Connection c(database);
    c.run(
        QStringLiteral("CREATE TABLE IF NOT EXISTS studies ("
                       "study_uid TEXT PRIMARY KEY, patient_name TEXT, patient_id TEXT, "
                       "study_date TEXT, study_description TEXT, accession TEXT)"));
    c.run(
        QStringLiteral("CREATE TABLE IF NOT EXISTS series ("
                       "series_uid TEXT PRIMARY KEY, study_uid TEXT NOT NULL, modality TEXT, "
                       "series_description TEXT, series_number INTEGER, instances INTEGER)"));
    QSqlQuery result = c.run(QStringLiteral(
        "SELECT count(*) FROM sqlite_master WHERE type='table' AND name IN ('studies','series')"));
    if (!result.next() || result.value(0).toInt() != 2) {
        throw FormatError(database, "not a VesselView store index");
    }  // Indexes made before the size limit lack the time of last use.
    QSqlQuery columns = c.run(QStringLiteral("PRAGMA table_info(studies)"));
    bool hasLastUsed = false;
    while (columns.next()) {
        hasLastUsed = hasLastUsed || columns.value(1).toString() == QStringLiteral("last_used");
    }
    if (!hasLastUsed) {
        c.run(
            QStringLiteral("ALTER TABLE studies ADD COLUMN last_used INTEGER NOT NULL DEFAULT 0"));
    }
}

void recordSeries(const std::filesystem::path& database,
                  const std::vector<CommittedSeries>& series) {
    const Connection c(database);
    const Transaction t(c, database);
    for (const CommittedSeries& one : series) {
        const InstanceFields& f = one.fields;
        c.run(QStringLiteral("INSERT OR REPLACE INTO studies (study_uid, patient_name, "
                             "patient_id, study_date, study_description, accession, "
                             "last_used) VALUES (?, ?, ?, ?, ?, ?, ?)"),
              {q(f.studyInstanceUid), q(f.patientName), q(f.patientId), q(f.studyDate),
               q(f.studyDescription), q(f.accessionNumber), nextUse(c)});
        c.run(QStringLiteral("INSERT OR REPLACE INTO series VALUES (?, ?, ?, ?, ?, ?)"),
              {q(f.seriesInstanceUid), q(f.studyInstanceUid), q(f.modality), q(f.seriesDescription),
               f.seriesNumber, one.instances});
    }
    t.commit();
}

bool touchStudy(const std::filesystem::path& database, const std::string& studyUid) {
    const Connection c(database);
    const Transaction t(c, database);
    const QSqlQuery updated =
        c.run(QStringLiteral("UPDATE studies SET last_used = ? WHERE study_uid = ?"),
              {nextUse(c), q(studyUid)});
    const bool found = updated.numRowsAffected() > 0;
    t.commit();
    return found;
}

std::vector<std::string> studiesByUse(const std::filesystem::path& database) {
    const Connection c(database);
    std::vector<std::string> uids;
    QSqlQuery st =
        c.run(QStringLiteral("SELECT study_uid FROM studies ORDER BY last_used, study_uid"));
    while (st.next()) {
        uids.push_back(s(st.value(0)));
    }
    return uids;
}

void removeStudy(const std::filesystem::path& database, const std::string& studyUid) {
    const Connection c(database);
    const Transaction t(c, database);
    c.run(QStringLiteral("DELETE FROM series WHERE study_uid = ?"), {q(studyUid)});
    c.run(QStringLiteral("DELETE FROM studies WHERE study_uid = ?"), {q(studyUid)});
    t.commit();
}

std::vector<StoredStudy> readIndex(const std::filesystem::path& database) {
    const Connection c(database);
    std::vector<StoredStudy> studies;
    std::map<std::string, std::size_t> byUid;
    QSqlQuery st = c.run(QStringLiteral(
        "SELECT study_uid, patient_name, patient_id, study_date, study_description, accession "
        "FROM studies ORDER BY study_date DESC, study_uid"));
    while (st.next()) {
        StoredStudy study;
        study.studyInstanceUid = s(st.value(0));
        study.patientName = s(st.value(1));
        study.patientId = s(st.value(2));
        study.studyDate = s(st.value(3));
        study.studyDescription = s(st.value(4));
        study.accessionNumber = s(st.value(5));
        byUid.emplace(study.studyInstanceUid, studies.size());
        studies.push_back(std::move(study));
    }
    QSqlQuery se = c.run(QStringLiteral(
        "SELECT study_uid, series_uid, modality, series_description, series_number, instances "
        "FROM series ORDER BY series_number, series_uid"));
    while (se.next()) {
        const auto it = byUid.find(s(se.value(0)));
        if (it == byUid.end()) {
            continue;
        }
        StoredSeries one;
        one.seriesInstanceUid = s(se.value(1));
        one.modality = s(se.value(2));
        one.seriesDescription = s(se.value(3));
        one.seriesNumber = se.value(4).toInt();
        one.instances = se.value(5).toInt();
        studies[it->second].series.push_back(std::move(one));
    }
    return studies;
}

}  // namespace vv::pacs::detail
