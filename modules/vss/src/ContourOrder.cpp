// SPDX-License-Identifier: GPL-3.0-or-later
// The border-following order of a contour list (see ContourOrder.h).
#include "ContourOrder.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <vector>

#include "vv/core/Error.h"

namespace vv::vss::detail {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

/// The 8 neighbour offsets: the 4-neighbours first (E, S, W, N), then the
/// diagonal ones (SE, SW, NW, NE). The walk's tie-break follows this order.
constexpr std::array<int, 8> kDx{1, 0, -1, 0, 1, -1, -1, 1};
constexpr std::array<int, 8> kDy{0, 1, 0, -1, 1, 1, -1, -1};

std::uint64_t pixelKey(std::int64_t x, std::int64_t y) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(y)) << 32U) |
           static_cast<std::uint64_t>(static_cast<std::uint32_t>(x));
}

/// An open-addressing hash table from a pixel to its id (linear probing; no
/// removal). Capacity: a power of two >= twice the number of pixels.
class PixelTable {
  public:
    explicit PixelTable(std::size_t pixels)
        : capacity_(std::bit_ceil(std::max<std::size_t>(16, 2 * pixels))),
          shift_(64 - std::countr_zero(capacity_)),
          keys_(capacity_, 0),
          ids_(capacity_, kNone) {}

    void insert(std::uint64_t key, std::uint32_t id) {
        std::size_t slot = home(key);
        while (ids_[slot] != kNone) {
            slot = (slot + 1) & (capacity_ - 1);
        }
        keys_[slot] = key;
        ids_[slot] = id;
    }

    [[nodiscard]] std::uint32_t find(std::uint64_t key) const {
        for (std::size_t slot = home(key);; slot = (slot + 1) & (capacity_ - 1)) {
            if (ids_[slot] == kNone || keys_[slot] == key) {
                return ids_[slot];
            }
        }
    }

  private:
    [[nodiscard]] std::size_t home(std::uint64_t key) const {
        return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ULL) >> shift_);
    }

    std::size_t capacity_;
    int shift_;
    std::vector<std::uint64_t> keys_;
    std::vector<std::uint32_t> ids_;
};

}  // namespace

ContourOrder orderAlongBorders(std::span<const ContourPoint> points) {
    ContourOrder order;
    const std::size_t n = points.size();
    if (n == 0) {
        return order;
    }
    if (n >= kNone) {
        throw InvalidArgumentError("orderAlongBorders: too many contour points");
    }

    // The input positions sorted row-major (ties: input order), and the
    // distinct pixels as runs of that list: pixel p is sorted[first[p] .. first[p + 1]).
    std::vector<std::uint32_t> sorted(n);
    std::iota(sorted.begin(), sorted.end(), std::uint32_t{0});
    std::sort(sorted.begin(), sorted.end(), [&](std::uint32_t a, std::uint32_t b) {
        const ContourPoint& pa = points[a];
        const ContourPoint& pb = points[b];
        if (pa.y != pb.y) {
            return pa.y < pb.y;
        }
        if (pa.x != pb.x) {
            return pa.x < pb.x;
        }
        return a < b;
    });
    std::vector<std::uint32_t> first;
    first.reserve(n + 1);
    for (std::size_t i = 0; i < n; ++i) {
        if (i == 0 || points[sorted[i]].x != points[sorted[i - 1]].x ||
            points[sorted[i]].y != points[sorted[i - 1]].y) {
            first.push_back(static_cast<std::uint32_t>(i));
        }
    }
    const std::size_t m = first.size();
    first.push_back(static_cast<std::uint32_t>(n));

    PixelTable table(m);
    for (std::size_t p = 0; p < m; ++p) {
        const ContourPoint& q = points[sorted[first[p]]];
        table.insert(pixelKey(q.x, q.y), static_cast<std::uint32_t>(p));
    }
    // The 8 neighbour ids of every pixel (kNone: not in the set).
    std::vector<std::uint32_t> neighbours(8 * m, kNone);
    constexpr std::int64_t lo = std::numeric_limits<int>::min();
    constexpr std::int64_t hi = std::numeric_limits<int>::max();
    for (std::size_t p = 0; p < m; ++p) {
        const ContourPoint& q = points[sorted[first[p]]];
        for (std::size_t d = 0; d < 8; ++d) {
            const std::int64_t x = std::int64_t{q.x} + kDx[d];
            const std::int64_t y = std::int64_t{q.y} + kDy[d];
            if (x >= lo && x <= hi && y >= lo && y <= hi) {
                neighbours[8 * p + d] = table.find(pixelKey(x, y));
            }
        }
    }

    std::vector<std::uint8_t> visited(m, 0);
    const auto unvisitedDegree = [&](std::uint32_t p) {
        int count = 0;
        for (std::size_t d = 0; d < 8; ++d) {
            const std::uint32_t q = neighbours[8 * p + d];
            count += static_cast<int>(q != kNone && visited[q] == 0);
        }
        return count;
    };
    // The next pixel of a walk from `p` (already visited), kNone when stuck.
    const auto step = [&](std::uint32_t p) {
        std::uint32_t best = kNone;
        int bestKey = std::numeric_limits<int>::max();
        for (std::size_t d = 0; d < 8; ++d) {
            const std::uint32_t q = neighbours[8 * p + d];
            if (q == kNone || visited[q] != 0) {
                continue;
            }
            const int degree = unvisitedDegree(q);
            // Fewest onward neighbours first (follows the border and picks up
            // side pixels before they are stranded), a dead end last; within a
            // degree, the direction order (4-neighbours before diagonal ones).
            const int key = (degree == 0 ? 9 : degree) * 8 + static_cast<int>(d);
            if (key < bestKey) {
                bestKey = key;
                best = q;
            }
        }
        return best;
    };
    const auto walk = [&](std::uint32_t from, std::vector<std::uint32_t>& out) {
        for (std::uint32_t q = step(from); q != kNone; q = step(q)) {
            visited[q] = 1;
            out.push_back(q);
        }
    };
    const auto emit = [&](std::uint32_t p) {
        for (std::uint32_t i = first[p]; i < first[p + 1]; ++i) {
            order.index.push_back(sorted[i]);
        }
    };

    order.index.reserve(n);
    std::vector<std::uint32_t> forward;
    std::vector<std::uint32_t> backward;
    for (std::uint32_t s = 0; s < m; ++s) {
        if (visited[s] != 0) {
            continue;
        }
        visited[s] = 1;
        forward.clear();
        backward.clear();
        forward.push_back(s);
        walk(s, forward);
        walk(s, backward);
        order.chainStart.push_back(static_cast<std::uint32_t>(order.index.size()));
        for (auto it = backward.rbegin(); it != backward.rend(); ++it) {
            emit(*it);
        }
        for (const std::uint32_t p : forward) {
            emit(p);
        }
    }
    return order;
}

}  // namespace vv::vss::detail
