// SPDX-License-Identifier: MIT
// Coordination number of a DEM snapshot (gc2d spec section 7 item 4): contacts per grain K, its
// distribution P(K) and mean, with the rattlers (grains without a stable force-bearing cage)
// found by iterative removal and reported apart.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "analysis/dem_geometry.hpp"
#include "analysis/table.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

struct CoordinationParams {
    bool countWalls = false;  ///< K also counts wall contacts (the rattler test always does)
    /// A contact bears force when |F| > forceThreshold * <|F|> (<|F|> over all contacts) [1].
    Real forceThreshold = 1e-9;
    /// Statistics over the grains whose centre lies in the rectangle (e.g. without the surface or
    /// boundary layers); all grains when unset. Rattler removal always runs on the whole packing.
    std::optional<Rect> region;
};

struct Coordination {
    std::vector<std::uint32_t> contactsPerGrain;  ///< K of every grain of the frame (file order)
    std::vector<char> rattler;                    ///< 1 for a rattler, per grain
    std::vector<char> selected;                   ///< 1 for a grain in the region, per grain
    std::vector<Real> probability;                ///< P(K) for K = 0, 1, ... over the selected grains
    std::vector<std::uint64_t> grainsWithK;       ///< selected grains with K contacts
    std::size_t grains = 0;                       ///< selected grains
    std::size_t rattlers = 0;                     ///< selected rattlers
    Real meanK = 0;  ///< <K> over the selected grains (all contacts, rattlers included)
    Real meanKNonRattler =
        0;  ///< <K> of the selected non-rattlers, force-bearing contacts between non-rattlers
    Real rattlerFraction = 0;    ///< rattlers / grains
    std::size_t unknownIds = 0;  ///< contacts naming an id missing from the grain frame (skipped)
    std::vector<std::string> notes;
};

/// K per grain: the grain-grain contacts (each contact line counts once for both grains) plus the
/// wall contacts when countWalls. Rattlers: a grain with fewer than 2 force-bearing contacts (wall
/// contacts included) is removed, which lowers its force-bearing neighbours' counts; repeated until
/// none is left (O(N + C) with a queue). Empty selection: NaN means and a note. Throws
/// std::invalid_argument for forceThreshold < 0 or a malformed rectangle.
Coordination coordination(const GrainFrame& grains, const ContactFrame& contacts,
                          const CoordinationParams& params = {});

/// Table "coordination": K [1], P [1], grains [1]; notes mean_K, mean_K_nonrattler,
/// rattler_fraction, grains, rattlers.
Table toTable(const Coordination& result);

}  // namespace granulab::analysis
