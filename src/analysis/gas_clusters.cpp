// SPDX-License-Identifier: MIT
// Cluster search and cluster-size statistics (edmd spec section 5.2, eqs. 5.11-5.15).
//
// Why this layout: the search runs union-find in *slot* space (particles in cell order, see
// gas_cell_grid.hpp), so the pair loop reads positions, radii and the union-find parents nearly
// sequentially; only the final labelling pass goes back to particle order. Each unordered pair of
// adjacent cells is visited once, so every candidate pair is tested once. The dimension is a
// template parameter so the distance loop unrolls.
#include "analysis/gas_clusters.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "analysis/gas_cell_grid.hpp"

namespace granulab::analysis {

namespace {

/// Disjoint sets over 0..n-1 with path halving and union by size (Tarjan & van Leeuwen 1984).
class UnionFind {
public:
    explicit UnionFind(std::size_t n) : m_parent(n), m_size(n, 1) {
        for (std::size_t i = 0; i < n; ++i) m_parent[i] = static_cast<std::uint32_t>(i);
    }

    std::uint32_t find(std::uint32_t i) noexcept {
        while (m_parent[i] != i) {
            m_parent[i] = m_parent[m_parent[i]];  // path halving
            i = m_parent[i];
        }
        return i;
    }

    void unite(std::uint32_t a, std::uint32_t b) noexcept {
        a = find(a);
        b = find(b);
        if (a == b) return;
        if (m_size[a] < m_size[b]) std::swap(a, b);
        m_parent[b] = a;
        m_size[a] += m_size[b];
    }

private:
    std::vector<std::uint32_t> m_parent;
    std::vector<std::uint32_t> m_size;
};

/// Unites every pair of slots whose centre distance is < (r_a + r_b) * linkFactor.
template <int D>
void linkNeighbours(const CellGrid& grid, const std::vector<Real>& slotRadius, Real linkFactor,
                    UnionFind& sets) {
    const Real* radius = slotRadius.data();
    forEachNearPair<D>(grid, [&](std::uint32_t a, std::uint32_t b, Real distance2) {
        const Real reach = (radius[a] + radius[b]) * linkFactor;  // [m]
        if (distance2 < reach * reach) sets.unite(a, b);
    });
}

}  // namespace

ClusterResult findClusters(const PointSet& points, Real deltaRatio) {
    checkPointSet(points, "findClusters");
    if (!(deltaRatio >= 0) || !std::isfinite(deltaRatio))
        throw std::invalid_argument("findClusters: deltaRatio must be >= 0, got " +
                                    std::to_string(deltaRatio));
    const std::size_t n = points.size();
    ClusterResult result;
    if (n == 0) return result;

    const Real linkFactor = 1 + deltaRatio;  // eq. 5.11: centre distance < (r_i + r_j)(1 + delta/2a)
    const Real maxRadius = *std::max_element(points.radius.begin(), points.radius.end());  // [m]
    if (!(maxRadius >= 0) || !std::isfinite(maxRadius))
        throw std::invalid_argument("findClusters: radii must be finite and >= 0");
    Real maxLink = 2 * maxRadius * linkFactor;                     // [m] largest link distance
    if (maxLink <= 0) maxLink = std::numeric_limits<Real>::min();  // zero radii: nothing links
    const CellGrid grid = buildCellGrid(points, maxLink, 2 * n);

    std::vector<Real> slotRadius(n);
    for (std::size_t s = 0; s < n; ++s) slotRadius[s] = points.radius[grid.particle[s]];
    UnionFind sets(n);
    if (points.dim == 2) {
        linkNeighbours<2>(grid, slotRadius, linkFactor, sets);
    } else {
        linkNeighbours<3>(grid, slotRadius, linkFactor, sets);
    }

    // Labels in order of each cluster's lowest particle index, in three passes that touch memory
    // mostly in slot or particle order: lowest particle of every root, a scan over particle
    // indices that numbers the roots, then the labels.
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> rootOf(n);
    std::vector<std::uint32_t> lowest(n, kNone);  // per root: lowest particle index
    for (std::uint32_t s = 0; s < n; ++s) {
        rootOf[s] = sets.find(s);
        lowest[rootOf[s]] = std::min(lowest[rootOf[s]], grid.particle[s]);
    }
    std::vector<std::uint32_t> firstOf(n, kNone);  // per particle index: the root it is lowest of
    for (std::uint32_t s = 0; s < n; ++s)
        if (lowest[s] != kNone) firstOf[lowest[s]] = s;
    std::vector<std::uint32_t>& labelOfRoot = lowest;  // reused: lowest is no longer needed
    for (std::size_t i = 0; i < n; ++i) {
        if (firstOf[i] == kNone) continue;
        labelOfRoot[firstOf[i]] = static_cast<std::uint32_t>(result.sizes.size());
        result.sizes.push_back(0);
    }
    result.label.resize(n);
    for (std::uint32_t s = 0; s < n; ++s) {
        const std::uint32_t label = labelOfRoot[rootOf[s]];
        result.label[grid.particle[s]] = label;
        ++result.sizes[label];
    }
    return result;
}

std::vector<Real> smoothHoles(const std::vector<std::uint32_t>& sizeCounts) {
    std::vector<Real> smoothed(sizeCounts.size(), 0);
    std::size_t previous = 0;  // r: last size with n_r > 0 (0 before the first)
    for (std::size_t s = 1; s < sizeCounts.size(); ++s) {
        if (sizeCounts[s] == 0) continue;
        const Real spread = static_cast<Real>(sizeCounts[s]) / static_cast<Real>(s - previous);
        for (std::size_t k = previous + 1; k <= s; ++k) smoothed[k] = spread;  // footnote 5
        previous = s;
    }
    return smoothed;
}

ClusterStats computeClusterStats(const std::vector<std::uint32_t>& sizes, std::size_t particleCount) {
    ClusterStats stats;
    stats.particleCount = particleCount;
    std::size_t total = 0;
    for (const std::uint32_t s : sizes) {
        if (s == 0) throw std::invalid_argument("computeClusterStats: a cluster of size 0");
        total += s;
        stats.largest = std::max(stats.largest, s);
    }
    if (total != particleCount)
        throw std::invalid_argument("computeClusterStats: the sizes add up to " + std::to_string(total) +
                                    ", not to N = " + std::to_string(particleCount));
    if (sizes.empty()) return stats;

    stats.clusterCount = sizes.size();
    stats.sizeCounts.assign(std::size_t{stats.largest} + 1, 0);
    for (const std::uint32_t s : sizes) ++stats.sizeCounts[s];
    // eq. 5.12 summed over sizes: M_k = (1/n_tot) sum_s s^k n_s
    std::array<Real, 4> sum{};
    for (std::size_t s = 1; s < stats.sizeCounts.size(); ++s) {
        if (stats.sizeCounts[s] == 0) continue;
        const auto size = static_cast<Real>(s);
        const auto count = static_cast<Real>(stats.sizeCounts[s]);
        sum[0] += count;
        sum[1] += count * size;
        sum[2] += count * size * size;
        sum[3] += count * size * size * size;
    }
    const auto clusterCount = static_cast<Real>(stats.clusterCount);
    const auto largest = static_cast<Real>(stats.largest);
    Real largestPower = 1;  // N_x^k
    for (std::size_t k = 0; k < 4; ++k) {
        stats.moment[k] = sum[k] / clusterCount;
        stats.reducedMoment[k] = stats.moment[k] - largestPower / clusterCount;  // eq. 5.14
        largestPower *= largest;
    }
    stats.largestFraction = largest / static_cast<Real>(particleCount);  // eq. 5.13
    stats.smoothedCounts = smoothHoles(stats.sizeCounts);
    return stats;
}

Real tauPeak(const std::vector<Real>& times, const std::vector<Real>& reducedM2) {
    if (times.empty() || times.size() != reducedM2.size())
        throw std::invalid_argument("tauPeak: times and M'_2 must be non-empty and of equal length");
    const auto peak =
        static_cast<std::size_t>(std::max_element(reducedM2.begin(), reducedM2.end()) - reducedM2.begin());
    if (peak == 0 || peak + 1 == times.size()) return times[peak];

    // Vertex of the parabola through (t0, y0), (t1, y1), (t2, y2) (Lagrange form, uneven spacing).
    const Real t0 = times[peak - 1], t1 = times[peak], t2 = times[peak + 1];
    const Real y0 = reducedM2[peak - 1], y1 = reducedM2[peak], y2 = reducedM2[peak + 1];
    const Real slope01 = (y1 - y0) / (t1 - t0);  // first divided differences
    const Real slope12 = (y2 - y1) / (t2 - t1);
    const Real curvature = (slope12 - slope01) / (t2 - t0);        // second divided difference
    if (!(curvature < 0) || !std::isfinite(curvature)) return t1;  // flat top: no refinement
    const Real vertex = 0.5 * (t0 + t1) - slope01 / (2 * curvature);
    return std::clamp(vertex, std::min(t0, t2), std::max(t0, t2));
}

}  // namespace granulab::analysis
