// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace vv::vss {

/// The version of the OpenCV library vv::vss runs with (e.g. "4.6.0"), as
/// the linked library reports it; for the About box. Never throws.
[[nodiscard]] std::string openCvVersion();

}  // namespace vv::vss
