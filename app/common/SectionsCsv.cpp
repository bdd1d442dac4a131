// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/SectionsCsv.h"

#include <algorithm>
#include <fstream>
#include <string>

#include "vv/core/AtomicFile.h"
#include "vv/core/CsvField.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"

namespace vv::app {

std::vector<SectionRow> allSectionRows(const analysis::VesselAnalysis& analysis) {
    std::vector<SectionRow> rows;
    for (std::size_t b = 0; b < analysis.sections.size(); ++b) {
        for (std::size_t i = 0; i < analysis.sections[b].size(); ++i) {
            rows.push_back({static_cast<int>(b), i, std::nullopt});
        }
    }
    return rows;
}

void writeSectionsCsv(const std::filesystem::path& file, const analysis::VesselAnalysis& analysis,
                      const std::vector<SectionRow>& rows,
                      const std::map<int, std::string>& names) {
    for (const SectionRow& row : rows) {
        if (row.branch < 0 || static_cast<std::size_t>(row.branch) >= analysis.sections.size() ||
            row.pointIndex >= analysis.sections[static_cast<std::size_t>(row.branch)].size()) {
            throw InvalidArgumentError("writeSectionsCsv: a row outside the analysis");
        }
    }
    const bool withPath = std::any_of(rows.begin(), rows.end(),
                                      [](const SectionRow& r) { return r.pathMm.has_value(); });
    const bool withNames = !names.empty();
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << (withPath ? "path_mm," : "") << "branch_id," << (withNames ? "branch_name," : "")
            << "point,abscissa_mm,x_mm,y_mm,z_mm,area_mm2,equivalent_diameter_mm,"
               "min_diameter_mm,max_diameter_mm,inscribed_diameter_mm,perimeter_mm,"
               "circularity,status,end_zone\n";
        for (const SectionRow& row : rows) {
            const analysis::CrossSection& s =
                analysis.sections[static_cast<std::size_t>(row.branch)][row.pointIndex];
            const bool ok = s.status == analysis::CrossSection::Status::Ok;
            const auto number = [ok](double v) { return ok ? fixedText(v, 4) : ""; };
            if (withPath) {
                out << (row.pathMm ? fixedText(*row.pathMm, 3) : "") << ',';
            }
            out << s.branch << ',';
            if (withNames) {
                const auto name = names.find(s.branch);
                out << (name != names.end() ? csvField(name->second) : "") << ',';
            }
            out << s.pointIndex << ',' << fixedText(s.abscissaMm, 3) << ','
                << fixedText(s.centre.x, 4) << ',' << fixedText(s.centre.y, 4) << ','
                << fixedText(s.centre.z, 4) << ',' << number(s.areaMm2) << ','
                << number(s.equivalentDiameterMm) << ',' << number(s.minDiameterMm) << ','
                << number(s.maxDiameterMm) << ',' << fixedText(s.inscribedDiameterMm, 4) << ','
                << number(s.perimeterMm) << ',' << number(s.circularity) << ','
                << (ok ? "ok" : "no contour") << ',' << (s.inEndZone ? "yes" : "no") << '\n';
        }
        out.flush();
        if (!out) {
            throw IoError(file, "cannot write the sections");
        }
    });
}

}  // namespace vv::app
