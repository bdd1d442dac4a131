// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: handing a container's memory back.
#pragma once

#include <utility>

namespace vv::analysis::detail {

/// Empties `container` and frees its memory. (`container = {}` does not:
/// for a std::vector it assigns an empty initializer list, which keeps the
/// capacity; the analysis frees large arrays as soon as they are done with
/// to keep its peak down.)
template <class Container>
void release(Container& container) {
    Container().swap(container);
}

}  // namespace vv::analysis::detail
