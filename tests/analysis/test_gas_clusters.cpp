// SPDX-License-Identifier: MIT
// Cluster search and cluster-size statistics (edmd spec 5.2, eqs. 5.11-5.15, footnote 5):
// against an O(N^2) union-find, on hand-built configurations, and on moment identities.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "analysis/gas_clusters.hpp"
#include "gas_points.hpp"

namespace granulab {
namespace {

using analysis::ClusterResult;
using analysis::PointSet;

/// O(N^2) reference: links every pair closer than (r_i + r_j)(1 + delta), union-find without
/// any heuristics, labels in order of the lowest particle index. Counts the links that cross a
/// periodic boundary (raw coordinate difference above half the box) into outCrossing.
ClusterResult bruteForceClusters(const PointSet& p, Real deltaRatio, std::size_t& outCrossing) {
    const std::size_t n = p.size();
    std::vector<std::size_t> parent(n);
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    auto root = [&parent](std::size_t i) {
        while (parent[i] != i) i = parent[i];
        return i;
    };
    const auto dim = static_cast<std::size_t>(p.dim);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            const Real reach = (p.radius[i] + p.radius[j]) * (1 + deltaRatio);
            if (test::bruteDistance2(p, i, j) >= reach * reach) continue;
            parent[root(j)] = root(i);
            for (std::size_t d = 0; d < dim; ++d)
                if (p.periodic[d] && std::abs(p.x[j * dim + d] - p.x[i * dim + d]) > 0.5 * p.box[d]) {
                    ++outCrossing;
                    break;
                }
        }
    }
    ClusterResult r;
    std::vector<std::uint32_t> labelOfRoot(n, UINT32_MAX);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t top = root(i);
        if (labelOfRoot[top] == UINT32_MAX) {
            labelOfRoot[top] = static_cast<std::uint32_t>(r.sizes.size());
            r.sizes.push_back(0);
        }
        r.label.push_back(labelOfRoot[top]);
        ++r.sizes[labelOfRoot[top]];
    }
    return r;
}

/// Compares findClusters with the brute force; returns the boundary-crossing links.
std::size_t expectSameAsBruteForce(const PointSet& p, Real deltaRatio = 0.1) {
    std::size_t crossing = 0;
    const ClusterResult expected = bruteForceClusters(p, deltaRatio, crossing);
    const ClusterResult got = analysis::findClusters(p, deltaRatio);
    EXPECT_EQ(got.label, expected.label);
    EXPECT_EQ(got.sizes, expected.sizes);
    return crossing;
}

TEST(GasClusters, MatchesBruteForce2DPolydisperse) {
    // nu ~ 0.3, radii 0.5..1.5 [m]: clusters of all sizes, links across both periodic edges.
    const PointSet p = test::randomPoints(2, 3000, {200, 170, 1}, 0.5, 1.5, 11);
    const std::size_t crossing = expectSameAsBruteForce(p);
    EXPECT_GT(crossing, 5u);
    const ClusterResult r = analysis::findClusters(p);
    EXPECT_GT(r.sizes.size(), 100u);
    EXPECT_GT(*std::max_element(r.sizes.begin(), r.sizes.end()), 5u);
}

TEST(GasClusters, MatchesBruteForce3DPolydisperse) {
    const PointSet p = test::randomPoints(3, 3000, {40, 45, 35}, 0.5, 1.5, 12);  // nu ~ 0.25
    const std::size_t crossing = expectSameAsBruteForce(p);
    EXPECT_GT(crossing, 5u);
    const ClusterResult r = analysis::findClusters(p);
    EXPECT_GT(r.sizes.size(), 100u);
    EXPECT_GT(*std::max_element(r.sizes.begin(), r.sizes.end()), 5u);
}

TEST(GasClusters, MatchesBruteForceWithOneOrTwoCellsPerAxis) {
    // Largest link 1.32 m: box 2 x 3 x 8 [m] gives 1, 2 and 6 cells, so wrapped neighbour cells
    // coincide; several seeds and delta ratios, 3D and 2D.
    std::size_t crossing = 0;
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        crossing += expectSameAsBruteForce(test::randomPoints(3, 40, {2.0, 3.0, 8.0}, 0.2, 0.6, 100 + seed));
        crossing +=
            expectSameAsBruteForce(test::randomPoints(2, 30, {2.0, 7.0, 1.0}, 0.2, 0.6, 200 + seed), 0.3);
    }
    EXPECT_GT(crossing, 50u);
}

