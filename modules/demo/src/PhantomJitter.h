// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::demo: the vertex jitter of the phantoms (a noisy
// segmentation), the same for the same seed with every standard library.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <random>

namespace vv::demo::detail {

class PhantomJitter {
  public:
    /// Offsets uniform in [-amplitude, amplitude] per axis.
    PhantomJitter(std::uint32_t seed, double amplitude) : random_(seed), amplitude_(amplitude) {}
    /// The next offset; zero (drawing nothing) for amplitude 0.
    glm::dvec3 next() {
        if (amplitude_ == 0.0) {
            return glm::dvec3(0.0);
        }
        return {unit(), unit(), unit()};
    }

  private:
    // From the generator's raw output, not a distribution's (whose results
    // the standard leaves to each library).
    double unit() {
        const double u = static_cast<double>(random_()) / 4294967295.0;
        return amplitude_ * (2.0 * u - 1.0);
    }
    std::mt19937 random_;
    double amplitude_;
};

}  // namespace vv::demo::detail
