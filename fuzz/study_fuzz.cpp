// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target "study": one input through vv::fuzz::feedStudy
// (FuzzBodies.h). A vv::Error is an expected refusal; anything else is a finding.
#include <cstddef>
#include <cstdint>

#include "FuzzBodies.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static_cast<void>(vv::fuzz::feedStudy(vv::fuzz::Bytes(data, size)));
    return 0;
}
