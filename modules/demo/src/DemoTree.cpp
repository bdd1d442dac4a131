// SPDX-License-Identifier: GPL-3.0-or-later
// The synthetic demo vessel tree: seeded geometry (curved centrelines, Murray's
// law radii, plausible bifurcation angles) and Poiseuille flow through it.
// The model is documented in docs/demo-data.md.
#include "vv/demo/DemoTree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "DemoValidation.h"

namespace vv::demo {

namespace {

using glm::dvec3;

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

/// Pascal per millimetre of mercury (conventional mmHg).
constexpr double kPascalPerMmHg = 133.322387415;

// Geometry of the generator (see docs/demo-data.md).
constexpr int kCenterlinePoints = 25;             // samples per centreline (24 pieces)
constexpr double kTrifurcationProbability = 0.1;  // for parents of generation >= 1
constexpr double kSplitMin = 0.35;                // share of r^3 of the first child
constexpr double kSplitMax = 0.65;                //   of a bifurcation
constexpr double kTrifurcationWeightMin = 0.7;    // weights of r^3 shares of
constexpr double kTrifurcationWeightMax = 1.3;    //   a trifurcation
constexpr double kLengthJitterMin = 0.75;         // length = (L0 / r0) * r * jitter
constexpr double kLengthJitterMax = 1.3;
constexpr double kAngleJitter = 6.0 * kDegree;  // +- on the optimal branching angle
constexpr double kMinBranchAngle = 15.0 * kDegree;
constexpr double kMaxBranchAngle = 80.0 * kDegree;
constexpr double kPlaneTwist = 90.0 * kDegree;  // bifurcation plane turn per generation
constexpr double kPlaneTwistJitter = 25.0 * kDegree;
constexpr double kAzimuthJitter = 15.0 * kDegree;
constexpr double kBendMin = 12.0 * kDegree;  // start tangent vs chord
constexpr double kBendMax = 28.0 * kDegree;
constexpr double kEndBendMin = 8.0 * kDegree;  // end tangent vs chord
constexpr double kEndBendMax = 25.0 * kDegree;
constexpr double kChordPerLength = 1.0 / 1.04;  // chord of a gently curved segment
constexpr int kPlacementAttempts = 24;
constexpr double kAcceptedGap = 1.0;  // wall-to-wall gap / child radius

/// xoshiro256** (Blackman & Vigna), seeded through splitmix64. Written here so
/// that the sequence is the same with every standard library.
class Random {
  public:
    explicit Random(std::uint64_t seed) {
        for (auto& word : state_) {
            word = splitMix(seed);
        }
    }

    std::uint64_t next() noexcept {
        const std::uint64_t result = rotateLeft(state_[1] * 5U, 7) * 9U;
        const std::uint64_t t = state_[1] << 17U;
        state_[2] ^= state_[0];
        state_[3] ^= state_[1];
        state_[1] ^= state_[2];
        state_[0] ^= state_[3];
        state_[2] ^= t;
        state_[3] = rotateLeft(state_[3], 45);
        return result;
    }

    /// Uniform in [0, 1) with 53 random bits.
    double uniform() noexcept { return static_cast<double>(next() >> 11U) * 0x1.0p-53; }
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) noexcept { return lo + (hi - lo) * uniform(); }

  private:
    static std::uint64_t splitMix(std::uint64_t& x) noexcept {
        x += 0x9E3779B97F4A7C15ULL;
        std::uint64_t z = x;
        z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31U);
    }
    static std::uint64_t rotateLeft(std::uint64_t x, unsigned k) noexcept {
        return (x << k) | (x >> (64U - k));
    }

    std::array<std::uint64_t, 4> state_{};
};

/// Rotates v about the unit axis by angle (Rodrigues).
dvec3 rotate(const dvec3& v, const dvec3& axis, double angle) {
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    return v * c + glm::cross(axis, v) * s + axis * (glm::dot(axis, v) * (1.0 - c));
}

/// A unit vector perpendicular to the unit vector d.
dvec3 anyPerpendicular(const dvec3& d) {
    const dvec3 a = glm::abs(d);
    const dvec3 e = (a.x <= a.y && a.x <= a.z) ? dvec3(1, 0, 0)
                    : (a.y <= a.z)             ? dvec3(0, 1, 0)
                                               : dvec3(0, 0, 1);
    return glm::normalize(glm::cross(d, e));
}

