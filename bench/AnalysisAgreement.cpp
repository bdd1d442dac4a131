// SPDX-License-Identifier: GPL-3.0-or-later
#include "AnalysisAgreement.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>

#include "vv/analysis/Bifurcations.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/segmentation/SceneSource.h"

namespace vv::bench {
namespace {

using analysis::CrossSection;

/// Distance from `p` to the polyline `line`.
double distanceToPolyline(const glm::dvec3& p, const std::vector<glm::vec3>& line) {
    double best = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const glm::dvec3 a(line[i]);
        const glm::dvec3 ab = glm::dvec3(line[i + 1]) - a;
        const double t =
            std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-12), 0.0, 1.0);
        best = std::min(best, glm::length(p - (a + t * ab)));
    }
    return best;
}

double percentile(std::vector<double> values, double q) {
    if (values.empty()) {
        return std::nan("");
    }
    std::sort(values.begin(), values.end());
    return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1))];
}

/// The leaves found and the ends that match no leaf nor the root's start.
void matchEnds(const demo::VesselTree& truth, const analysis::CenterlineTree& tree, double slack,
               ConstructionAgreement& result) {
    std::vector<bool> endMatched(tree.ends.size(), false);
    const auto near = [&](const glm::dvec3& place, double radius) {
        bool any = false;
        for (std::size_t e = 0; e < tree.ends.size(); ++e) {
            if (glm::length(tree.ends[e].position - place) <= 2.0 * radius + slack) {
                endMatched[e] = true;
                any = true;
            }
        }
        return any;
    };
    for (const auto& segment : truth.segments) {
        if (segment.parent < 0) {
            (void)near(glm::dvec3(segment.centerline.front()), segment.radiusMm);
        }
        if (segment.children.empty()) {
            ++result.leaves;
            result.leavesFound +=
                near(glm::dvec3(segment.centerline.back()), segment.radiusMm) ? 1U : 0U;
        }
    }
    result.endsElsewhere =
        static_cast<std::size_t>(std::count(endMatched.begin(), endMatched.end(), false));
}

/// The widest trunk section that measures the vessel, or null.
const CrossSection* widestTrunkSection(const demo::AneurysmPhantom& phantom,
                                       const std::vector<std::vector<CrossSection>>& sections) {
    const CrossSection* widest = nullptr;
    for (const auto& branch : sections) {
        for (const CrossSection& s : branch) {
            if (!s.measuresTheVessel() ||
                phantom.nearestAxisPoint(s.centre).part != demo::AneurysmPart::Trunk) {
                continue;
            }
            if (widest == nullptr || s.equivalentDiameterMm > widest->equivalentDiameterMm) {
                widest = &s;
            }
        }
    }
    return widest;
}

/// The radius of the part `axis` (nearestAxisPoint of `q`) lies on, where
/// the axis distance is measured: two radii clear of the ends and the
/// bifurcation point; nullopt elsewhere.
std::optional<double> measuredRadius(const demo::AneurysmPhantom& phantom,
                                     const demo::AneurysmAxisPoint& axis, const glm::dvec3& q) {
    const auto& o = phantom.options;
    const bool trunk = axis.part == demo::AneurysmPart::Trunk;
    const double r = trunk ? o.radiusMm : o.iliacRadiusMm;
    const double end = trunk ? 0.0 : o.iliacLengthMm;
    if (glm::length(q - phantom.bifurcationPoint) < 2.0 * o.radiusMm ||
        std::abs(axis.abscissaMm - end) < 2.0 * r) {
        return std::nullopt;
    }
    return r;
}

/// AneurysmAgreement::worstWallDistancePerR.
double wallDistance(const demo::AneurysmPhantom& phantom) {
    return worstOverFacets(phantom.mesh, [&](const glm::dvec3& q) {
        const auto axis = phantom.nearestAxisPoint(q);
        const auto r = measuredRadius(phantom, axis, q);
        return r ? std::abs(axis.distanceMm - axis.radiusMm) / *r : std::nan("");
    });
}

/// Worst distance per r and the points counted (AneurysmAgreement).
std::pair<double, std::size_t> axisDistance(const demo::AneurysmPhantom& phantom,
                                            const analysis::CenterlineTree& tree) {
    double worst = 0.0;
    std::size_t checked = 0;
    for (const auto& branch : tree.branches) {
        for (const auto& p : branch.points) {
            const auto axis = phantom.nearestAxisPoint(p.position);
            const auto r = measuredRadius(phantom, axis, p.position);
            if (!r) {
                continue;
            }
            worst = std::max(worst, axis.distanceMm / *r);
            ++checked;
        }
    }
    return {worst, checked};
}

/// AneurysmAgreement::trunkLengthError.
double trunkLengthError(const demo::AneurysmPhantom& phantom,
                        const analysis::CenterlineTree& tree) {
    const auto& o = phantom.options;
    const double z = o.trunkLengthMm;
    const double truth = o.trunkLengthMm + (o.openEnds ? 0.0 : o.radiusMm);
    const auto& points = tree.branches.front().points;
    double measured = points.back().abscissaMm + (z - points.back().position.z);
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const double z0 = points[i].position.z;
        const double z1 = points[i + 1].position.z;
        if (z0 <= z && z1 > z) {
            const double t = (z - z0) / (z1 - z0);
            measured = points[i].abscissaMm + t * (points[i + 1].abscissaMm - points[i].abscissaMm);
            break;
        }
    }
    return measured / truth - 1.0;
}

}  // namespace

