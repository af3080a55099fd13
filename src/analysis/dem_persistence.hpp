// SPDX-License-Identifier: MIT
// Contact persistence between two DEM snapshots (gc2d spec section 7 item 11, the cluster-motion
// diagnostic of section 8.8): the fraction of grain pairs in contact before (the outlet opens)
// that are still in contact after (the final heap), optionally within a region (region C).
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "analysis/dem_geometry.hpp"
#include "analysis/table.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

struct PersistenceParams {
    /// Count only pairs whose both grains lie (centre, in the `after` grain frame) inside this
    /// rectangle; a grain missing from that frame (it left) is outside. Unset: every pair.
    std::optional<Rect> region;
};

struct ContactPersistence {
    std::size_t pairsBefore = 0;  ///< distinct unordered grain-grain id pairs in contact before (selected)
    std::size_t pairsKept = 0;    ///< of those, pairs also in contact after
    std::size_t pairsAfter = 0;   ///< distinct grain-grain pairs in contact after (all, for reference)
    Real fraction = 0;            ///< pairsKept / pairsBefore (NaN when pairsBefore = 0)
    std::vector<std::string> notes;
};

/// Unordered id pairs {a, b} of the grain-grain contacts (wall contacts ignored, duplicates counted
/// once). `afterGrains` is read only with a region. Throws std::invalid_argument for a malformed
/// rectangle. Cost O(C log C + N).
ContactPersistence contactPersistence(const ContactFrame& before, const ContactFrame& after,
                                      const GrainFrame& afterGrains, const PersistenceParams& params = {});

/// One-row table "contact_persistence": pairs_before [1], pairs_kept [1], pairs_after [1], fraction [1].
Table toTable(const ContactPersistence& result);

}  // namespace granulab::analysis
