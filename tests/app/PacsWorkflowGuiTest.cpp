// SPDX-License-Identifier: GPL-3.0-or-later
// The DICOM menu's pieces working together as a clinic uses them, against a
// real Orthanc: the listener switched on in Preferences starts in the window,
// the PACS browser's C-MOVE lands through it in the local store, the study
// opened from there is held open against deletion, and Local Studies lists
// it without any other step.
#include <gtest/gtest.h>

#include <QAction>
#include <QCheckBox>
#include <QPointer>
#include <QRadioButton>
#include <QTreeWidget>

#include "PacsGuiFixture.h"
#include "gui/MainWindow.h"
#include "gui/SeriesDialog.h"
#include "gui/pacs/ListenerService.h"
#include "gui/pacs/LocalStudiesBrowser.h"
#include "vv/pacs/LocalStore.h"

namespace {

using vv::test::waitUntil;
using PacsWorkflowGuiTest = vv::test::PacsGuiFixture;

TEST_F(PacsWorkflowGuiTest, ListenerTurnedOnInPreferencesReceivesTheMoveAndLocalStudiesShowsIt) {
    vv::gui::ListenerService* listener = window_->listenerService();
    ASSERT_NE(listener, nullptr);

    // C-MOVE is refused while the listener is off...
    auto* b = browser();
    ASSERT_TRUE(search(b, QStringLiteral("VV-GUI-1")));
    ASSERT_TRUE(selectStudy(b));
    b->moveButton()->click();
    EXPECT_FALSE(retrieve(b, b->retrieveStudyButton()));
    EXPECT_TRUE(b->status().startsWith(QStringLiteral("C-MOVE needs our listener")))
        << b->status().toStdString();

    // ...and works once it is switched on in Preferences and saved.
    auto* prefs = preferences();
    ASSERT_FALSE(prefs->listenerBox()->isChecked());
    prefs->listenerBox()->setChecked(true);
    clickOk(prefs);
    ASSERT_TRUE(waitUntil(
        [listener] { return listener->state() == vv::gui::ListenerService::State::Running; },
        10000))
        << listener->stateText().toStdString();
    EXPECT_EQ(listener->storeFolder(), store_);

    ASSERT_TRUE(retrieve(b, b->retrieveStudyButton())) << b->status().toStdString();
    EXPECT_TRUE(b->status().startsWith(QStringLiteral("Done:"))) << b->status().toStdString();
    const auto studies = vv::pacs::LocalStore(store_).studies();
    ASSERT_EQ(studies.size(), 1U);
    EXPECT_EQ(studies[0].series.at(0).instances, slices_);
    EXPECT_TRUE(waitUntil(
        [&] { return listener->committedInstances() == static_cast<std::size_t>(slices_); }, 5000))
        << listener->committedInstances();

    // Open from the PACS browser: the study on screen is held open, so the
    // store will not delete it (here, nor from another program).
    const QPointer<vv::gui::SeriesDialog> chooser = openRetrieved(b);
    ASSERT_NE(chooser, nullptr);
    ASSERT_TRUE(acceptAndShow(chooser));
    EXPECT_THROW(vv::pacs::LocalStore(store_).remove(studies[0].studyInstanceUid),
                 vv::pacs::StudyOpenError);

    // Local Studies lists it.
    auto* action = window_->findChild<QAction*>(QStringLiteral("localStudies"));
    ASSERT_NE(action, nullptr);
    action->trigger();
    auto* local = window_->findChild<vv::gui::LocalStudiesBrowser*>();
    ASSERT_NE(local, nullptr);
    ASSERT_TRUE(waitUntil([local] { return local->tree()->topLevelItemCount() == 1; }, 10000));
    const QTreeWidgetItem* row = local->tree()->topLevelItem(0);
    bool hasId = false;
    for (int c = 0; c < local->tree()->columnCount(); ++c) {
        hasId = hasId || row->text(c) == QStringLiteral("VV-GUI-1");
    }
    EXPECT_TRUE(hasId);
    EXPECT_EQ(row->childCount(), 1);
    local->close();

    // Switched off again: the port is free and C-MOVE is refused again.
    prefs = preferences();
    prefs->listenerBox()->setChecked(false);
    clickOk(prefs);
    ASSERT_TRUE(waitUntil(
        [listener] { return listener->state() == vv::gui::ListenerService::State::Stopped; },
        10000));
    EXPECT_FALSE(retrieve(b, b->retrieveStudyButton()));
    EXPECT_TRUE(b->status().startsWith(QStringLiteral("C-MOVE needs our listener")));
}

}  // namespace
