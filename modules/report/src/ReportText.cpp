// SPDX-License-Identifier: GPL-3.0-or-later
#include "ReportText.h"

#include <QLocale>
#include <algorithm>
#include <cmath>

namespace vv::report {

namespace {

/// The default locale (set to the UI language) without group separators:
/// "1234,5", never "1.234,5" (a '.' a German reader could take for a decimal point).
QLocale locale() {
    QLocale l;
    l.setNumberOptions(l.numberOptions() | QLocale::OmitGroupSeparator);
    return l;
}

}  // namespace

QString qs(const std::string& text) {
    return QString::fromStdString(text);
}

namespace {

/// The fixed-point decimals number() gives a magnitude in [1e-3, 1e5).
int decimalsFor(double magnitude) {
    return std::clamp(2 - static_cast<int>(std::floor(std::log10(magnitude))), 0, 4);
}

bool fixedPoint(double magnitude) {
    return magnitude >= 1e-3 && magnitude < 1e5;
}

}  // namespace

QString number(double value) {
    if (!std::isfinite(value)) {
        return QStringLiteral("\u2014");
    }
    const double a = std::abs(value);
    if (a == 0.0) {
        return locale().toString(0);
    }
    if (!fixedPoint(a)) {
        return locale().toString(value, 'g', 3);
    }
    return locale().toString(value, 'f', decimalsFor(a));
}

std::pair<QString, QString> rangeNumbers(double low, double high) {
    const double larger = std::max(std::abs(low), std::abs(high));
    if (!std::isfinite(low) || !std::isfinite(high) || !fixedPoint(larger)) {
        return {number(low), number(high)};
    }
    const int decimals = decimalsFor(larger);
    return {locale().toString(low, 'f', decimals), locale().toString(high, 'f', decimals)};
}

QString exact(double value) {
    return locale().toString(value, 'g', 6);
}

QString percent(double fraction) {
    return locale().toString(fraction * 100.0, 'f', 1) + QStringLiteral(" %");
}

QString integer(long long value) {
    return locale().toString(value);
}

QString fixed(double value, int decimals) {
    return locale().toString(value, 'f', decimals);
}

QString withUnit(const QString& value, const std::string& unit) {
    if (unit.empty()) {
        return value;
    }
    return unit == "\u00b0" ? value + qs(unit) : value + QChar(0x202F) + qs(unit);
}

QString formatDate(const QDate& date) {
    //: Date format of the report (QDate::toString); e.g. dd.MM.yyyy in German.
    return locale().toString(date, ReportText::tr("yyyy-MM-dd"));
}

QString formatDateTime(const QDateTime& dateTime) {
    //: Date and time format of the report (QDateTime::toString).
    return locale().toString(dateTime, ReportText::tr("yyyy-MM-dd HH:mm"));
}

QString engineName(std::string_view name) {
    // The same names and translations as the GUI's panels (one .qm file).
    const QByteArray utf8(name.data(), static_cast<qsizetype>(name.size()));
    return QCoreApplication::translate("vv::gui::panels::EngineNames", utf8.constData());
}

}  // namespace vv::report
