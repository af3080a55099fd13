// SPDX-License-Identifier: MIT
// Velocity statistics of a gas snapshot (edmd spec section 5.2; T = 2E/D from 4.4). Moments are
// taken in two passes (mean, then central moments), which keeps the variance accurate when the
// mean flow is large compared with the fluctuations.
#include "analysis/gas_velocity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "analysis/gas_cell_grid.hpp"

namespace granulab::analysis {

namespace {

void checkVelocities(const PointSet& points, const char* who) {
    checkPointSet(points, who);
    const std::size_t n = points.size();
    const std::string prefix = std::string(who) + ": ";
    if (n == 0) throw std::invalid_argument(prefix + "no particles");
    if (points.v.size() != static_cast<std::size_t>(points.dim) * n)
        throw std::invalid_argument(prefix + "v must hold dim values per particle");
    if (!points.mass.empty() && points.mass.size() != n)
        throw std::invalid_argument(prefix + "mass must be empty or hold one value per particle");
}

Real kurtosisOf(Real fourthMoment, Real variance) {
    if (!(variance > 0)) return std::numeric_limits<Real>::quiet_NaN();
    return fourthMoment / (variance * variance);
}

}  // namespace

VelocityStats velocityStats(const PointSet& points) {
    checkVelocities(points, "velocityStats");
    const std::size_t n = points.size();
    const auto dim = static_cast<std::size_t>(points.dim);
    const auto count = static_cast<Real>(n);
    VelocityStats stats;

    std::array<Real, 3> mean{};  // [m/s]
    Real twiceEnergy = 0;        // [J] sum m v^2
    for (std::size_t i = 0; i < n; ++i) {
        const Real m = points.mass.empty() ? 1 : points.mass[i];
        for (std::size_t d = 0; d < dim; ++d) {
            const Real v = points.v[i * dim + d];
            mean[d] += v;
            twiceEnergy += m * v * v;
        }
    }
    for (std::size_t d = 0; d < dim; ++d) mean[d] /= count;

    std::array<Real, 3> second{}, fourth{};  // [m^2/s^2], [m^4/s^4] central sums
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t d = 0; d < dim; ++d) {
            const Real dv = points.v[i * dim + d] - mean[d];
            const Real dv2 = dv * dv;
            second[d] += dv2;
            fourth[d] += dv2 * dv2;
        }
    }
    Real pooledMean = 0, pooledSecond = 0, pooledFourth = 0;
    for (std::size_t d = 0; d < dim; ++d) {
        stats.axis[d].mean = mean[d];
        stats.axis[d].variance = second[d] / count;
        stats.axis[d].kurtosis = kurtosisOf(fourth[d] / count, stats.axis[d].variance);
        pooledMean += mean[d];
        pooledSecond += second[d];
        pooledFourth += fourth[d];
    }
    const Real components = count * static_cast<Real>(dim);
    stats.pooled.mean = pooledMean / static_cast<Real>(dim);
    stats.pooled.variance = pooledSecond / components;
    stats.pooled.kurtosis = kurtosisOf(pooledFourth / components, stats.pooled.variance);
    stats.kineticEnergy = 0.5 * twiceEnergy / count;                       // spec 5.2
    stats.temperature = 2 * stats.kineticEnergy / static_cast<Real>(dim);  // T = 2E/D, spec 4.4
    return stats;
}

VelocityHistogram velocityHistogram(const PointSet& points, std::size_t binCount, Real k) {
    const VelocityStats stats = velocityStats(points);
    if (binCount == 0 || !(k > 0))
        throw std::invalid_argument("velocityHistogram: binCount and k must be > 0");
    if (!(stats.temperature > 0)) throw std::invalid_argument("velocityHistogram: temperature is 0");
    const std::size_t n = points.size();
    const auto dim = static_cast<std::size_t>(points.dim);
    Real meanMass = 1;  // [kg]
    if (!points.mass.empty()) {
        meanMass = 0;
        for (const Real m : points.mass) meanMass += m;
        meanMass /= static_cast<Real>(n);
    }

    VelocityHistogram result;
    result.vMax = k * std::sqrt(stats.temperature / meanMass);
    result.binWidth = 2 * result.vMax / static_cast<Real>(binCount);
    result.v.resize(binCount);
    for (std::size_t b = 0; b < binCount; ++b)
        result.v[b] = -result.vMax + (static_cast<Real>(b) + 0.5) * result.binWidth;
    const Real normalisation = 1 / (static_cast<Real>(n) * result.binWidth);  // [s/m] per count
    std::vector<std::size_t> counts(binCount);
    for (std::size_t d = 0; d < dim; ++d) {
        std::fill(counts.begin(), counts.end(), 0);
        std::size_t outside = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const Real position = (points.v[i * dim + d] + result.vMax) / result.binWidth;
            if (!(position >= 0 && position <= static_cast<Real>(binCount))) {
                ++outside;
                continue;
            }
            ++counts[std::min(static_cast<std::size_t>(position), binCount - 1)];
        }
        result.density[d].resize(binCount);
        for (std::size_t b = 0; b < binCount; ++b)
            result.density[d][b] = static_cast<Real>(counts[b]) * normalisation;
        result.outsideFraction[d] = static_cast<Real>(outside) / static_cast<Real>(n);
    }
    return result;
}

}  // namespace granulab::analysis
