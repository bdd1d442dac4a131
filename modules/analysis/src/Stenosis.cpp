// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/analysis/Stenosis.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "vv/core/Error.h"
#include "vv/core/NumberText.h"

namespace vv::analysis {
namespace {

constexpr double kLesionFraction = 0.95;  ///< below this share of the healthy diameter: lesion
constexpr double kHealthyPercentile = 0.75;
constexpr double kReferenceDiameters = 2.0;  ///< a reference stretch's length, in diameters
constexpr std::size_t kMinSections = 5;
constexpr std::size_t kMinReferenceSections = 3;

double median(std::vector<double> values) {
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

/// Median equivalent diameter and area of the measured sections in [from, to].
struct StretchSize {
    std::size_t count = 0;
    double diameter = 0.0;
    double area = 0.0;
};
StretchSize stretchSize(const std::vector<const CrossSection*>& measured, double from, double to) {
    std::vector<double> diameters;
    std::vector<double> areas;
    for (const CrossSection* s : measured) {
        if (s->abscissaMm >= from - 1e-9 && s->abscissaMm <= to + 1e-9) {
            diameters.push_back(s->equivalentDiameterMm);
            areas.push_back(s->areaMm2);
        }
    }
    StretchSize size;
    size.count = diameters.size();
    if (size.count > 0) {
        size.diameter = median(diameters);
        size.area = median(areas);
    }
    return size;
}

/// The measured sections of the branch outside its end zones, in order.
std::vector<const CrossSection*> measuredSections(const std::vector<CrossSection>& sections) {
    std::vector<const CrossSection*> measured;
    for (const CrossSection& s : sections) {
        if (s.measuresTheVessel()) {
            measured.push_back(&s);
        }
    }
    return measured;
}

std::string mm(double value) {
    return fixedText(value, 1) + " mm";
}

/// The automatic reference: healthy stretches either side of the lesion.
bool automaticReference(const std::vector<const CrossSection*>& measured, std::size_t narrowest,
                        Stenosis& result) {
    std::vector<double> diameters;
    diameters.reserve(measured.size());
    for (const CrossSection* s : measured) {
        diameters.push_back(s->equivalentDiameterMm);
    }
    std::vector<double> sorted = diameters;
    std::sort(sorted.begin(), sorted.end());
    const double healthy = sorted[static_cast<std::size_t>(kHealthyPercentile *
                                                           static_cast<double>(sorted.size() - 1))];
    std::size_t start = narrowest;
    while (start > 0 && diameters[start - 1] < kLesionFraction * healthy) {
        --start;
    }
    std::size_t end = narrowest;
    while (end + 1 < diameters.size() && diameters[end + 1] < kLesionFraction * healthy) {
        ++end;
    }
    result.lesionFromMm = measured[start]->abscissaMm;
    result.lesionToMm = measured[end]->abscissaMm;
    const double reach = kReferenceDiameters * healthy;
    const double first = measured.front()->abscissaMm;
    const double last = measured.back()->abscissaMm;
    const double proximalFrom = std::max(first, result.lesionFromMm - reach);
    const double distalTo = std::min(last, result.lesionToMm + reach);
    const StretchSize proximal =
        start > 0 ? stretchSize(measured, proximalFrom, measured[start - 1]->abscissaMm)
                  : StretchSize{};
    const StretchSize distal = end + 1 < measured.size()
                                   ? stretchSize(measured, measured[end + 1]->abscissaMm, distalTo)
                                   : StretchSize{};
    const bool useProximal = proximal.count >= kMinReferenceSections;
    const bool useDistal = distal.count >= kMinReferenceSections;
    if (!useProximal && !useDistal) {
        return false;
    }
    if (useProximal) {
        result.proximalFromMm = proximalFrom;
        result.proximalToMm = measured[start - 1]->abscissaMm;
    }
    if (useDistal) {
        result.distalFromMm = measured[end + 1]->abscissaMm;
        result.distalToMm = distalTo;
    }
    const double n = (useProximal ? 1.0 : 0.0) + (useDistal ? 1.0 : 0.0);
    result.referenceDiameterMm =
        ((useProximal ? proximal.diameter : 0.0) + (useDistal ? distal.diameter : 0.0)) / n;
    result.referenceAreaMm2 =
        ((useProximal ? proximal.area : 0.0) + (useDistal ? distal.area : 0.0)) / n;
    std::string sides = useProximal && useDistal ? "proximal and distal"
                        : useProximal            ? "proximal (no room distally)"
                                                 : "distal (no room proximally)";
    result.method = "Automatic: the median diameters over " + mm(reach) + " of healthy vessel " +
                    sides + " of the lesion (" + mm(result.lesionFromMm) + " to " +
                    mm(result.lesionToMm) + ", below 95 % of the branch's healthy " + mm(healthy) +
                    ")";
    return true;
}

/// The sections within half a diameter of abscissa `at`.
StretchSize sizeAt(const std::vector<const CrossSection*>& measured, double at) {
    const CrossSection* nearest = measured.front();
    for (const CrossSection* s : measured) {
        if (std::abs(s->abscissaMm - at) < std::abs(nearest->abscissaMm - at)) {
            nearest = s;
        }
    }
    const double half = 0.5 * nearest->equivalentDiameterMm;
    return stretchSize(measured, at - half, at + half);
}

}  // namespace

std::optional<Stenosis> gradeStenosis(const CenterlineTree& tree,
                                      const std::vector<std::vector<CrossSection>>& sections,
                                      int branch, const StenosisReference& reference) {
    if (branch < 0 || static_cast<std::size_t>(branch) >= tree.branches.size() ||
        static_cast<std::size_t>(branch) >= sections.size()) {
        throw InvalidArgumentError("stenosis: no branch " + std::to_string(branch));
    }
    const Branch& b = tree.branches[static_cast<std::size_t>(branch)];
    const auto measured = measuredSections(sections[static_cast<std::size_t>(branch)]);
    if (measured.size() < kMinSections) {
        return std::nullopt;
    }
    const auto narrowest = static_cast<std::size_t>(
        std::min_element(measured.begin(), measured.end(),
                         [](const CrossSection* a, const CrossSection* c) {
                             return a->equivalentDiameterMm < c->equivalentDiameterMm;
                         }) -
        measured.begin());
    Stenosis result;
    result.branch = branch;
    result.reference = reference;
    result.abscissaMm = measured[narrowest]->abscissaMm;
    result.minimumDiameterMm = measured[narrowest]->equivalentDiameterMm;
    result.minimumAreaMm2 = measured[narrowest]->areaMm2;
    result.lesionFromMm = result.lesionToMm = result.abscissaMm;
    if (reference.kind == StenosisReference::Kind::Automatic) {
        if (!automaticReference(measured, narrowest, result)) {
            return std::nullopt;
        }
    } else {
        const double first = b.points.front().abscissaMm;
        const double last = b.points.back().abscissaMm;
        const auto inside = [&](double s) { return s >= first && s <= last; };
        const bool given = reference.kind == StenosisReference::Kind::Given;
        if (!inside(reference.distalMm) || (given && !inside(reference.proximalMm))) {
            throw InvalidArgumentError("stenosis: a reference abscissa lies outside branch " +
                                       std::to_string(branch) + " (" + mm(first) + " to " +
                                       mm(last) + ")");
        }
        const StretchSize distal = sizeAt(measured, reference.distalMm);
        const StretchSize proximal = given ? sizeAt(measured, reference.proximalMm) : distal;
        result.referenceDiameterMm = 0.5 * (distal.diameter + proximal.diameter);
        result.referenceAreaMm2 = 0.5 * (distal.area + proximal.area);
        result.distalFromMm = result.distalToMm = reference.distalMm;
        if (given) {
            result.proximalFromMm = result.proximalToMm = reference.proximalMm;
            result.method = "Given: the mean of the diameters at " + mm(reference.proximalMm) +
                            " and " + mm(reference.distalMm);
        } else {
            result.method = "NASCET: the distal normal diameter at " + mm(reference.distalMm);
        }
    }
    if (result.referenceDiameterMm <= 0.0 || result.referenceAreaMm2 <= 0.0) {
        return std::nullopt;
    }
    result.diameterPercent = 100.0 * (1.0 - result.minimumDiameterMm / result.referenceDiameterMm);
    result.areaPercent = 100.0 * (1.0 - result.minimumAreaMm2 / result.referenceAreaMm2);
    return result;
}

}  // namespace vv::analysis
