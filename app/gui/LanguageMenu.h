// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QMenu>

class QActionGroup;

namespace vv::gui {

/// View > Language: "System Default" and every available language
/// (Translations.h), the one stored under kLanguageKey checked. Choosing one
/// stores it in QSettings and says, in a message box over the menu's parent,
/// that it applies when VesselView starts again. Give it the window as
/// parent (and add it to the View menu): the message box is the window's.
class LanguageMenu : public QMenu {
    Q_OBJECT

  public:
    explicit LanguageMenu(QWidget* parent);

  private:
    void addLanguage(const QString& code, const QString& label, const QString& chosen);

    QActionGroup* group_ = nullptr;
};

}  // namespace vv::gui
