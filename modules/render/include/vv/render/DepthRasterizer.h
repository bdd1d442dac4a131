// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <stop_token>

#include "vv/core/Image.h"
#include "vv/render/Camera.h"
#include "vv/scene/Mesh.h"

namespace vv::render {

/// One indexed triangle list to rasterise: three indices per triangle into
/// `positions` (world space). The spans must outlive the call.
struct TriangleList {
    std::span<const glm::vec3> positions;
    std::span<const std::uint32_t> indices;
};

/// A deterministic CPU depth rasteriser: no GL, no GPU; a given build gives the
/// same image on every run and for any number of threads.
///
/// The result is a width × height image of LINEAR view depth: the distance of
/// the nearest surface along the view axis (-z in view space), in scene units,
/// and +Inf where no triangle covers the pixel centre (background).
///
/// Conventions and promises:
/// - Row 0 is the top of the image (+y down, like Camera's pixel coordinates);
///   pixel (x, y) is sampled at its centre (x + 0.5, y + 0.5).
/// - The projection is applied as given (OpenGL clip space, NDC in [-1, 1]);
///   depth is interpolated perspective-correctly, in double precision, from the
///   exact per-vertex view depths: a triangle at one depth d gives exactly d.
/// - Triangles are clipped against the near plane (z_clip >= -w_clip); parts
///   behind it are cut away, the rest is drawn. There is no far clipping and no
///   back-face culling (either winding is drawn); degenerate triangles and
///   triangles with non-finite vertices are skipped.
/// - Coverage: a pixel centre strictly inside a triangle is covered; one exactly
///   on an edge belongs to exactly one of the two triangles sharing that edge
///   (a consistent tie rule on canonically ordered edges), so closed surfaces
///   have no cracks and no doubly covered pixels along shared edges.
/// - Z-buffered with the minimum depth, which does not depend on drawing order:
///   tiles are rasterised in parallel (vv::parallelForTiles) and the result is
///   bit-identical for any VV_THREADS.
///
/// Throws InvalidArgumentError for width or height below 1 or above 32768,
/// an index list whose size is not a multiple of 3, or an index out of range;
/// CancelledError when `stop` is requested.
[[nodiscard]] Image<float> rasterizeDepth(std::span<const TriangleList> lists,
                                          const glm::mat4& view, const glm::mat4& projection,
                                          int width, int height, const std::stop_token& stop = {});

/// Every mesh of `scene` seen through `camera` (its view and projection
/// matrices), at the camera's viewport size. Throws as above.
[[nodiscard]] Image<float> rasterizeDepth(const scene::Scene& scene, const Camera& camera,
                                          const std::stop_token& stop = {});

}  // namespace vv::render
