// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to the session code (Session.cpp, SessionView.cpp,
// SessionMigration.cpp): typed, range-checked reading of JSON fields.
#pragma once

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <filesystem>
#include <glm/glm.hpp>
#include <string_view>
#include <vector>

#include "common/DisplaySettings.h"
#include "common/Session.h"
#include "common/SettingsSchema.h"

namespace vv::app::detail {

/// Large enough for any coordinate or value a session holds.
inline constexpr double kHuge = 1e30;
/// Positions in millimetres (slice positions, pans, cursors, landmarks) lie
/// within a kilometre of the origin.
inline constexpr double kMaxMm = 1e6;

/// The JSON value of `value` for `setting` (SettingsSchema.h): a bool, a
/// number, a Choice's name, a colour as [r, g, b], text, or null.
[[nodiscard]] QJsonValue settingToJson(const Setting& setting, const SettingValue& value);

/// QString of UTF-8 text.
[[nodiscard]] QString text(std::string_view s);

/// Reads typed, range-checked fields; every error is a FormatError naming
/// the file and the field ("camera.distance").
class SessionReader {
  public:
    explicit SessionReader(std::filesystem::path file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const QString& field, const QString& problem) const;

    /// o[key]; fails "is missing" when absent.
    [[nodiscard]] QJsonValue get(const QJsonObject& o, const QString& where, const char* key) const;
    [[nodiscard]] QJsonObject object(const QJsonObject& o, const QString& where,
                                     const char* key) const;
    [[nodiscard]] double number(const QJsonObject& o, const QString& where, const char* key,
                                double lo, double hi) const;
    [[nodiscard]] int integer(const QJsonObject& o, const QString& where, const char* key, int lo,
                              int hi) const;
    [[nodiscard]] float real(const QJsonObject& o, const QString& where, const char* key, double lo,
                             double hi) const;
    [[nodiscard]] bool boolean(const QJsonObject& o, const QString& where, const char* key) const;
    [[nodiscard]] QString string(const QJsonObject& o, const QString& where, const char* key) const;
    /// `n` numbers in [lo, hi].
    [[nodiscard]] std::vector<double> numbers(const QJsonValue& v, const QString& field,
                                              qsizetype n, double lo, double hi) const;
    [[nodiscard]] glm::vec3 vec3(const QJsonObject& o, const QString& where, const char* key,
                                 double lo, double hi) const;

    /// `v` (the JSON at `field`) as a valid value of `setting`: right type,
    /// within range, a known name; fails naming `field` otherwise.
    [[nodiscard]] SettingValue setting(const Setting& setting, const QJsonValue& v,
                                       const QString& field) const;

    [[nodiscard]] const std::filesystem::path& file() const noexcept { return file_; }

    /// "where.key", or "key" at the top.
    static QString path(const QString& where, const char* key);

  private:
    [[nodiscard]] double checkNumber(const QJsonValue& v, const QString& field, double lo,
                                     double hi) const;

    std::filesystem::path file_;
};

/// The "view" object of `settings` (every setting the schema marks as
/// Required or Optional, then the structured ones: the VSS depth range, the
/// colour range and the objects).
[[nodiscard]] QJsonObject viewToJson(const DisplaySettings& settings);

/// Puts `value` at `setting`'s key into `view` (a scalar setting's).
void insertSetting(QJsonObject& view, const Setting& setting, const QJsonValue& value);

/// Reads the "view" object `view` into `settings` (which holds the defaults).
void readView(const SessionReader& reader, const QJsonObject& view, DisplaySettings& settings);

/// The "slices" object of `state` (SessionSlices.cpp).
[[nodiscard]] QJsonObject slicesToJson(const SliceSessionState& state);

/// Reads the "slices" object `value`; fails naming the field ("slices.axial.zoom").
[[nodiscard]] SliceSessionState readSlices(const SessionReader& reader, const QJsonValue& value);
/// The "planning" object (SessionPlanning.cpp).
[[nodiscard]] QJsonObject planningToJson(const PlanningSessionState& p);
[[nodiscard]] PlanningSessionState readPlanning(const SessionReader& r, const QJsonValue& value);

/// Brings `root` (any supported version) to the current version, one step at a time.
[[nodiscard]] QJsonObject migrateSession(QJsonObject root, const SessionReader& reader);

}  // namespace vv::app::detail
