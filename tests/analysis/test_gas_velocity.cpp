// SPDX-License-Identifier: MIT
// Velocity statistics (edmd spec 5.2 "Kinetic energy", "Velocity distribution"; T = 2E/D of 4.4):
// exact values on hand-made velocities, and Gaussian samples within their standard errors.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "analysis/gas_velocity.hpp"
#include "core/rng.hpp"

namespace granulab {
namespace {

using analysis::PointSet;

/// N particles with Gaussian velocity components: mean[d] + sigma * normal, fixed seed.
PointSet gaussianGas(int dim, std::size_t n, std::array<Real, 3> mean, Real sigma, std::uint64_t seed) {
    PointSet p;
    p.dim = dim;
    p.x.assign(n * static_cast<std::size_t>(dim), 0.5);
    p.radius.assign(n, 0.01);
    CounterRng rng(seed, 0);
    for (std::size_t i = 0; i < n; ++i)
        for (int d = 0; d < dim; ++d) p.v.push_back(mean[static_cast<std::size_t>(d)] + sigma * rng.normal());
    return p;
}

TEST(GasVelocity, HandMadeVelocitiesExact) {
    // 2D: v = (+-1, 0) with m = 1 kg, (0, +-2) with m = 2 kg.
    PointSet p;
    p.dim = 2;
    p.x.assign(8, 0.5);
    p.radius.assign(4, 0.1);
    p.v = {1, 0, -1, 0, 0, 2, 0, -2};
    p.mass = {1, 1, 2, 2};
    analysis::VelocityStats s = analysis::velocityStats(p);
    EXPECT_DOUBLE_EQ(s.kineticEnergy, (0.5 + 0.5 + 4 + 4) / 4);  // 2.25 J
    EXPECT_DOUBLE_EQ(s.temperature, 2.25);                       // 2E/D with D = 2
    EXPECT_DOUBLE_EQ(s.axis[0].mean, 0.0);
    EXPECT_DOUBLE_EQ(s.axis[0].variance, 0.5);
    EXPECT_DOUBLE_EQ(s.axis[0].kurtosis, 2.0);  // <v^4> = 0.5, <v^2>^2 = 0.25
    EXPECT_DOUBLE_EQ(s.axis[1].variance, 2.0);
    EXPECT_DOUBLE_EQ(s.axis[1].kurtosis, 2.0);  // 8 / 4
    EXPECT_DOUBLE_EQ(s.pooled.variance, 10.0 / 8);
    EXPECT_DOUBLE_EQ(s.pooled.kurtosis, (34.0 / 8) / (1.25 * 1.25));

    p.mass.clear();  // unit masses
    EXPECT_DOUBLE_EQ(analysis::velocityStats(p).kineticEnergy, (0.5 + 0.5 + 2 + 2) / 4);

    // A drift of (3, -1) m/s changes E but no central moment.
    for (std::size_t i = 0; i < 4; ++i) {
        p.v[2 * i] += 3;
        p.v[2 * i + 1] -= 1;
    }
    s = analysis::velocityStats(p);
    EXPECT_DOUBLE_EQ(s.axis[0].mean, 3.0);
    EXPECT_DOUBLE_EQ(s.axis[1].mean, -1.0);
    EXPECT_DOUBLE_EQ(s.pooled.mean, 1.0);
    EXPECT_DOUBLE_EQ(s.axis[0].kurtosis, 2.0);
    EXPECT_DOUBLE_EQ(s.pooled.variance, 10.0 / 8);
    EXPECT_DOUBLE_EQ(s.kineticEnergy, (0.5 + 0.5 + 2 + 2) / 4 + 0.5 * (9 + 1));

    // Two-valued components +-1: kurtosis exactly 1.
    PointSet twoValued;
    twoValued.dim = 3;
    twoValued.x.assign(6, 0.5);
    twoValued.radius.assign(2, 0.1);
    twoValued.v = {1, -1, 1, -1, 1, -1};
    EXPECT_DOUBLE_EQ(analysis::velocityStats(twoValued).pooled.kurtosis, 1.0);
}

TEST(GasVelocity, GaussianMomentsWithinStandardErrors) {
    // 3D, sigma = 1.5 m/s, different means per axis; unit masses.
    const std::size_t n = 200000;
    const Real sigma = 1.5;
    const std::array<Real, 3> mean{0.3, -1.0, 0.0};
    const PointSet p = gaussianGas(3, n, mean, sigma, 31);
    const analysis::VelocityStats s = analysis::velocityStats(p);
    const auto count = static_cast<Real>(n);
    const Real var = sigma * sigma;
    for (std::size_t d = 0; d < 3; ++d) {
        EXPECT_NEAR(s.axis[d].mean, mean[d], 5 * sigma / std::sqrt(count)) << "axis " << d;
        EXPECT_NEAR(s.axis[d].variance, var, 5 * var * std::sqrt(2 / count)) << "axis " << d;
        EXPECT_NEAR(s.axis[d].kurtosis, 3.0, 5 * std::sqrt(24 / count)) << "axis " << d;  // SE 0.011
    }
    EXPECT_NEAR(s.pooled.kurtosis, 3.0, 5 * std::sqrt(24 / (3 * count)));
    EXPECT_NEAR(s.pooled.mean, (s.axis[0].mean + s.axis[1].mean + s.axis[2].mean) / 3, 1e-12);
    // E = (1/2) sum_d (mean_d^2 + sigma^2); Var(v^2) = 2 sigma^4 + 4 mean^2 sigma^2 per component.
    Real energy = 0, energyVar = 0;
    for (const Real m : mean) {
        energy += 0.5 * (m * m + var);
        energyVar += 0.25 * (2 * var * var + 4 * m * m * var) / count;
    }
    EXPECT_NEAR(s.kineticEnergy, energy, 5 * std::sqrt(energyVar));
    EXPECT_DOUBLE_EQ(s.temperature, 2 * s.kineticEnergy / 3);
}

TEST(GasVelocity, GaussianHistogramMatchesTheDensity) {
    // 2D, sigma = 1 m/s, zero mean: per bin, the count is binomial around N (Phi(hi) - Phi(lo)).
    const std::size_t n = 100000, bins = 50;
    const PointSet p = gaussianGas(2, n, {0, 0, 0}, 1.0, 32);
    const analysis::VelocityHistogram h = analysis::velocityHistogram(p, bins);
    const Real temperature = analysis::velocityStats(p).temperature;
    EXPECT_NEAR(h.vMax, 5 * std::sqrt(temperature), 1e-12);
    auto phi = [](Real x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
    const auto count = static_cast<Real>(n);
    for (std::size_t d = 0; d < 2; ++d) {
        Real chi2 = 0, dof = 0, integral = h.outsideFraction[d];
        for (std::size_t b = 0; b < bins; ++b) {
            const Real prob = phi(h.v[b] + 0.5 * h.binWidth) - phi(h.v[b] - 0.5 * h.binWidth);
            const Real observed = h.density[d][b] * count * h.binWidth;
            integral += h.density[d][b] * h.binWidth;
            if (count * prob < 5) continue;  // far tails: too few counts for a normal error
            const Real sigma = std::sqrt(count * prob * (1 - prob));
            EXPECT_LT(std::abs(observed - count * prob), 5 * sigma) << "axis " << d << " v " << h.v[b];
            chi2 += (observed - count * prob) * (observed - count * prob) / (sigma * sigma);
            dof += 1;
        }
        EXPECT_LT(std::abs(chi2 - dof), 5 * std::sqrt(2 * dof)) << "chi2 " << chi2 << " bins " << dof;
        EXPECT_NEAR(integral, 1.0, 1e-12);
        EXPECT_LT(h.outsideFraction[d], 1e-4);  // P(|v| > 5 sigma) = 5.7e-7
    }
    EXPECT_TRUE(h.density[2].empty());
}

TEST(GasVelocity, RejectsMalformedInput) {
    PointSet p = gaussianGas(3, 10, {0, 0, 0}, 1.0, 33);
    p.v.pop_back();
    EXPECT_THROW(analysis::velocityStats(p), std::invalid_argument);
    PointSet still = gaussianGas(2, 10, {0, 0, 0}, 0.0, 34);
    EXPECT_THROW(analysis::velocityHistogram(still, 10), std::invalid_argument);  // T = 0
}

}  // namespace
}  // namespace granulab
