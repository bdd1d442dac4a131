// SPDX-License-Identifier: GPL-3.0-or-later
// A CT-angiography-like volume of the synthetic demo tree for the
// segmentation / surface round-trip tests: the library's generateDemoCt()
// (vv/demo/DemoCtSeries.h, vv/dicom/SeriesWriter.h) under the names the tests use.
#pragma once

#include <glm/glm.hpp>

#include "vv/demo/DemoCtSeries.h"

namespace vv::test {

using SyntheticCta = vv::demo::DemoCt;

/// The tree of `generations` generations voxelised into a `dims` volume whose
/// rows are rotated by `angleDegrees` about the superior axis. Deterministic.
inline SyntheticCta makeSyntheticCta(glm::ivec3 dims = {96, 96, 80}, int generations = 4,
                                     double angleDegrees = 20.0, double noiseSigma = 15.0) {
    vv::demo::DemoCtOptions options;
    options.dims = dims;
    options.generations = generations;
    options.angleDegrees = angleDegrees;
    options.noiseSigma = noiseSigma;
    return vv::demo::generateDemoCt(options);
}

}  // namespace vv::test