AneurysmAgreement measureAneurysm(const demo::AneurysmPhantom& phantom,
                                  const analysis::CenterlineTree& tree,
                                  const std::vector<std::vector<CrossSection>>& sections) {
    AneurysmAgreement result;
    result.branches = tree.branches.size();
    result.ends = tree.ends.size();
    const CrossSection* widest = widestTrunkSection(phantom, sections);
    result.maxDiameterError = std::nan("");
    result.widestAbscissaMm = std::nan("");
    result.widestTrueRadiusMm = std::nan("");
    if (widest != nullptr) {
        result.maxDiameterError = widest->equivalentDiameterMm / phantom.maxDiameterMm - 1.0;
        result.widestAbscissaMm = phantom.nearestAxisPoint(widest->centre).abscissaMm;
        result.widestTrueRadiusMm = phantom.trunkRadiusAt(result.widestAbscissaMm);
    }
    std::tie(result.worstAxisDistancePerR, result.axisPoints) = axisDistance(phantom, tree);
    result.worstWallDistancePerR = wallDistance(phantom);
    result.trunkLengthError =
        tree.branches.empty() ? std::nan("") : trunkLengthError(phantom, tree);
    if (!tree.branches.empty()) {
        for (const int child : tree.branches.front().children) {
            const double x =
                tree.branches[static_cast<std::size_t>(child)].points.back().position.x;
            result.childEndMaxX = std::max(result.childEndMaxX, x);
            result.childEndMinX = std::min(result.childEndMinX, x);
        }
    }
    const auto bifurcations = analysis::findBifurcations(tree);
    result.bifurcations = bifurcations.size();
    result.angleErrorDeg =
        bifurcations.empty() ? std::nan("")
                             : bifurcations.front().angleDeg - phantom.options.bifurcationAngleDeg;
    return result;
}

/// The area centroid of the closed polygon `contour`.
glm::dvec2 polygonCentroid(const std::vector<glm::dvec2>& contour) {
    double twiceArea = 0.0;
    glm::dvec2 sum(0.0);
    for (std::size_t i = 0; i < contour.size(); ++i) {
        const glm::dvec2& a = contour[i];
        const glm::dvec2& b = contour[(i + 1) % contour.size()];
        const double cross = a.x * b.y - b.x * a.y;
        twiceArea += cross;
        sum += (a + b) * cross;
    }
    return twiceArea != 0.0 ? sum / (3.0 * twiceArea) : glm::dvec2(0.0);
}

ConstructionAgreement compareWithConstruction(
    const demo::VesselTree& truth, const analysis::CenterlineTree& tree,
    const std::vector<std::vector<analysis::CrossSection>>& sections, double slackMm) {
    ConstructionAgreement result;
    result.segments = truth.segments.size();
    matchEnds(truth, tree, slackMm, result);
    std::vector<double> offAxis;
    std::vector<double> diameterError;
    std::vector<double> centroidOffAxis;
    for (std::size_t b = 0; b < sections.size(); ++b) {
        for (std::size_t i = 0; i < sections[b].size(); ++i) {
            const CrossSection& s = sections[b][i];
            result.sectionsOk += s.status == CrossSection::Status::Ok ? 1U : 0U;
            ++result.sectionsAll;
            if (s.inEndZone) {
                continue;  // caps and junctions: the construction has no axis there
            }
            const glm::dvec3 p = tree.branches[b].points[i].position;
            double nearest = std::numeric_limits<double>::max();
            double radius = 0.0;
            for (const auto& segment : truth.segments) {
                const double d = distanceToPolyline(p, segment.centerline);
                if (d < nearest) {
                    nearest = d;
                    radius = segment.radiusMm;
                }
            }
            offAxis.push_back(nearest / radius);
            if (s.status == CrossSection::Status::Ok) {
                diameterError.push_back(s.equivalentDiameterMm / (2.0 * radius) - 1.0);
                const glm::dvec2 c = polygonCentroid(s.contour);
                const glm::dvec3 centroid = s.centre + c.x * s.axisU + c.y * s.axisV;
                double toAxis = std::numeric_limits<double>::max();
                for (const auto& segment : truth.segments) {
                    toAxis = std::min(toAxis, distanceToPolyline(centroid, segment.centerline));
                }
                centroidOffAxis.push_back(toAxis / radius);
            }
        }
    }
    result.compared = offAxis.size();
    result.offAxisMedian = percentile(offAxis, 0.5);
    result.offAxisP95 = percentile(offAxis, 0.95);
    result.centroidOffAxisMedian = percentile(centroidOffAxis, 0.5);
    result.diameterErrorMedian = percentile(diameterError, 0.5);
    for (double& e : diameterError) {
        e = std::abs(e);
    }
    result.diameterErrorP95 = percentile(diameterError, 0.95);
    return result;
}

scene::Mesh segmentAsRenderDoes(const demo::DemoCt& ct, const std::filesystem::path& folder) {
    (void)dicom::writeCtSeries(folder, ct.volume);
    scene::Scene scene = segmentation::loadSceneSource(folder, segmentation::SceneSourceOptions{});
    return std::move(scene.meshes.front());
}

double worstOverFacets(const scene::Mesh& mesh,
                       const std::function<double(const glm::dvec3&)>& distance) {
    constexpr int kSteps = 8;
    const auto& positions = mesh.positions;
    const auto& indices = mesh.indices;
    double worst = 0.0;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::dvec3 a(positions[indices[t]]);
        const glm::dvec3 b(positions[indices[t + 1]]);
        const glm::dvec3 c(positions[indices[t + 2]]);
        for (int i = 0; i <= kSteps; ++i) {
            for (int j = 0; i + j <= kSteps; ++j) {
                const double d =
                    distance(a + (b - a) * (i / double{kSteps}) + (c - a) * (j / double{kSteps}));
                if (!std::isnan(d)) {
                    worst = std::max(worst, d);
                }
            }
        }
    }
    return worst;
}

}  // namespace vv::bench
