// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Label (categorical) arrays: segment, branch or group ids whose values name
// classes rather than measure something. They are shown with one colour per
// label (colormaps::labelPalette()), never through a continuous colour map.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vv/scene/Mesh.h"

namespace vv::scene {

/// At most this many distinct values make an array look categorical.
inline constexpr std::size_t kMaxAutoLabels = 16;
/// Without a hint (integer storage or a label-like name) an array must have
/// at most this many distinct values to look categorical.
inline constexpr std::size_t kMaxUnhintedLabels = 8;
/// At most this many distinct values can be shown as labels at all (the
/// user's "Categories" override on an array with more stays continuous).
inline constexpr std::size_t kMaxLabels = 256;

/// One label of an array: its value and its name from the file (empty when
/// the file names none).
struct Label {
    std::int64_t value = 0;
    std::string name;
    bool operator==(const Label&) const = default;
};

/// True when `name` hints at labels: it ends in "_id" / "id" after a
/// separator, or contains "label", "segment", "group", "branch", "region",
/// "class" or "part" (ASCII case ignored).
[[nodiscard]] bool labelLikeName(std::string_view name) noexcept;

/// The sorted distinct values of the scalar array `name` over all meshes of
/// `scene`, with their names (Mesh::labelNames, first mesh that names a
/// value wins), when every finite value is a whole number and there are at
/// most `limit` distinct ones; nullopt otherwise (also for vector arrays, no
/// finite value, or no mesh with the array).
[[nodiscard]] std::optional<std::vector<Label>> distinctLabels(const Scene& scene,
                                                               const std::string& name,
                                                               std::size_t limit = kMaxLabels);

/// The rule that decides when an array is shown as labels unless the user
/// says otherwise. Every finite value must be a whole number, and
///  - an array stored as integers (DataArray::integer, on every mesh that
///    has it) with a label-like name (labelLikeName(): segment_id from
///    centreline tools) is labels with up to kMaxLabels distinct values;
///  - otherwise at most kMaxAutoLabels distinct values, and the array is
///    stored as integers, or has a label-like name, or at most
///    kMaxUnhintedLabels distinct values.
/// So a float array of whole numbers with many distinct values (a rounded
/// pressure) stays continuous; the name only breaks the tie.
[[nodiscard]] bool looksCategorical(const Scene& scene, const std::string& name);

/// The labels of `name` (as distinctLabels()) when looksCategorical() holds,
/// else nullopt; one pass over the values. Never throws but std::bad_alloc.
[[nodiscard]] std::optional<std::vector<Label>> categoricalLabels(const Scene& scene,
                                                                  const std::string& name);

/// The display name of a label: its name from the file, else "Label <value>"
/// (translatable: QCoreApplication context "vv::render::Legend" in the
/// callers; this plain form is the English fallback for machine output).
[[nodiscard]] std::string labelText(const Label& label);

}  // namespace vv::scene
