// SPDX-License-Identifier: MIT
// Coordination number and rattlers of a DEM snapshot (gc2d spec section 7 item 4).
#include "analysis/dem_coordination.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "analysis/table_note.hpp"

namespace granulab::analysis {

namespace {

constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();
constexpr std::size_t kWall = std::numeric_limits<std::size_t>::max();

/// One contact as the grain sees it.
struct Link {
    std::size_t other;  ///< grain index, kWall at a wall
    bool bearing;       ///< |F| above the threshold
};

/// Contacts per grain in compressed rows: grain i's links are links[start[i] .. start[i + 1]).
struct Adjacency {
    std::vector<std::size_t> start;
    std::vector<Link> links;
    std::size_t unknownIds = 0;  ///< contacts naming an id missing from the grains (skipped)
};

Adjacency buildAdjacency(const GrainFrame& grains, const ContactFrame& contacts, Real threshold) {
    const auto index = indexById(grains);
    Adjacency adj;
    adj.start.assign(grains.size() + 1, 0);
    // Grain indices of each contact's ends (kWall at a wall); `known` false for unknown ids.
    std::vector<std::pair<std::size_t, std::size_t>> ends(contacts.size(), {kWall, kWall});
    std::vector<char> known(contacts.size(), 0);
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const auto a = index.find(contacts.a[k]);
        const auto b = contacts.atWall(k) ? index.end() : index.find(contacts.b[k]);
        if (a == index.end() || (!contacts.atWall(k) && b == index.end())) {
            ++adj.unknownIds;
            continue;
        }
        known[k] = 1;
        ends[k] = {a->second, contacts.atWall(k) ? kWall : b->second};
        ++adj.start[ends[k].first + 1];
        if (ends[k].second != kWall) ++adj.start[ends[k].second + 1];
    }
    for (std::size_t i = 0; i < grains.size(); ++i) adj.start[i + 1] += adj.start[i];
    adj.links.resize(adj.start.back());
    std::vector<std::size_t> next = adj.start;  // next free slot per grain
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        if (!known[k]) continue;
        const bool bearing = std::hypot(contacts.fx[k], contacts.fy[k]) > threshold;
        const auto [a, b] = ends[k];
        adj.links[next[a]++] = {b, bearing};
        if (b != kWall) adj.links[next[b]++] = {a, bearing};
    }
    return adj;
}

}  // namespace

Coordination coordination(const GrainFrame& grains, const ContactFrame& contacts,
                          const CoordinationParams& params) {
    if (!(params.forceThreshold >= 0) || !std::isfinite(params.forceThreshold))
        throw std::invalid_argument("coordination: forceThreshold must be finite and >= 0");
    if (params.region) checkRect(*params.region, "coordination");
    const std::size_t n = grains.size();
    Coordination r;
    r.contactsPerGrain.assign(n, 0);
    r.rattler.assign(n, 0);
    r.selected.assign(n, 1);
    if (params.region)
        for (std::size_t i = 0; i < n; ++i)
            r.selected[i] = params.region->contains(grains.x[i], grains.y[i]) ? 1 : 0;

    Real forceSum = 0;  // [N]
    for (std::size_t k = 0; k < contacts.size(); ++k) forceSum += std::hypot(contacts.fx[k], contacts.fy[k]);
    const Real threshold = contacts.size() > 0
                               ? params.forceThreshold * forceSum / static_cast<Real>(contacts.size())
                               : 0;  // [N]

    const Adjacency adjacency = buildAdjacency(grains, contacts, threshold);
    const std::vector<std::size_t>& start = adjacency.start;
    const std::vector<Link>& links = adjacency.links;
    r.unknownIds = adjacency.unknownIds;

    // K and the force-bearing counts.
    std::vector<std::uint32_t> bearingCount(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t l = start[i]; l < start[i + 1]; ++l) {
            if (links[l].other != kWall || params.countWalls) ++r.contactsPerGrain[i];
            if (links[l].bearing) ++bearingCount[i];
        }

    // Iterative rattler removal.
    std::vector<std::size_t> queue;
    for (std::size_t i = 0; i < n; ++i)
        if (bearingCount[i] < 2) {
            r.rattler[i] = 1;
            queue.push_back(i);
        }
    for (std::size_t q = 0; q < queue.size(); ++q) {
        const std::size_t i = queue[q];
        for (std::size_t l = start[i]; l < start[i + 1]; ++l) {
            const std::size_t j = links[l].other;
            if (j == kWall || !links[l].bearing || r.rattler[j]) continue;
            if (--bearingCount[j] < 2) {
                r.rattler[j] = 1;
                queue.push_back(j);
            }
        }
    }

    // Statistics over the selection.
    Real sumK = 0, sumKStable = 0;
    std::size_t stable = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!r.selected[i]) continue;
        ++r.grains;
        const std::uint32_t k = r.contactsPerGrain[i];
        if (r.grainsWithK.size() <= k) r.grainsWithK.resize(k + 1, 0);
        ++r.grainsWithK[k];
        sumK += k;
        if (r.rattler[i]) {
            ++r.rattlers;
            continue;
        }
        ++stable;
        for (std::size_t l = start[i]; l < start[i + 1]; ++l) {
            const std::size_t j = links[l].other;
            if (!links[l].bearing) continue;
            if (j == kWall ? params.countWalls : !r.rattler[j]) sumKStable += 1;
        }
    }
    r.probability.resize(r.grainsWithK.size());
    for (std::size_t k = 0; k < r.grainsWithK.size(); ++k)
        r.probability[k] = static_cast<Real>(r.grainsWithK[k]) / static_cast<Real>(r.grains);
    r.meanK = r.grains > 0 ? sumK / static_cast<Real>(r.grains) : kNaN;
    r.rattlerFraction = r.grains > 0 ? static_cast<Real>(r.rattlers) / static_cast<Real>(r.grains) : kNaN;
    r.meanKNonRattler = stable > 0 ? sumKStable / static_cast<Real>(stable) : kNaN;
    if (r.grains == 0)
        r.notes.push_back("warning: no grain selected; the means are undefined (NaN)");
    else if (stable == 0)
        r.notes.push_back("warning: every selected grain is a rattler; mean_K_nonrattler is NaN");
    if (r.unknownIds > 0)
        r.notes.push_back(fmt::format(
            "warning: {} contacts name grain ids missing from the grain frame (skipped)", r.unknownIds));
    return r;
}

Table toTable(const Coordination& result) {
    Table t;
    t.name = "coordination";
    t.add("K", "1");  // filled below: add() returns a reference into the column vector
    t.add("P", "1").values = result.probability;
    t.add("grains", "1").values.assign(result.grainsWithK.begin(), result.grainsWithK.end());
    for (std::size_t i = 0; i < result.probability.size(); ++i)
        t.columns[0].values.push_back(static_cast<Real>(i));
    t.notes.push_back(noteLine("mean_K", result.meanK));
    t.notes.push_back(noteLine("mean_K_nonrattler", result.meanKNonRattler));
    t.notes.push_back(noteLine("rattler_fraction", result.rattlerFraction));
    t.notes.push_back(noteLine("grains", static_cast<Real>(result.grains)));
    t.notes.push_back(noteLine("rattlers", static_cast<Real>(result.rattlers)));
    for (const std::string& n : result.notes) t.notes.push_back(n);
    return t;
}

}  // namespace granulab::analysis
