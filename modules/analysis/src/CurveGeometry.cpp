// SPDX-License-Identifier: GPL-3.0-or-later
#include "CurveGeometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace vv::analysis::detail {
namespace {

/// The point at arc length `s` of the polyline with arc lengths `at`.
glm::dvec3 pointAt(const std::vector<glm::dvec3>& points, const std::vector<double>& at, double s) {
    if (s <= at.front()) {
        return points.front();
    }
    if (s >= at.back()) {
        return points.back();
    }
    const auto upper = std::upper_bound(at.begin(), at.end(), s);
    const auto i = static_cast<std::size_t>(upper - at.begin());
    const double span = at[i] - at[i - 1];
    const double t = span > 0.0 ? (s - at[i - 1]) / span : 0.0;
    return glm::mix(points[i - 1], points[i], t);
}

glm::dvec3 anyPerpendicular(const glm::dvec3& t) {
    const glm::dvec3 axis =
        std::abs(t.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    return glm::normalize(glm::cross(t, axis));
}

}  // namespace

std::vector<double> arcLengths(const std::vector<glm::dvec3>& points) {
    std::vector<double> s(points.size(), 0.0);
    for (std::size_t i = 1; i < points.size(); ++i) {
        s[i] = s[i - 1] + glm::length(points[i] - points[i - 1]);
    }
    return s;
}

std::vector<glm::dvec3> resample(const std::vector<glm::dvec3>& input, double step) {
    std::vector<glm::dvec3> points;
    for (const glm::dvec3& p : input) {
        if (points.empty() || glm::length(p - points.back()) > 1e-9) {
            points.push_back(p);
        }
    }
    if (points.size() < 2) {
        return points;
    }
    const std::vector<double> at = arcLengths(points);
    const double length = at.back();
    std::vector<glm::dvec3> out;
    const auto count = static_cast<std::size_t>(std::floor(length / step));
    out.reserve(count + 2);
    for (std::size_t i = 0; i <= count; ++i) {
        out.push_back(pointAt(points, at, static_cast<double>(i) * step));
    }
    if (length - static_cast<double>(count) * step > 1e-6 * step) {
        out.push_back(points.back());
    }
    if (out.size() < 2) {
        out.push_back(points.back());
    }
    return out;
}

double interpolate(const std::vector<double>& at, const std::vector<double>& values, double s) {
    if (s <= at.front()) {
        return values.front();
    }
    if (s >= at.back()) {
        return values.back();
    }
    const auto i = static_cast<std::size_t>(std::upper_bound(at.begin(), at.end(), s) - at.begin());
    const double span = at[i] - at[i - 1];
    const double t = span > 0.0 ? (s - at[i - 1]) / span : 0.0;
    return values[i - 1] + t * (values[i] - values[i - 1]);
}

std::vector<glm::dvec3> smoothAlong(const std::vector<glm::dvec3>& points,
                                    const std::vector<double>& sigma) {
    const std::vector<double> at = arcLengths(points);
    const double length = at.empty() ? 0.0 : at.back();
    std::vector<glm::dvec3> out(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double reach = std::min({3.0 * sigma[i], at[i], length - at[i]});
        if (reach <= 0.0 || sigma[i] <= 0.0) {
            out[i] = points[i];
            continue;
        }
        // Weighted least squares of p(u) = a + b u + c u^2 (u = arc offset):
        // moments of the weights (m[k] = sum w u^k) and of the points.
        std::array<double, 5> m{};
        std::array<glm::dvec3, 3> q{glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
        const auto add = [&](std::size_t j) {
            const double u = at[j] - at[i];
            const double w = std::exp(-0.5 * u * u / (sigma[i] * sigma[i]));
            double power = w;
            for (int k = 0; k < 5; ++k) {
                m[static_cast<std::size_t>(k)] += power;
                if (k < 3) {
                    q[static_cast<std::size_t>(k)] += power * points[j];
                }
                power *= u;
            }
        };
        for (std::size_t j = i + 1; j-- > 0 && at[i] - at[j] <= reach;) {
            add(j);
        }
        for (std::size_t j = i + 1; j < points.size() && at[j] - at[i] <= reach; ++j) {
            add(j);
        }
        const glm::dmat3 normal(m[0], m[1], m[2], m[1], m[2], m[3], m[2], m[3], m[4]);
        const double det = glm::determinant(normal);
        if (!(std::abs(det) > 1e-12 * m[0] * m[2] * m[4])) {
            out[i] = q[0] / m[0];  // too few points for a parabola: their mean
            continue;
        }
        // The fit's value at u = 0 is a: the first row of the inverse.
        const glm::dmat3 inverse = glm::inverse(normal);
        out[i] = inverse[0][0] * q[0] + inverse[1][0] * q[1] + inverse[2][0] * q[2];
    }
    return out;
}

std::vector<glm::dvec3> tangents(const std::vector<glm::dvec3>& points) {
    const std::size_t n = points.size();
    std::vector<glm::dvec3> t(n, glm::dvec3(0.0, 0.0, 1.0));
    for (std::size_t i = 0; i < n && n >= 2; ++i) {
        const glm::dvec3 d = points[std::min(i + 1, n - 1)] - points[i > 0 ? i - 1 : 0];
        if (glm::length(d) > 0.0) {
            t[i] = glm::normalize(d);
        } else if (i > 0) {
            t[i] = t[i - 1];
        }
    }
    return t;
}

std::vector<glm::dvec3> rotationMinimisingNormals(const std::vector<glm::dvec3>& points,
                                                  const std::vector<glm::dvec3>& t) {
    std::vector<glm::dvec3> r(points.size());
    if (points.empty()) {
        return r;
    }
    r[0] = anyPerpendicular(t[0]);
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        // Reflect (r, t) in the plane bisecting the step, then in the plane
        // bisecting the reflected tangent and the next one.
        const glm::dvec3 v1 = points[i + 1] - points[i];
        const double c1 = glm::dot(v1, v1);
        glm::dvec3 rL = r[i];
        glm::dvec3 tL = t[i];
        if (c1 > 0.0) {
            rL = r[i] - (2.0 / c1) * glm::dot(v1, r[i]) * v1;
            tL = t[i] - (2.0 / c1) * glm::dot(v1, t[i]) * v1;
        }
        const glm::dvec3 v2 = t[i + 1] - tL;
        const double c2 = glm::dot(v2, v2);
        glm::dvec3 next = c2 > 0.0 ? rL - (2.0 / c2) * glm::dot(v2, rL) * v2 : rL;
        // Keep it exactly perpendicular and unit against rounding drift.
        next -= glm::dot(next, t[i + 1]) * t[i + 1];
        r[i + 1] = glm::length(next) > 1e-12 ? glm::normalize(next) : anyPerpendicular(t[i + 1]);
    }
    return r;
}

std::vector<double> curvatures(const std::vector<glm::dvec3>& points,
                               const std::vector<double>& scale) {
    const std::vector<double> at = arcLengths(points);
    std::vector<double> k(points.size(), 0.0);
    if (points.size() < 3) {
        return k;
    }
    const double length = at.back();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double reach = std::min(scale[i], std::max(at[i], length - at[i]));
        const double s0 = std::max(0.0, at[i] - reach);
        const double s2 = std::min(length, at[i] + reach);
        const double s1 = (s0 == 0.0 || s2 == length) ? 0.5 * (s0 + s2) : at[i];
        const glm::dvec3 a = pointAt(points, at, s0);
        const glm::dvec3 b = pointAt(points, at, s1);
        const glm::dvec3 c = pointAt(points, at, s2);
        const double ab = glm::length(b - a);
        const double bc = glm::length(c - b);
        const double ca = glm::length(a - c);
        const double area2 = glm::length(glm::cross(b - a, c - a));  // twice the area
        const double denominator = ab * bc * ca;
        k[i] = denominator > 0.0 ? 2.0 * area2 / denominator : 0.0;
    }
    return k;
}

