// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/DateText.h"

#include <QCoreApplication>
#include <QLocale>
#include <QStringList>

namespace vv::gui {

QString uiDateFormat() {
    //: Date format of dates on screen (QDate::toString), as the report's: dd.MM.yyyy in
    //: German.
    return QCoreApplication::translate("vv::gui::StudyDate", "yyyy-MM-dd");
}

QString uiDatePlaceholder() {
    //: How a date is typed, in the letters of the language: the date format of dates on
    //: screen ("yyyy-MM-dd" above) with Y = year, M = month, D = day; TT.MM.JJJJ in German.
    return QCoreApplication::translate("vv::gui::StudyDate", "YYYY-MM-DD");
}

std::optional<QDate> parseUiDate(const QString& typed) {
    const QString text = typed.trimmed();
    if (text.isEmpty()) {
        return QDate();
    }
    // "d" and "M" also read one digit: 7.3.2025 as well as 07.03.2025.
    QString lenient = uiDateFormat();
    lenient.replace(QStringLiteral("dd"), QStringLiteral("d"));
    lenient.replace(QStringLiteral("MM"), QStringLiteral("M"));
    const QStringList formats{lenient, QStringLiteral("yyyy-M-d"), QStringLiteral("yyyyMMdd")};
    for (const QString& format : formats) {
        // Numbers only: the C locale reads the digits the same in every language.
        const QDate date = QLocale::c().toDate(text, format);
        if (date.isValid()) {
            return date;
        }
    }
    return std::nullopt;
}

}  // namespace vv::gui
