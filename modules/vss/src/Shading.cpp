// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/vss/Shading.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::vss {

IsoLevel isoLevel(float z, int lineCount) {
    if (lineCount < 1) {
        throw InvalidArgumentError("isoLevel: the number of iso-lines must be >= 1, got " +
                                   std::to_string(lineCount));
    }
    IsoLevel level;
    if (!std::isfinite(z)) {
        level.band = -1;
        level.distance = std::numeric_limits<float>::quiet_NaN();
        return level;
    }
    const double s = std::clamp(static_cast<double>(z), 0.0, 1.0) * lineCount;
    level.band = std::min(lineCount - 1, static_cast<int>(std::floor(s)));
    level.distance = static_cast<float>(std::abs(s - std::round(s)));
    return level;
}

namespace {

/// dh along one axis at index i of a line of n samples read by at(j).
template <typename At>
double derivative(int i, int n, const At& at) {
    const double c = at(i);
    const bool left = i > 0 && std::isfinite(at(i - 1));
    const bool right = i + 1 < n && std::isfinite(at(i + 1));
    if (left && right) {
        return 0.5 * (at(i + 1) - at(i - 1));
    }
    if (right) {
        return at(i + 1) - c;
    }
    if (left) {
        return c - at(i - 1);
    }
    return 0.0;
}

}  // namespace

Image<glm::vec3> heightFieldNormals(ImageView<const float> height, double depthScale,
                                    double pixelSize) {
    if (!std::isfinite(depthScale) || depthScale < 0.0) {
        throw InvalidArgumentError("heightFieldNormals: depthScale must be finite and >= 0, got " +
                                   std::to_string(depthScale));
    }
    if (!std::isfinite(pixelSize) || pixelSize <= 0.0) {
        throw InvalidArgumentError("heightFieldNormals: pixelSize must be finite and > 0, got " +
                                   std::to_string(pixelSize));
    }
    const int w = height.width();
    const int h = height.height();
    Image<glm::vec3> normals(w, h, glm::vec3(0.0F, 0.0F, -1.0F));
    const double k = depthScale / pixelSize;
    parallelFor(0, h, 64, [&](long b, long e) {
        for (int y = static_cast<int>(b); y < static_cast<int>(e); ++y) {
            const float* row = height.row(y);
            glm::vec3* n = normals.row(y);
            for (int x = 0; x < w; ++x) {
                if (!std::isfinite(row[x])) {
                    continue;
                }
                const double gx =
                    k * derivative(x, w, [&](int j) { return static_cast<double>(row[j]); });
                const double gy =
                    k * derivative(y, h, [&](int j) { return static_cast<double>(height(x, j)); });
                // Clamped so the squares below stay finite for any input.
                const double cx = std::clamp(std::isnan(gx) ? 0.0 : gx, -1e150, 1e150);
                const double cy = std::clamp(std::isnan(gy) ? 0.0 : gy, -1e150, 1e150);
                const double len = std::sqrt(cx * cx + cy * cy + 1.0);
                n[x] = glm::vec3(static_cast<float>(cx / len), static_cast<float>(cy / len),
                                 static_cast<float>(-1.0 / len));
            }
        }
    });
    return normals;
}

}  // namespace vv::vss