/// The part of v perpendicular to the unit vector d, normalised; any
/// perpendicular when v is (nearly) parallel to d.
dvec3 perpendicularPart(const dvec3& v, const dvec3& d) {
    const dvec3 p = v - d * glm::dot(v, d);
    const double len = glm::length(p);
    return len > 1e-9 ? p / len : anyPerpendicular(d);
}

/// A random unit vector perpendicular to the unit vector d.
dvec3 randomPerpendicular(const dvec3& d, Random& random) {
    return rotate(anyPerpendicular(d), d, random.uniform(0.0, 2.0 * kPi));
}

double distanceToPiece(const dvec3& p, const dvec3& a, const dvec3& b) {
    const dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + ab * t));
}

double distanceToPolyline(const dvec3& p, const std::vector<dvec3>& line) {
    double best = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        best = std::min(best, distanceToPiece(p, line[i], line[i + 1]));
    }
    return best;
}

/// A centreline under construction, in double precision.
struct Draft {
    std::vector<dvec3> points;
    dvec3 endTangent{0.0};
    dvec3 boxMin{0.0};
    dvec3 boxMax{0.0};
};

/// A cubic Bezier from start leaving along the unit direction `start`, with
/// a random bend: the chord turns away from the start direction and the end
/// tangent turns away from the chord, each about a random axis.
Draft curvedSegment(const dvec3& origin, const dvec3& start, double chordLength, Random& random) {
    const dvec3 bendAxis = randomPerpendicular(start, random);
    const dvec3 chord = rotate(start, bendAxis, random.uniform(kBendMin, kBendMax));
    const dvec3 endAxis = randomPerpendicular(chord, random);
    const dvec3 endTangent = rotate(chord, endAxis, random.uniform(kEndBendMin, kEndBendMax));

    const dvec3 p0 = origin;
    const dvec3 p3 = origin + chord * chordLength;
    const dvec3 p1 = p0 + start * (chordLength / 3.0);
    const dvec3 p2 = p3 - endTangent * (chordLength / 3.0);

    Draft draft;
    draft.points.resize(kCenterlinePoints);
    for (int i = 0; i < kCenterlinePoints; ++i) {
        const double t = static_cast<double>(i) / (kCenterlinePoints - 1);
        const double u = 1.0 - t;
        draft.points[static_cast<std::size_t>(i)] =
            p0 * (u * u * u) + p1 * (3.0 * u * u * t) + p2 * (3.0 * u * t * t) + p3 * (t * t * t);
    }
    draft.points.front() = p0;
    draft.points.back() = p3;
    draft.endTangent = endTangent;
    draft.boxMin = draft.points.front();
    draft.boxMax = draft.points.front();
    for (const auto& p : draft.points) {
        draft.boxMin = glm::min(draft.boxMin, p);
        draft.boxMax = glm::max(draft.boxMax, p);
    }
    return draft;
}

/// Smallest wall-to-wall gap, in child radii, between the candidate and the
/// placed segments. Against its family (the parent and the siblings, which
/// touch it at the junction by design) the candidate's points within `skip`
/// of its start are ignored.
double clearance(const Draft& candidate, double radius, double skip, int parent,
                 const std::vector<Draft>& placed, const std::vector<int>& placedParents,
                 const std::vector<double>& placedRadii, double maxPlacedRadius) {
    const dvec3 origin = candidate.points.front();
    const double reach = radius * (1.0 + kAcceptedGap) + maxPlacedRadius;
    double worst = std::numeric_limits<double>::max();
    for (std::size_t j = 0; j < placed.size(); ++j) {
        const Draft& other = placed[j];
        const double pad = reach + placedRadii[j];
        if (glm::any(glm::greaterThan(other.boxMin, candidate.boxMax + pad)) ||
            glm::any(glm::lessThan(other.boxMax, candidate.boxMin - pad))) {
            continue;
        }
        const bool family = static_cast<int>(j) == parent || placedParents[j] == parent;
        for (const auto& p : candidate.points) {
            if (family && glm::length(p - origin) < skip) {
                continue;
            }
            const double gap =
                (distanceToPolyline(p, other.points) - radius - placedRadii[j]) / radius;
            worst = std::min(worst, gap);
        }
    }
    return worst;
}

