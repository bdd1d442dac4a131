// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target "analysis": one input through vv::fuzz::feedAnalysis
// (FuzzBodies.h). A vv::Error from the centrelines or the sections is an
// expected refusal; anything else, and a broken invariant (which aborts), is a
// finding.
#include <cstddef>
#include <cstdint>

#include "FuzzBodies.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static_cast<void>(vv::fuzz::feedAnalysis(vv::fuzz::Bytes(data, size)));
    return 0;
}
