// SPDX-License-Identifier: GPL-3.0-or-later
#include "StoreIndex.h"

#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QString>
#include <QVariant>
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
    }
}

void recordSeries(const std::filesystem::path& database,
                  const std::vector<CommittedSeries>& series) {
    const Connection c(database);
    QSqlDatabase db = c.db();
    if (!db.transaction()) {
        throw IoError(database, "store index: " + db.lastError().text().toStdString());
    }
    try {
        for (const CommittedSeries& one : series) {
            const InstanceFields& f = one.fields;
            c.run(QStringLiteral("INSERT OR REPLACE INTO studies VALUES (?, ?, ?, ?, ?, ?)"),
                  {q(f.studyInstanceUid), q(f.patientName), q(f.patientId), q(f.studyDate),
                   q(f.studyDescription), q(f.accessionNumber)});
            c.run(QStringLiteral("INSERT OR REPLACE INTO series VALUES (?, ?, ?, ?, ?, ?)"),
                  {q(f.seriesInstanceUid), q(f.studyInstanceUid), q(f.modality),
                   q(f.seriesDescription), f.seriesNumber, one.instances});
        }
        if (!db.commit()) {
            throw IoError(database, "store index: " + db.lastError().text().toStdString());
        }
    } catch (...) {
        db.rollback();
        throw;
    }
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