/// The branching angle from the parent direction that minimises pumping plus
/// volume work for a child of radius r taking its share of r^3 from a parent
/// of radius r0, the rest going to the siblings (Murray 1926, Zamir 1976):
/// cos(theta) = (r0^4 + r^4 - rest^4) / (2 r0^2 r^2) with rest^3 = r0^3 - r^3.
double optimalBranchAngle(double r0, double r) {
    const double rest = std::cbrt(std::max(0.0, r0 * r0 * r0 - r * r * r));
    const double r02 = r0 * r0;
    const double r2 = r * r;
    const double rest2 = rest * rest;
    const double c = (r02 * r02 + r2 * r2 - rest2 * rest2) / (2.0 * r02 * r2);
    return std::acos(std::clamp(c, -1.0, 1.0));
}

double polylineLength(const std::vector<glm::vec3>& line) {
    double length = 0.0;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        length += glm::length(glm::dvec3(line[i + 1]) - glm::dvec3(line[i]));
    }
    return length;
}

/// Poiseuille flow through the tree: resistances, subtree resistances, flow
/// split, pressures and wall shear stress (SI inside).
void solveFlow(VesselTree& tree, const DemoTreeOptions& options) {
    auto& segments = tree.segments;
    const double mu = options.viscosityPaS;
    for (auto& s : segments) {
        const double r = s.radiusMm * 1e-3;
        const double length = s.lengthMm * 1e-3;
        s.resistance = 8.0 * mu * length / (kPi * r * r * r * r);
    }
    // Subtree resistances, children first (they come after their parents).
    std::vector<double> subtree(segments.size(), 0.0);
    for (std::size_t i = segments.size(); i-- > 0;) {
        const auto& s = segments[i];
        double conductance = 0.0;
        for (const int c : s.children) {
            conductance += 1.0 / subtree[static_cast<std::size_t>(c)];
        }
        subtree[i] = s.resistance + (s.children.empty() ? 0.0 : 1.0 / conductance);
    }
    // Flows and pressures, parents first.
    segments[0].flowMlPerS = options.inletFlowMlPerS;
    segments[0].pressureInMmHg = options.inletPressureMmHg;
    for (auto& s : segments) {
        const double flow = s.flowMlPerS * 1e-6;
        s.pressureOutMmHg = s.pressureInMmHg - flow * s.resistance / kPascalPerMmHg;
        const double r = s.radiusMm * 1e-3;
        s.wssPa = 4.0 * mu * flow / (kPi * r * r * r);
        double conductance = 0.0;
        for (const int c : s.children) {
            conductance += 1.0 / subtree[static_cast<std::size_t>(c)];
        }
        for (const int c : s.children) {
            auto& child = segments[static_cast<std::size_t>(c)];
            child.flowMlPerS =
                s.flowMlPerS * (1.0 / subtree[static_cast<std::size_t>(c)]) / conductance;
            child.pressureInMmHg = s.pressureOutMmHg;
        }
    }
}

}  // namespace

