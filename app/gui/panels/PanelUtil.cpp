// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/PanelUtil.h"

#include <QAbstractSpinBox>
#include <QComboBox>
#include <QFormLayout>

#include "vv/io/Mesh.h"

namespace vv::gui::panels {

QString arrayLabel(const io::Scene& scene, const std::string& name) {
    for (const auto& mesh : scene.meshes) {
        const io::DataArray* array = mesh.pointArray(name);
        if (array != nullptr && !array->unit.empty()) {
            return QString::fromStdString(name + " [" + array->unit + "]");
        }
    }
    return QString::fromStdString(name);
}

void makeNarrow(QWidget* panel) {
    constexpr int kComboCharacters = 10;
    constexpr int kSpinWidth = 64;
    for (auto* combo : panel->findChildren<QComboBox*>()) {
        combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        combo->setMinimumContentsLength(kComboCharacters);
    }
    for (auto* spin : panel->findChildren<QAbstractSpinBox*>()) {
        spin->setMinimumWidth(kSpinWidth);
        spin->setSizePolicy(QSizePolicy::Ignored, spin->sizePolicy().verticalPolicy());
    }
    if (auto* form = qobject_cast<QFormLayout*>(panel->layout())) {
        form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    }
}

}  // namespace vv::gui::panels
