// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/vss/Versions.h"

#include <opencv2/core/utility.hpp>

namespace vv::vss {

std::string openCvVersion() {
    return cv::getVersionString();
}

}  // namespace vv::vss
