// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace vv {

/// `text` as a CSV field (RFC 4180): quoted, its quotes doubled, when it
/// holds a comma, a quote or a line break; else as it is.
[[nodiscard]] std::string csvField(const std::string& text);

}  // namespace vv