std::vector<double> torsions(const std::vector<glm::dvec3>& points,
                             const std::vector<double>& scale) {
    const std::vector<double> at = arcLengths(points);
    std::vector<double> tau(points.size(), 0.0);
    if (points.size() < 4) {
        return tau;
    }
    const double length = at.back();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double h = std::min(scale[i], length / 4.0);
        const double s = std::clamp(at[i], 2.0 * h, length - 2.0 * h);
        const auto p = [&](double offset) { return pointAt(points, at, s + offset * h); };
        const glm::dvec3 d1 = (p(1.0) - p(-1.0)) / (2.0 * h);
        const glm::dvec3 d2 = (p(1.0) - 2.0 * p(0.0) + p(-1.0)) / (h * h);
        const glm::dvec3 d3 = (p(2.0) - 2.0 * p(1.0) + 2.0 * p(-1.0) - p(-2.0)) / (2.0 * h * h * h);
        const glm::dvec3 b = glm::cross(d1, d2);
        const double b2 = glm::dot(b, b);
        const double speed = glm::length(d1);
        // |d1 x d2| / |d1|^3 is the curvature; below ~1e-4 / h the binormal
        // is noise.
        if (speed <= 0.0 || std::sqrt(b2) / (speed * speed * speed) < 1e-4 / h) {
            continue;
        }
        tau[i] = glm::dot(b, d3) / b2;
    }
    return tau;
}

}  // namespace vv::analysis::detail
