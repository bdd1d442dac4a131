// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::analysis: handing a container's memory back.
#pragma once

#include <utility>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace vv::analysis::detail {

/// Empties `container` and frees its memory. (`container = {}` does not:
/// for a std::vector it assigns an empty initializer list, which keeps the
/// capacity; the analysis frees large arrays as soon as they are done with
/// to keep its peak down.)
template <class Container>
void release(Container& container) {
    Container().swap(container);
}

/// Hands the heap's free pages back to the system (glibc: malloc_trim,
/// which also releases whole free pages inside the heap and the other
/// threads' arenas; elsewhere nothing). Called where a stage has freed
/// large arrays and the next one allocates others of other sizes: without
/// it the freed ones stay resident beside the new (glibc raises its
/// threshold for mapping large blocks as they are freed, so later large
/// arrays come from the heap and fit none of its holes).
inline void handBackFreedMemory() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

}  // namespace vv::analysis::detail