TEST(GasClusters, MatchesBruteForceWithAWall) {
    // Non-periodic y axis: no links through y = 0 / y = box.
    PointSet p = test::randomPoints(3, 1500, {30, 30, 30}, 0.5, 1.5, 13);
    p.periodic = {true, false, true};
    expectSameAsBruteForce(p);
}

TEST(GasClusters, HandBuiltChainsGiveExactSizesAndMoments) {
    // Disks of radius 0.5 m (2a = 1 m): linked iff centre distance < 1.1 m. A: a 5-chain with
    // spacing 1.05 m that wraps through x = 0; C: an L of 3; B, D: singletons 1.15 m apart.
    PointSet p;
    p.dim = 2;
    p.box = {20, 20, 1};
    p.x = {19.5, 5,     10,  10, 5,    15,    0.55, 5, 10,  11.15,  // A B C A D
           5,    16.05, 1.6, 5,  6.05, 16.05, 2.65, 5, 3.7, 5};     // C A C A A
    p.radius.assign(10, 0.5);
    const ClusterResult r = analysis::findClusters(p);
    EXPECT_EQ(r.label, (std::vector<std::uint32_t>{0, 1, 2, 0, 3, 2, 0, 2, 0, 0}));
    EXPECT_EQ(r.sizes, (std::vector<std::uint32_t>{5, 1, 3, 1}));

    const analysis::ClusterStats s = analysis::computeClusterStats(r.sizes, p.size());
    EXPECT_EQ(s.clusterCount, 4u);
    EXPECT_EQ(s.largest, 5u);
    EXPECT_DOUBLE_EQ(s.largestFraction, 0.5);
    EXPECT_DOUBLE_EQ(s.moment[0], 1.0);
    EXPECT_DOUBLE_EQ(s.moment[1], 10.0 / 4);   // (5 + 1 + 3 + 1) / 4
    EXPECT_DOUBLE_EQ(s.moment[2], 36.0 / 4);   // (25 + 1 + 9 + 1) / 4
    EXPECT_DOUBLE_EQ(s.moment[3], 154.0 / 4);  // (125 + 1 + 27 + 1) / 4
    EXPECT_DOUBLE_EQ(s.reducedMoment[0], 0.75);
    EXPECT_DOUBLE_EQ(s.reducedMoment[1], 5.0 / 4);
    EXPECT_DOUBLE_EQ(s.reducedMoment[2], 11.0 / 4);
    EXPECT_DOUBLE_EQ(s.reducedMoment[3], 29.0 / 4);
    EXPECT_EQ(s.sizeCounts, (std::vector<std::uint32_t>{0, 2, 0, 1, 0, 1}));
    EXPECT_EQ(s.smoothedCounts, (std::vector<Real>{0, 2, 0.5, 0.5, 0.5, 0.5}));

    // delta/2a = 0.2 (link < 1.2 m) joins the singletons B and D (1.15 m apart).
    const ClusterResult wide = analysis::findClusters(p, 0.2);
    EXPECT_EQ(wide.sizes, (std::vector<std::uint32_t>{5, 2, 3}));
}

TEST(GasClusters, PolydisperseLinkThreshold) {
    // Radii 0.5 and 1.0 [m]: link distance (0.5 + 1.0) * 1.1 = 1.65 m.
    PointSet p;
    p.dim = 3;
    p.box = {10, 10, 10};
    p.x = {5, 5, 5, 6.64, 5, 5, 3.34, 5, 5};  // 1.64 m and 1.66 m from particle 0
    p.radius = {1.0, 0.5, 0.5};
    EXPECT_EQ(analysis::findClusters(p).sizes, (std::vector<std::uint32_t>{2, 1}));
}

