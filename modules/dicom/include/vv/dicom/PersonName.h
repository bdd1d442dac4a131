// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <string_view>

namespace vv::dicom {

/// A DICOM person name (PN: "Family^Given^Middle^Prefix^Suffix"; only the
/// alphabetic group before any '=') as people write a name in a list, the
/// one form every dialog and report shows: "Family, Given Middle", a prefix
/// before it ("Dr Family, Given"), a suffix after it ("Family, Given, Jr").
/// Spaces around components are dropped; empty components are left out
/// ("Doe^^^^" is "Doe"). "" for a name without letters.
[[nodiscard]] std::string personNameText(std::string_view pn);

/// What a person typed as a name ("Doe, Jane" or DICOM's "Doe^Jane") as a
/// DICOM PN: the first comma separates family and given names; a text that
/// already holds '^' is taken as it is (trimmed).
[[nodiscard]] std::string personNameFromText(std::string_view typed);

}  // namespace vv::dicom
