// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Names of label values in VTK files. The convention: a string array in the
// dataset's field data called "<array>_names" (e.g. "segment_id_names")
// names the values of the point or cell array <array>. An entry
// "<value>=<name>" names that value ("200=Renal artery"); an entry without
// "=" names the value equal to its position (entry 0 names label 0, ...).
// Empty names are skipped. Other field data is ignored.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "vv/scene/Mesh.h"

class vtkFieldData;

namespace vv::meshio::detail {

/// The names that `entries` give, by the convention above.
[[nodiscard]] std::map<std::int64_t, std::string> parseLabelNames(
    const std::vector<std::string>& entries);

/// Sets the labelNames of every array of `mesh` that `field` (may be null) names.
void readLabelNames(vtkFieldData* field, scene::Mesh& mesh);

/// Adds "<array>_names" ("<value>=<name>" entries) to `field` for each
/// array of `mesh` with label names.
void writeLabelNames(const scene::Mesh& mesh, vtkFieldData& field);

}  // namespace vv::meshio::detail
