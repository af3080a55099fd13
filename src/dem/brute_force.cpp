// SPDX-License-Identifier: MIT
// Brute-force broad phase: every pair tested; the reference for tests. Also the factory.
#include <algorithm>

#include "dem/broad_phase.hpp"
#include "geom/segment.hpp"

namespace granulab::dem {

void BruteForce::findPairs(const model::ParticleStore& s, Real margin, std::vector<std::uint64_t>& out) {
    out.clear();
    const std::size_t n = s.size();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            const Real dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i];
            const Real reach = s.radius[i] + s.radius[j] + margin;
            if (dx * dx + dy * dy < reach * reach)
                out.push_back(pairKey(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)));
        }
}

void BruteForce::findWallPairs(const model::ParticleStore& s, const model::WallSet& walls, Real margin,
                               std::vector<std::uint64_t>& out) {
    out.clear();
    for (std::size_t i = 0; i < s.size(); ++i)
        for (std::size_t seg = 0; seg < walls.segments.size(); ++seg) {
            const auto& w = walls.segments[seg];
            const Vec2 c{s.x[i], s.y[i]};
            const Vec2 q = w.a + (w.b - w.a) * geom::closestParameter(w.a, w.b, c);
            const Real reach = s.radius[i] + margin;
            if (norm2(c - q) < reach * reach)
                out.push_back(pairKey(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(seg)));
        }
}

std::unique_ptr<BroadPhase> makeBroadPhase(const std::string& name) {
    if (name == "brute_force") return std::make_unique<BruteForce>();
    if (name == "cell_grid") return std::make_unique<CellGrid>();
    if (name == "sort_and_sweep") return std::make_unique<SortAndSweep>();
    return nullptr;
}

std::vector<std::string> broadPhaseNames() {
    return {"auto", "cell_grid", "sort_and_sweep", "brute_force"};
}

}  // namespace granulab::dem
