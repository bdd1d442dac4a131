// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/LanguageMenu.h"

#include <QActionGroup>
#include <QMessageBox>
#include <QSettings>

#include "gui/Translations.h"

namespace vv::gui {

LanguageMenu::LanguageMenu(QWidget* parent)
    : QMenu(tr("&Language"), parent), group_(new QActionGroup(this)) {
    setObjectName(QStringLiteral("languageMenu"));
    const QString chosen = QSettings().value(QLatin1String(kLanguageKey)).toString();
    addLanguage(QString(), tr("System Default"), chosen);
    for (const QString& code : availableLanguages()) {
        addLanguage(code, languageName(code), chosen);
    }
}

void LanguageMenu::addLanguage(const QString& code, const QString& label, const QString& chosen) {
    QAction* action = addAction(label);
    action->setData(code);
    action->setCheckable(true);
    action->setChecked(code == chosen);
    group_->addAction(action);
    connect(action, &QAction::triggered, this, [this, code] {
        QSettings().setValue(QLatin1String(kLanguageKey), code);
        auto* box = new QMessageBox(QMessageBox::Information, tr("Language"),
                                    tr("The language changes when VesselView starts again."),
                                    QMessageBox::Ok, parentWidget());
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    });
}

}  // namespace vv::gui
