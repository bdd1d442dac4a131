// SPDX-License-Identifier: GPL-3.0-or-later
#include "evaluation/ArtefactScore.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::evaluation {

Image<float> distanceToVessels(ImageView<const std::uint8_t> vessels) {
    const int w = vessels.width();
    const int h = vessels.height();
    constexpr float kInf = std::numeric_limits<float>::infinity();
    constexpr float kDiagonal = 1.41421356F;
    Image<float> d(w, h, kInf);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (vessels(x, y) != 0) {
                d(x, y) = 0.0F;
            }
        }
    }
    // Two chamfer passes: forward (from above and the left), backward.
    const auto relax = [&](int x, int y, int dx, int dy, float step) {
        const int nx = x + dx;
        const int ny = y + dy;
        if (nx >= 0 && nx < w && ny >= 0 && ny < h) {
            d(x, y) = std::min(d(x, y), d(nx, ny) + step);
        }
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            relax(x, y, -1, 0, 1.0F);
            relax(x, y, 0, -1, 1.0F);
            relax(x, y, -1, -1, kDiagonal);
            relax(x, y, 1, -1, kDiagonal);
        }
    }
    for (int y = h - 1; y >= 0; --y) {
        for (int x = w - 1; x >= 0; --x) {
            relax(x, y, 1, 0, 1.0F);
            relax(x, y, 0, 1, 1.0F);
            relax(x, y, 1, 1, kDiagonal);
            relax(x, y, -1, 1, kDiagonal);
        }
    }
    return d;
}

namespace {

void validate(const ArtefactScoreOptions& options) {
    if (!(options.bandNear > 0.0) || !(options.bandFar >= options.bandNear) ||
        !std::isfinite(options.bandFar) || !(options.spacing > 0.0) ||
        !std::isfinite(options.spacing) || !(options.smoothing > 0.0) ||
        !std::isfinite(options.smoothing)) {
        throw InvalidArgumentError(
            "artefactScore: needs 0 < bandNear <= bandFar, spacing > 0 "
            "and smoothing > 0, all finite");
    }
}

/// The 1-D Gaussian taps of `sigma`, radius ceil(3 sigma).
std::vector<double> gaussianTaps(double sigma) {
    const int radius = static_cast<int>(std::ceil(3.0 * sigma));
    std::vector<double> taps(static_cast<std::size_t>(2 * radius + 1));
    for (int i = -radius; i <= radius; ++i) {
        const int index = i + radius;
        taps[static_cast<std::size_t>(index)] = std::exp(-0.5 * i * i / (sigma * sigma));
    }
    return taps;
}

/// `in` convolved with `taps` along one axis (dx, dy: (1, 0) or (0, 1));
/// outside the image counts as 0.
Image<double> blurAxis(const Image<double>& in, const std::vector<double>& taps, int dx, int dy) {
    const int w = in.width();
    const int h = in.height();
    const int radius = static_cast<int>(taps.size() / 2);
    Image<double> out(w, h, 0.0);
    parallelFor(0, h, 32, [&](long b, long e) {
        for (int y = static_cast<int>(b); y < static_cast<int>(e); ++y) {
            for (int x = 0; x < w; ++x) {
                double s = 0.0;
                for (int k = -radius; k <= radius; ++k) {
                    const int qx = x + k * dx;
                    const int qy = y + k * dy;
                    const int index = k + radius;
                    if (qx >= 0 && qx < w && qy >= 0 && qy < h) {
                        s += taps[static_cast<std::size_t>(index)] * in(qx, qy);
                    }
                }
                out(x, y) = s;
            }
        }
    });
    return out;
}

/// The separable Gaussian of `taps`: along x, then y.
Image<double> blur(const Image<double>& in, const std::vector<double>& taps) {
    return blurAxis(blurAxis(in, taps, 1, 0), taps, 0, 1);
}

}  // namespace

namespace {

/// Bilinear sample of `l` at (x, y) (pixel centres at integers), or NaN when
/// one of the four pixels is outside or not finite.
double bilinear(ImageView<const float> l, double x, double y) {
    // The last row / column itself is a sample (of the cell before it).
    int x0 = static_cast<int>(std::floor(x));
    int y0 = static_cast<int>(std::floor(y));
    if (x0 == l.width() - 1 && x == x0) {
        --x0;
    }
    if (y0 == l.height() - 1 && y == y0) {
        --y0;
    }
    if (x0 < 0 || y0 < 0 || x0 + 1 >= l.width() || y0 + 1 >= l.height()) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    const double fx = x - x0;
    const double fy = y - y0;
    const double a = l(x0, y0);
    const double b = l(x0 + 1, y0);
    const double c = l(x0, y0 + 1);
    const double d = l(x0 + 1, y0 + 1);
    return (a * (1.0 - fx) + b * fx) * (1.0 - fy) + (c * (1.0 - fx) + d * fx) * fy;
}

}  // namespace