TEST(GasClusters, MomentIdentitiesOnRandomClusters) {
    const PointSet p = test::randomPoints(3, 20000, {70, 70, 70}, 0.8, 1.2, 14);  // nu ~ 0.25
    const ClusterResult r = analysis::findClusters(p);
    const analysis::ClusterStats s = analysis::computeClusterStats(r.sizes, p.size());
    const auto nTot = static_cast<Real>(r.sizes.size());
    ASSERT_GT(s.largest, 10u);
    EXPECT_EQ(s.clusterCount, r.sizes.size());
    EXPECT_NEAR(s.moment[0], 1.0, 1e-14);
    EXPECT_NEAR(s.moment[1], static_cast<Real>(p.size()) / nTot, 1e-12);  // M_1 = N/n_tot
    const auto largest = static_cast<Real>(*std::max_element(r.sizes.begin(), r.sizes.end()));
    for (int k = 0; k < 4; ++k) {
        Real sum = 0;  // directly over the clusters, not via n_s
        for (const std::uint32_t size : r.sizes) sum += std::pow(static_cast<Real>(size), k);
        const auto kk = static_cast<std::size_t>(k);
        EXPECT_NEAR(s.moment[kk], sum / nTot, 1e-12 * s.moment[kk]);
        EXPECT_NEAR(s.reducedMoment[kk], sum / nTot - std::pow(largest, k) / nTot, 1e-12 * s.moment[kk]);
    }
    EXPECT_DOUBLE_EQ(s.largestFraction, largest / static_cast<Real>(p.size()));
    Real particles = 0, counted = 0, smoothed = 0;
    for (std::size_t size = 0; size < s.sizeCounts.size(); ++size) {
        particles += static_cast<Real>(size * s.sizeCounts[size]);
        counted += s.sizeCounts[size];
        smoothed += s.smoothedCounts[size];
    }
    EXPECT_EQ(particles, static_cast<Real>(p.size()));
    EXPECT_EQ(counted, nTot);
    EXPECT_NEAR(smoothed, nTot, 1e-9);  // smoothing only redistributes counts
}

TEST(GasClusters, StatsRejectInconsistentSizes) {
    EXPECT_THROW(analysis::computeClusterStats({3, 2}, 6), std::invalid_argument);
    EXPECT_THROW(analysis::computeClusterStats({3, 0}, 3), std::invalid_argument);
    EXPECT_EQ(analysis::computeClusterStats({}, 0).clusterCount, 0u);
}

TEST(GasClusters, HoleSmoothingHandExample) {
    // n_1 = 10, n_2 = 4, n_5 = 3, n_10 = 1: 3 spread over 3..5, 1 over 6..10.
    EXPECT_EQ(analysis::smoothHoles({0, 10, 4, 0, 0, 3, 0, 0, 0, 0, 1}),
              (std::vector<Real>{0, 10, 4, 1, 1, 1, 0.2, 0.2, 0.2, 0.2, 0.2}));
    // No singletons: the first entry spreads down to s = 1.
    EXPECT_EQ(analysis::smoothHoles({0, 0, 0, 6}), (std::vector<Real>{0, 2, 2, 2}));
}

TEST(GasClusters, TauPeakOfAParabola) {
    // M'_2 = 5 - (t - 2.3)^2, peak at 2.3 between samples; even and uneven spacing.
    auto parabola = [](const std::vector<Real>& t) {
        std::vector<Real> y;
        for (const Real ti : t) y.push_back(5 - (ti - 2.3) * (ti - 2.3));
        return y;
    };
    const std::vector<Real> even{0, 1, 2, 3, 4, 5};
    EXPECT_NEAR(analysis::tauPeak(even, parabola(even)), 2.3, 1e-12);
    const std::vector<Real> uneven{0, 0.5, 1.7, 2.9, 5};
    EXPECT_NEAR(analysis::tauPeak(uneven, parabola(uneven)), 2.3, 1e-12);
    // Monotonic: the end point, no extrapolation.
    EXPECT_EQ(analysis::tauPeak({1, 2, 3}, {0.1, 0.2, 0.3}), 3.0);
    EXPECT_EQ(analysis::tauPeak({1, 2, 3}, {0.3, 0.2, 0.1}), 1.0);
    EXPECT_THROW(analysis::tauPeak({1, 2}, {1}), std::invalid_argument);
}

}  // namespace
}  // namespace granulab
