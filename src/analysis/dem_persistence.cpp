// SPDX-License-Identifier: MIT
// Contact persistence between two DEM snapshots (gc2d spec section 7 item 11).
#include "analysis/dem_persistence.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <unordered_set>
#include <utility>

#include "analysis/table_note.hpp"

namespace granulab::analysis {

namespace {

using Pair = std::pair<std::int64_t, std::int64_t>;

/// Sorted distinct unordered grain-grain pairs (smaller id first).
std::vector<Pair> grainPairs(const ContactFrame& c) {
    std::vector<Pair> pairs;
    pairs.reserve(c.size());
    for (std::size_t k = 0; k < c.size(); ++k) {
        if (c.atWall(k) || c.b[k] < 0) continue;
        pairs.emplace_back(std::min(c.a[k], c.b[k]), std::max(c.a[k], c.b[k]));
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
}

}  // namespace

ContactPersistence contactPersistence(const ContactFrame& before, const ContactFrame& after,
                                      const GrainFrame& afterGrains, const PersistenceParams& params) {
    if (params.region) checkRect(*params.region, "contactPersistence");
    std::vector<Pair> old = grainPairs(before);
    const std::vector<Pair> now = grainPairs(after);
    if (params.region) {
        std::unordered_set<std::int64_t> inside;
        for (std::size_t i = 0; i < afterGrains.size(); ++i)
            if (params.region->contains(afterGrains.x[i], afterGrains.y[i])) inside.insert(afterGrains.id[i]);
        std::erase_if(old,
                      [&](const Pair& p) { return !inside.contains(p.first) || !inside.contains(p.second); });
    }
    ContactPersistence r;
    r.pairsBefore = old.size();
    r.pairsAfter = now.size();
    for (const Pair& p : old) r.pairsKept += std::binary_search(now.begin(), now.end(), p) ? 1 : 0;
    r.fraction = r.pairsBefore > 0 ? static_cast<Real>(r.pairsKept) / static_cast<Real>(r.pairsBefore)
                                   : std::numeric_limits<Real>::quiet_NaN();
    if (r.pairsBefore == 0)
        r.notes.push_back("warning: no grain pair in contact before (in the region); fraction NaN");
    return r;
}

Table toTable(const ContactPersistence& result) {
    Table t;
    t.name = "contact_persistence";
    t.add("pairs_before", "1").values = {static_cast<Real>(result.pairsBefore)};
    t.add("pairs_kept", "1").values = {static_cast<Real>(result.pairsKept)};
    t.add("pairs_after", "1").values = {static_cast<Real>(result.pairsAfter)};
    t.add("fraction", "1").values = {result.fraction};
    t.notes.push_back(
        "fraction of the grain pairs in contact before that are in contact after (gc2d spec 7 item 11)");
    t.notes.push_back(noteLine("persistence_fraction", result.fraction));
    for (const std::string& n : result.notes) t.notes.push_back(n);
    return t;
}

}  // namespace granulab::analysis
