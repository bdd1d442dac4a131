// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/scene/QuantityTitle.h"

namespace vv::scene {

std::string quantityTitle(const std::string& name, const std::string& unit) {
    return unit.empty() ? name : name + " (" + unit + ")";
}

}  // namespace vv::scene