VesselTree generateVesselTree(const DemoTreeOptions& options) {
    detail::validateDemoOptions(options);
    Random random(options.seed);

    // Drafts (double precision) and per-segment frames while growing.
    std::vector<Draft> drafts;
    std::vector<double> radii;
    std::vector<int> parents;
    std::vector<dvec3> spreadDirection;  // the direction each segment diverges in at its start
    double maxRadius = options.rootRadiusMm;
    const double lengthPerRadius = options.rootLengthMm / options.rootRadiusMm;

    VesselTree tree;
    auto& segments = tree.segments;

    // The root runs down the screen (-y); its bifurcation spreads roughly in z
    // turned by kPlaneTwist, i.e. in x, and the next one in z.
    {
        const dvec3 start(0.0, -1.0, 0.0);
        drafts.push_back(
            curvedSegment(dvec3(0.0), start, options.rootLengthMm * kChordPerLength, random));
        radii.push_back(options.rootRadiusMm);
        parents.push_back(-1);
        spreadDirection.emplace_back(0.0, 0.0, 1.0);
        VesselSegment root;
        root.id = 0;
        root.generation = 0;
        root.radiusMm = options.rootRadiusMm;
        segments.push_back(root);
    }

    // Breadth first: every generation after the previous, so parents come first.
    for (std::size_t parentIndex = 0; parentIndex < segments.size(); ++parentIndex) {
        const int generation = segments[parentIndex].generation + 1;
        if (generation >= options.generations) {
            continue;
        }
        const double r0 = radii[parentIndex];
        const dvec3 junction = drafts[parentIndex].points.back();
        const dvec3 axis = glm::normalize(drafts[parentIndex].endTangent);

        // Number of children and their shares of r0^3 (Murray's law).
        const bool trifurcation = generation >= 2 && random.uniform() < kTrifurcationProbability;
        std::vector<double> shares;
        if (trifurcation) {
            double sum = 0.0;
            for (int c = 0; c < 3; ++c) {
                shares.push_back(random.uniform(kTrifurcationWeightMin, kTrifurcationWeightMax));
                sum += shares.back();
            }
            for (auto& share : shares) {
                share /= sum;
            }
        } else {
            const double f = random.uniform(kSplitMin, kSplitMax);
            shares = {f, 1.0 - f};
        }

        // The plane of this branching: the parent's own spread direction
        // carried to its end and turned about its end tangent.
        const dvec3 carried = perpendicularPart(spreadDirection[parentIndex], axis);
        const dvec3 planeX = rotate(
            carried, axis, kPlaneTwist + random.uniform(-kPlaneTwistJitter, kPlaneTwistJitter));
        const dvec3 planeY = glm::cross(axis, planeX);

        const int childCount = static_cast<int>(shares.size());
        for (int c = 0; c < childCount; ++c) {
            const double share = shares[static_cast<std::size_t>(c)];
            const double r = r0 * std::cbrt(share);
            const double nominalAngle = optimalBranchAngle(r0, r);
            const double nominalAzimuth = 2.0 * kPi * c / childCount;
            const double length =
                lengthPerRadius * r * random.uniform(kLengthJitterMin, kLengthJitterMax);
            const double skip = 1.5 * r0 + 3.0 * r;

            Draft best;
            dvec3 bestSpread(0.0);
            double bestGap = -std::numeric_limits<double>::max();
            for (int attempt = 0; attempt < kPlacementAttempts; ++attempt) {
                // Later attempts stray further from the nominal directions.
                const double widen = 1.0 + 0.25 * attempt;
                const double angle =
                    std::clamp(nominalAngle + widen * random.uniform(-kAngleJitter, kAngleJitter),
                               kMinBranchAngle, kMaxBranchAngle);
                const double azimuth =
                    nominalAzimuth + widen * random.uniform(-kAzimuthJitter, kAzimuthJitter);
                const dvec3 spread = planeX * std::cos(azimuth) + planeY * std::sin(azimuth);
                const dvec3 direction =
                    glm::normalize(axis * std::cos(angle) + spread * std::sin(angle));
                Draft candidate =
                    curvedSegment(junction, direction, length * kChordPerLength, random);
                const double gap = clearance(candidate, r, skip, static_cast<int>(parentIndex),
                                             drafts, parents, radii, maxRadius);
                if (gap > bestGap) {
                    bestGap = gap;
                    best = std::move(candidate);
                    bestSpread = spread;
                }
                if (gap >= kAcceptedGap) {
                    break;
                }
            }

            VesselSegment child;
            child.id = static_cast<int>(segments.size());
            child.parent = static_cast<int>(parentIndex);
            child.generation = generation;
            child.radiusMm = r;
            segments[parentIndex].children.push_back(child.id);
            segments.push_back(child);
            drafts.push_back(std::move(best));
            radii.push_back(r);
            parents.push_back(static_cast<int>(parentIndex));
            spreadDirection.push_back(bestSpread);
            maxRadius = std::max(maxRadius, r);
        }
    }

    for (std::size_t i = 0; i < segments.size(); ++i) {
        auto& s = segments[i];
        s.centerline.reserve(drafts[i].points.size());
        for (const auto& p : drafts[i].points) {
            s.centerline.emplace_back(p);
        }
        // Children start exactly where their parent ends (same float point).
        if (s.parent >= 0) {
            s.centerline.front() = segments[static_cast<std::size_t>(s.parent)].centerline.back();
        }
        s.lengthMm = polylineLength(s.centerline);
    }
    solveFlow(tree, options);
    return tree;
}

}  // namespace vv::demo
