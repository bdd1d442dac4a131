// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target "stl": one input through vv::fuzz::feedMesh(..., ".stl")
// (FuzzBodies.h). A vv::Error is an expected refusal; anything else is a finding.
#include <cstddef>
#include <cstdint>

#include "FuzzBodies.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static_cast<void>(vv::fuzz::feedMesh(vv::fuzz::Bytes(data, size), ".stl"));
    return 0;
}