ArtefactScore artefactScore(ImageView<const float> luminance, ImageView<const std::uint8_t> vessels,
                            const ArtefactScoreOptions& options) {
    validate(options);
    const int w = luminance.width();
    const int h = luminance.height();
    if (vessels.width() != w || vessels.height() != h) {
        throw InvalidArgumentError("artefactScore: the luminance is " + std::to_string(w) + "x" +
                                   std::to_string(h) + ", the vessel mask " +
                                   std::to_string(vessels.width()) + "x" +
                                   std::to_string(vessels.height()));
    }
    // The contour's direction: across the level lines of the distance to the
    // vessels, smoothed so that it follows the silhouette, not its pixel steps.
    const Image<float> distance = distanceToVessels(vessels);
    Image<double> clipped(w, h, 0.0);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            clipped(x, y) = std::min(static_cast<double>(distance(x, y)), 2.0 * options.bandFar);
        }
    }
    // Normalised by the weight inside the image, so the border bends no direction.
    const std::vector<double> taps = gaussianTaps(options.smoothing);
    Image<double> smooth = blur(clipped, taps);
    const Image<double> inside = blur(Image<double>(w, h, 1.0), taps);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            smooth(x, y) /= inside(x, y);
        }
    }
    // Luminance only where it counts (void, finite); NaN elsewhere.
    Image<float> l(w, h, std::numeric_limits<float>::quiet_NaN());
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (vessels(x, y) == 0 && std::isfinite(luminance(x, y))) {
                l(x, y) = luminance(x, y);
            }
        }
    }
    const double step = options.spacing;
    double sum2 = 0.0;
    ArtefactScore score;
    for (int y = 1; y + 1 < h; ++y) {
        for (int x = 1; x + 1 < w; ++x) {
            const double d = distance(x, y);
            if (!std::isfinite(l(x, y)) || d < options.bandNear || d > options.bandFar) {
                continue;
            }
            const double gx = 0.5 * (smooth(x + 1, y) - smooth(x - 1, y));
            const double gy = 0.5 * (smooth(x, y + 1) - smooth(x, y - 1));
            const double g = std::hypot(gx, gy);
            if (!(g > 1e-9)) {
                continue;
            }
            const double tx = -gy / g;  // along the contour
            const double ty = gx / g;
            const double a = bilinear(l.view(), x + step * tx, y + step * ty);
            const double b = bilinear(l.view(), x - step * tx, y - step * ty);
            if (!std::isfinite(a) || !std::isfinite(b)) {
                continue;
            }
            const double r = l(x, y) - 0.5 * (a + b);
            sum2 += r * r;
            ++score.bandPixels;
        }
    }
    score.rms =
        score.bandPixels > 0 ? std::sqrt(sum2 / static_cast<double>(score.bandPixels)) : 0.0;
    return score;
}

Image<float> vssLuminance(ImageView<const float> height, ImageView<const glm::vec4> slopes,
                          ImageView<const std::uint8_t> vessels, const VssLight& light) {
    const int w = height.width();
    const int h = height.height();
    if (slopes.width() != w || slopes.height() != h || vessels.width() != w ||
        vessels.height() != h) {
        throw InvalidArgumentError("vssLuminance: height, slopes and vessel mask differ in size");
    }
    if (!(light.pixelScale > 0.0) || !std::isfinite(light.pixelScale)) {
        throw InvalidArgumentError("vssLuminance: pixelScale must be finite and > 0");
    }
    const double range = std::max(light.dmax - light.dmin, 0.0);
    // The half vector of the light and the viewer (0, 0, 1).
    double hx = light.lightX;
    double hy = light.lightY;
    double hz = light.lightZ + 1.0;
    const double hl = std::sqrt(hx * hx + hy * hy + hz * hz);
    hx /= hl;
    hy /= hl;
    hz /= hl;
    Image<float> out(w, h, std::numeric_limits<float>::quiet_NaN());
    parallelFor(0, h, 32, [&](long b, long e) {
        for (int y = static_cast<int>(b); y < static_cast<int>(e); ++y) {
            for (int x = 0; x < w; ++x) {
                const glm::vec4 s = slopes(x, y);
                if (vessels(x, y) != 0 || s.w <= 0.0F || !std::isfinite(height(x, y))) {
                    continue;
                }
                const double t = std::clamp(static_cast<double>(height(x, y)), 0.0, 1.0);
                const double pixel = std::max((light.dmin + t * range) * light.pixelScale, 1e-12);
                const double nx0 = s.x * range / pixel;
                // Rows run down, the light's y up (view space).
                const double ny0 = -s.y * range / pixel;
                const double nl = std::sqrt(nx0 * nx0 + ny0 * ny0 + 1.0);
                const double nx = nx0 / nl;
                const double ny = ny0 / nl;
                const double nz = 1.0 / nl;
                const double diffuse =
                    std::max(nx * light.lightX + ny * light.lightY + nz * light.lightZ, 0.0);
                const double u = std::clamp((s.z - 0.55) / (0.9 - 0.55), 0.0, 1.0);
                double specularScale = u * u * (3.0 - 2.0 * u);  // smoothstep
                const double len = std::clamp(static_cast<double>(s.w), 1e-3, 1.0);
                const double shininess =
                    len * light.shininess / (len + light.shininess * (1.0 - len));
                specularScale *= (1.0 + shininess) / (1.0 + light.shininess);
                const double specular =
                    diffuse > 0.0 ? std::pow(std::max(nx * hx + ny * hy + nz * hz, 0.0), shininess)
                                  : 0.0;
                const double lit = light.base * (light.ambient + light.diffuse * diffuse) +
                                   light.specular * specular * specularScale;
                out(x, y) = static_cast<float>(std::min(lit, 1.0));
            }
        }
    });
    return out;
}

}  // namespace vv::evaluation
