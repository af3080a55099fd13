// SPDX-License-Identifier: MIT
// The fixed split of the particle slots into tiles, the unit of work of the threaded DEM step
// (gc2d spec section 5.4; docs/physics/dem-threads.md). Slots are sorted along a space-filling
// curve (CellGrid::spatialOrder), so a tile is a compact patch of the packing and most contacts
// join two grains of one tile. The tiles depend on the particle count only, never on the number
// of threads: every sum over tiles, and the order in which a grain's forces are added, is the
// same for 1, 2, 3, ... threads, which makes the results bit-identical.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace granulab::dem {

struct SlotTiles {
    /// Fewest slots in a tile (small tiles make most contacts cross a tile border).
    static constexpr std::uint32_t kMinSlots = 128;
    /// Most tiles (enough to balance 16 threads or more with a dynamic schedule).
    static constexpr std::uint32_t kMaxTiles = 256;

    std::uint32_t slotsPerTile = kMinSlots;
    std::uint32_t count = 0;  ///< tiles
    std::uint32_t slots = 0;  ///< particles covered

    /// The tiles of n particles: ceil(n / 256) slots per tile, at least minSlots (tests vary it).
    static SlotTiles forParticles(std::size_t n, std::uint32_t minSlots = kMinSlots) noexcept {
        SlotTiles t;
        t.slots = static_cast<std::uint32_t>(n);
        t.slotsPerTile = std::max<std::uint32_t>(std::max<std::uint32_t>(minSlots, 1),
                                                 static_cast<std::uint32_t>((n + kMaxTiles - 1) / kMaxTiles));
        t.count = static_cast<std::uint32_t>((n + t.slotsPerTile - 1) / t.slotsPerTile);
        return t;
    }
    std::uint32_t tileOf(std::uint32_t slot) const noexcept { return slot / slotsPerTile; }
    std::uint32_t begin(std::uint32_t tile) const noexcept { return tile * slotsPerTile; }
    std::uint32_t end(std::uint32_t tile) const noexcept {
        return std::min(slots, (tile + 1) * slotsPerTile);
    }
};

}  // namespace granulab::dem
