// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Stenosis grading along a branch from its cross-sections: the narrowest
// point and how much it narrows against a reference diameter.
//
// - Percent diameter stenosis: 100 (1 - d_min / d_ref), d the equivalent
//   diameter (Sections.h); percent area stenosis: 100 (1 - A_min / A_ref).
// - Automatic reference (what the result says it used): the lesion is the
//   stretch around the narrowest point where the diameter stays below 95 %
//   of the branch's healthy diameter (the 75th percentile of its sections);
//   the reference is the mean of the median diameters over two healthy
//   diameters' length just proximal and just distal of the lesion (one of
//   them where the other side has no room).
// - Given reference: two abscissae (proximal, distal) whose sections' mean
//   is the reference; NASCET (as in carotid grading): the distal normal
//   lumen alone, at the abscissa the user marks.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"

namespace vv::analysis {

struct StenosisReference {
    enum class Kind : std::uint8_t {
        Automatic,  ///< healthy stretches either side of the lesion
        Given,      ///< the mean at two abscissae the user gave
        Nascet,     ///< the distal normal lumen at the abscissa the user gave
    };
    Kind kind = Kind::Automatic;
    double proximalMm = 0.0;  ///< Given: the proximal abscissa
    double distalMm = 0.0;    ///< Given, Nascet: the distal abscissa
};

struct Stenosis {
    int branch = 0;
    double abscissaMm = 0.0;         ///< of the narrowest section
    double minimumDiameterMm = 0.0;  ///< its equivalent diameter
    double minimumAreaMm2 = 0.0;
    double referenceDiameterMm = 0.0;  ///< equivalent diameter of the reference
    double referenceAreaMm2 = 0.0;
    double diameterPercent = 0.0;  ///< 100 (1 - d_min / d_ref); negative: a widening
    double areaPercent = 0.0;      ///< 100 (1 - A_min / A_ref)
    StenosisReference reference;
    /// The lesion (Automatic) and the stretches the reference came from,
    /// abscissae in mm; a stretch of length 0 was not used.
    double lesionFromMm = 0.0;
    double lesionToMm = 0.0;
    double proximalFromMm = 0.0;
    double proximalToMm = 0.0;
    double distalFromMm = 0.0;
    double distalToMm = 0.0;
    /// How the reference was chosen, in a sentence, for tables and reports.
    std::string method;
};

/// Grades branch `branch` of `tree` from its `sections` (computeSections).
/// Sections in the branch's end zones (CrossSection::inEndZone) are left
/// out. Returns nullopt when the branch has
/// too few measured sections (fewer than 5) or no room for a reference.
/// Throws InvalidArgumentError for a branch out of range or given
/// abscissae outside the branch.
[[nodiscard]] std::optional<Stenosis> gradeStenosis(
    const CenterlineTree& tree, const std::vector<std::vector<CrossSection>>& sections, int branch,
    const StenosisReference& reference = {});

}  // namespace vv::analysis
