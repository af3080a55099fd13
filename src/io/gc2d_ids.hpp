// SPDX-License-Identifier: MIT
// The ids of gc2d's files (gc2d spec 9.1, 9.4, 9.5; docs/coming-from-gc2d.md "Ids"): gc2d numbers
// walls and particles from one counter. granulab numbers the walls first, 0 .. W - 1 in the
// scene's wall order, and then every grain W + its granulab id (generation order: particles,
// blocks, heaps, then what sources insert), so an id never changes while grains come and go. The
// ggf, gff, gpf, gpl, gso and gco files all use these ids.
#pragma once
#include <cstdint>

namespace granulab::io {

struct Gc2dIds {
    std::int64_t wallCount = 0;  ///< W: walls of the scene at the start of the run

    std::int64_t wall(std::int64_t k) const noexcept { return k; }
    std::int64_t grain(std::int64_t granulabId) const noexcept { return wallCount + granulabId; }
    bool isWall(std::int64_t id) const noexcept { return id >= 0 && id < wallCount; }
    /// The granulab id of gc2d id `id` (>= W).
    std::int64_t granulabGrain(std::int64_t id) const noexcept { return id - wallCount; }
};

}  // namespace granulab::io
