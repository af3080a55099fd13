// SPDX-License-Identifier: MIT
// Geometry of gc2d's generators (spec section 6.5: GENERATE_BLOCK lattices and the regular piles
// of the Perl heap library heap.pm), shared by the scene checks (io/), the particle budget and
// generation (dem/): nearest site distances, a heap's grain footprint, pitches and limits, and
// an upper estimate of a heap's grain count. Pure functions; lengths in m, angles in rad.
#pragma once
#include <optional>
#include <vector>

#include "model/dem_def.hpp"

namespace granulab::model {

/// Smallest centre distance [m] between two sites of a lattice block before jitter: spacing
/// (hexagonal, square), min(dx, dy) (rect), min(dx, 2 dy, hypot(dx/2, dy)) (fcc); 0 for random
/// blocks and invalid spacings.
Real nearestSiteDistance(const BlockDef& b) noexcept;

/// The grain of a heap as the stacking sees it: disk-like (a disk, or a regular [[shape]] by its
/// circumcircle) or rectangle-like (plain `size` rectangles, or a rectangle [[shape]]).
struct HeapGrain {
    bool diskLike = true;
    Real width = 0;                   ///< [m] footprint along x: 2 r (disk-like) or a
    Real height = 0;                  ///< [m] footprint along y: 2 r (disk-like) or b
    const ShapeDef* shape = nullptr;  ///< the named [[shape]], or nullptr (disk or plain rectangle)
};

/// The grain of heap `h`; nullopt when its shape is unknown, of another kind, or its sizes are not
/// positive (the checks report which).
std::optional<HeapGrain> heapGrain(const HeapDef& h, const std::vector<ShapeDef>& shapes);

/// Centre distances [m]: `along` between row neighbours (width + gap x), `rows` between rows:
/// height + gap y, except hexagonal disk-like stacks, where a grain rests on the two below at
/// centre distance 2 r + gap y: rows = sqrt((2 r + gap y)^2 - (along / 2)^2).
struct HeapPitch {
    Real along = 0;
    Real rows = 0;
};
HeapPitch heapPitch(const HeapDef& h, const HeapGrain& g) noexcept;

/// Steepest allowed slope [rad] (exclusive): hexagonal stacks arctan(2 height / width) (gc2d:
/// arctan 2 for discs and squares, arctan(2b/a) for rectangles: steeper flanks would overhang);
/// rectangular stacks pi/2.
Real heapMaxSlope(const HeapDef& h, const HeapGrain& g) noexcept;

/// Largest gap along x [m] of a hexagonal stack: disk-like grains 2 sqrt((2 r + gap y)^2 - r^2) -
/// 2 r (inclusive: each grain rests on the two below and rows two apart do not overlap),
/// rectangle-like grains a (exclusive: a grain must rest on two). Infinite for rectangular stacks.
Real heapMaxGapX(const HeapDef& h, const HeapGrain& g) noexcept;

/// Upper estimate of the number of grains of heap `h` (rows times sites per row), before
/// generation; 0 for an invalid heap (the checks report it). May be inf.
double heapSiteEstimate(const HeapDef& h, const std::vector<ShapeDef>& shapes) noexcept;

}  // namespace granulab::model
