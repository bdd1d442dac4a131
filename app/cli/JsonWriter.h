// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The command line writes its JSON with the front ends' one writer.

#include "common/JsonWriter.h"

namespace vv::cli {
using app::jsonString;
using app::JsonWriter;
}  // namespace vv::cli
