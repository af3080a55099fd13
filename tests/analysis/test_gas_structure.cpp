// SPDX-License-Identifier: MIT
// Pair correlation g(r) (edmd spec eq. 5.10 with the erratum delta(r_ij - r)), its contact value,
// and the local volume-fraction distribution (spec 5.2 "Density distribution").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "analysis/gas_structure.hpp"
#include "gas_points.hpp"

namespace granulab {
namespace {

using analysis::PairCorrelation;
using analysis::PointSet;

/// Ideal gas: pair counts are binomial with p_b = ideal_b / (N(N-1)/2) (pairwise independent on a
/// torus), so each bin must lie within 5 sigma of g = 1 and chi^2 within 5 sigma of its mean.
void expectIdealGas(const PointSet& p, Real rMax, std::size_t bins) {
    const PairCorrelation c = analysis::pairCorrelation(p, rMax, bins);
    const auto n = static_cast<Real>(p.size());
    const Real pairs = n * (n - 1) / 2;
    Real chi2 = 0;
    for (std::size_t b = 0; b < bins; ++b) {
        const Real prob = c.idealPairCount[b] / pairs;
        const Real sigma = std::sqrt(pairs * prob * (1 - prob));  // pairs
        const Real deviation = static_cast<Real>(c.pairCount[b]) - c.idealPairCount[b];
        EXPECT_LT(std::abs(c.g[b] - 1), 5 * sigma / c.idealPairCount[b]) << "bin " << b << " r " << c.r[b];
        chi2 += deviation * deviation / (sigma * sigma);
    }
    const auto dof = static_cast<Real>(bins);
    EXPECT_LT(std::abs(chi2 - dof), 5 * std::sqrt(2 * dof)) << "chi2 " << chi2;
}

TEST(GasStructure, IdealGasIsOne3D) {
    // Points (radius ~0) in a non-cubic periodic box: 4 x 3 x 4 cells of edge >= rMax.
    expectIdealGas(test::randomPoints(3, 10000, {1.0, 0.8, 1.2}, 1e-9, 1e-9, 21), 0.25, 25);
}

TEST(GasStructure, IdealGasIsOne2D) {
    expectIdealGas(test::randomPoints(2, 20000, {1.0, 1.5, 1.0}, 1e-9, 1e-9, 22), 0.2, 40);
}

TEST(GasStructure, PairCountsMatchBruteForceWithFewCells) {
    // rMax close to L/2: 2 (and 6) cells per axis, wrapped neighbours coincide.
    for (const int dim : {2, 3}) {
        const PointSet p =
            test::randomPoints(dim, 400, {1.0, 3.0, 1.0}, 0, 0, 23 + static_cast<std::uint64_t>(dim));
        const Real rMax = 0.49;
        const std::size_t bins = 49;
        const PairCorrelation c = analysis::pairCorrelation(p, rMax, bins);
        std::vector<std::uint64_t> expected(bins, 0);
        for (std::size_t i = 0; i < p.size(); ++i)
            for (std::size_t j = i + 1; j < p.size(); ++j) {
                const Real r = std::sqrt(test::bruteDistance2(p, i, j));
                if (r < rMax) ++expected[std::min(static_cast<std::size_t>(r / c.binWidth), bins - 1)];
            }
        EXPECT_EQ(c.pairCount, expected) << "dim " << dim;
    }
}

/// First bin with a non-zero pair count.
std::size_t firstOccupiedBin(const PairCorrelation& c) {
    return static_cast<std::size_t>(
        std::find_if(c.pairCount.begin(), c.pairCount.end(), [](std::uint64_t k) { return k > 0; }) -
        c.pairCount.begin());
}

TEST(GasStructure, SquareLatticePeaksAtSpacing) {
    // Spacing 1 m, bins of 1/16 m (exact): the 4 nearest neighbours give 2N pairs in [1, 1.0625),
    // the 4 diagonal ones 2N pairs at sqrt(2) in bin 22; nothing below the spacing.
    const PointSet p = test::latticePoints(2, 20, 1.0, 0.1);
    const PairCorrelation c = analysis::pairCorrelation(p, 4.0, 64);
    const auto n = static_cast<Real>(p.size());
    EXPECT_EQ(firstOccupiedBin(c), 16u);
    EXPECT_EQ(c.pairCount[16], 2 * p.size());
    EXPECT_EQ(c.pairCount[22], 2 * p.size());
    const Real shell = kPi * (1.0625 * 1.0625 - 1.0);  // [m^2]
    EXPECT_NEAR(c.g[16], 2 * n / (n * (n - 1) / (2 * 400.0) * shell), 1e-12);
    EXPECT_EQ(*std::max_element(c.g.begin(), c.g.end()), c.g[16]);
}

TEST(GasStructure, CubicLatticePeaksAtSpacing) {
    const PointSet p = test::latticePoints(3, 10, 1.0, 0.1);  // box 10 m, rMax 4 m < 5 m
    const PairCorrelation c = analysis::pairCorrelation(p, 4.0, 64);
    EXPECT_EQ(firstOccupiedBin(c), 16u);
    EXPECT_EQ(c.pairCount[16], 3 * p.size());  // 6 neighbours at 1 m
    EXPECT_EQ(c.pairCount[22], 6 * p.size());  // 12 at sqrt(2) m
    EXPECT_EQ(c.pairCount[27], 4 * p.size());  // 8 at sqrt(3) m
}

TEST(GasStructure, HardSpheresHaveNoPairsBelowContact) {
    // Random sequential addition of spheres of radius 0.5 m (2a = 1 m) to nu = 0.2.
    const std::size_t n = 1500;
    const Real edge = std::cbrt(static_cast<Real>(n) * (4.0 / 3.0) * kPi * 0.125 / 0.2);  // [m]
    PointSet p;
    p.box = {edge, edge, edge};
    CounterRng rng(24, 0);
    while (p.size() < n) {
        p.x.insert(p.x.end(), {rng.uniform(0, edge), rng.uniform(0, edge), rng.uniform(0, edge)});
        p.radius.push_back(0.5);
        bool overlaps = false;
        for (std::size_t j = 0; j + 1 < p.size() && !overlaps; ++j)
            overlaps = test::bruteDistance2(p, j, p.size() - 1) < 1.0 + 1e-9;
        if (overlaps) {
            p.x.resize(p.x.size() - 3);
            p.radius.pop_back();
        }
    }
    const PairCorrelation c = analysis::pairCorrelation(p, 3.0, 60);  // bins of 0.05 m
    for (std::size_t b = 0; b < 20; ++b) EXPECT_EQ(c.pairCount[b], 0u) << "bin " << b;
    EXPECT_GT(c.pairCount[20], 0u);
    EXPECT_GT(analysis::gContact(c, 1.0), 1.0);  // crowding raises the contact value
}

TEST(GasStructure, ContactValueOfALinearG) {
    // g = 0 below sigma, g = 2.5 - 3 (r - sigma) above; the bin straddling sigma is half empty.
    const Real sigma = 1.003, width = 0.01;  // [m]
    PairCorrelation c;
    c.binWidth = width;
    for (std::size_t b = 0; b < 300; ++b) {
        const Real r = (static_cast<Real>(b) + 0.5) * width;
        c.r.push_back(r);
        const Real lower = r - 0.5 * width;
        c.g.push_back(lower >= sigma ? 2.5 - 3 * (r - sigma) : (r > sigma ? 1.0 : 0.0));
    }
    EXPECT_NEAR(analysis::gContact(c, sigma), 2.5, 1e-12);
    EXPECT_NEAR(analysis::gContact(c, sigma, 0.5), 2.5, 1e-12);
    c.g[105] += 0.09;  // one noisy bin of the 9 used moves the fit, but not by more than its share
    const Real shifted = analysis::gContact(c, sigma);
    EXPECT_GT(shifted, 2.5);
    EXPECT_LT(shifted, 2.5 + 0.09);
    PairCorrelation coarse;  // bins of 0.1 m: none lies wholly in [sigma, 1.1 sigma]
    coarse.binWidth = 0.1;
    for (std::size_t b = 0; b < 30; ++b) {
        coarse.r.push_back((static_cast<Real>(b) + 0.5) * coarse.binWidth);
        coarse.g.push_back(1.0);
    }
    EXPECT_THROW(analysis::gContact(coarse, sigma), std::invalid_argument);
    EXPECT_NEAR(analysis::gContact(coarse, sigma, 1.0), 1.0, 1e-12);  // window to 2 sigma: 9 bins
}

TEST(GasStructure, RMaxMustStayBelowHalfThePeriodicBox) {
    PointSet p = test::randomPoints(3, 50, {1.0, 1.0, 0.6}, 0, 0, 25);
    EXPECT_THROW(analysis::pairCorrelation(p, 0.3, 10), std::invalid_argument);
    p.periodic[2] = false;  // a wall along z: only x and y limit rMax
    EXPECT_NO_THROW(analysis::pairCorrelation(p, 0.45, 10));
    EXPECT_THROW(analysis::pairCorrelation(p, 0.5, 10), std::invalid_argument);
}

TEST(GasStructure, LatticeDensityIsASpike) {
    // 3D: 20^3 sites, spacing 1 m, 8 per bin -> bins of 2 m holding 8 centres each.
    for (const int dim : {2, 3}) {
        const Real radius = dim == 3 ? 0.3 : 0.4;
        const PointSet p = test::latticePoints(dim, 20, 1.0, radius);
        analysis::DensityParams params;
        params.particlesPerBin = dim == 3 ? 8 : 4;
        const analysis::DensityDistribution d = analysis::densityDistribution(p, params);
        const Real nu = dim == 3 ? (4.0 / 3.0) * kPi * radius * radius * radius : kPi * radius * radius;
        EXPECT_EQ(d.bins[0], 10u);
        EXPECT_DOUBLE_EQ(d.binEdge[1], 2.0);
        for (const Real local : d.localNu) EXPECT_NEAR(local, nu, 1e-14);
        for (const Real q : d.quantiles) EXPECT_NEAR(q, nu, 1e-14);
        const Real width = params.nuMax / static_cast<Real>(params.histogramBins);
        for (std::size_t h = 0; h < d.nu.size(); ++h) {
            const bool holdsNu = std::abs(d.nu[h] - nu) <= 0.5 * width;
            EXPECT_NEAR(d.probabilityDensity[h], holdsNu ? 1 / width : 0.0, 1e-9)
                << "dim " << dim << " h " << h;
        }
        EXPECT_EQ(d.overflowFraction, 0.0);
    }
}

TEST(GasStructure, DensityBinsAverageToTheGlobalVolumeFraction) {
    // Polydisperse random spheres: the mean of local nu over equal bins is sum V_i / V exactly;
    // the default 40 centres per bin are met within the integer-fit tolerance.
    const PointSet p = test::randomPoints(3, 30000, {60, 50, 70}, 0.6, 1.4, 26);
    const analysis::DensityDistribution d = analysis::densityDistribution(p);
    Real particleVolume = 0;  // [m^3]
    for (const Real r : p.radius) particleVolume += (4.0 / 3.0) * kPi * r * r * r;
    Real mean = 0;
    for (const Real local : d.localNu) mean += local;
    mean /= static_cast<Real>(d.localNu.size());
    EXPECT_NEAR(mean, particleVolume / p.volume(), 1e-12);
    for (std::size_t a = 0; a < 3; ++a) EXPECT_NEAR(d.binEdge[a] * d.bins[a], p.box[a], 1e-12);
    const Real perBin = static_cast<Real>(p.size()) / static_cast<Real>(d.localNu.size());
    EXPECT_GT(perBin, 30.0);
    EXPECT_LT(perBin, 53.0);
    Real integral = d.overflowFraction;
    for (const Real density : d.probabilityDensity) integral += density * (d.nu[1] - d.nu[0]);
    EXPECT_NEAR(integral, 1.0, 1e-12);
    EXPECT_TRUE(std::is_sorted(d.quantiles.begin(), d.quantiles.end()));
    EXPECT_LT(d.quantiles[0], d.quantiles[6]);
}

TEST(GasStructure, QuantileConventionIsLinearBetweenOrderStatistics) {
    const std::vector<Real> v{1, 2, 3, 4};
    EXPECT_DOUBLE_EQ(analysis::quantileSorted(v, 0.0), 1.0);
    EXPECT_DOUBLE_EQ(analysis::quantileSorted(v, 0.25), 1.75);  // h = 0.75
    EXPECT_DOUBLE_EQ(analysis::quantileSorted(v, 0.5), 2.5);
    EXPECT_DOUBLE_EQ(analysis::quantileSorted(v, 0.99), 3.97);
    EXPECT_DOUBLE_EQ(analysis::quantileSorted(v, 1.0), 4.0);
    EXPECT_DOUBLE_EQ(analysis::quantileSorted({7}, 0.1), 7.0);
    EXPECT_THROW(analysis::quantileSorted({}, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace granulab
