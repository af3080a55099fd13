// SPDX-License-Identifier: MIT
// Pair correlation and local density distribution of a gas snapshot (edmd spec section 5.2,
// eq. 5.10 with the erratum delta(r_ij - r); used in 5.4).
//
// Why rMax < L/2 on periodic axes: then every pair has at most one image closer than rMax, so the
// minimum-image histogram counts each pair once and the ideal-gas normalisation
// N(N-1)/(2V) * shell volume is exact (pair positions are uniform on the torus).
#include "analysis/gas_structure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "analysis/gas_cell_grid.hpp"

namespace granulab::analysis {

namespace {

/// Adds every unordered pair with minimum-image distance < rMax to its bin of `counts`.
template <int D>
void histogramPairs(const CellGrid& grid, Real rMax, Real binWidth, std::vector<std::uint64_t>& counts) {
    const Real rMax2 = rMax * rMax;  // [m^2]
    const Real inverseWidth = 1 / binWidth;
    const std::size_t lastBin = counts.size() - 1;
    forEachNearPair<D>(grid, [&](std::uint32_t, std::uint32_t, Real distance2) {
        if (distance2 >= rMax2) return;
        const auto bin = static_cast<std::size_t>(std::sqrt(distance2) * inverseWidth);
        ++counts[std::min(bin, lastBin)];
    });
}

/// Volume [m^D] of a ball of radius r [m] (2D: disk area).
Real ballVolume(int dim, Real r) {
    return dim == 2 ? kPi * r * r : (4.0 / 3.0) * kPi * r * r * r;
}

}  // namespace

PairCorrelation pairCorrelation(const PointSet& points, Real rMax, std::size_t binCount) {
    checkPointSet(points, "pairCorrelation");
    const std::size_t n = points.size();
    if (n < 2) throw std::invalid_argument("pairCorrelation: needs at least 2 particles");
    if (binCount == 0) throw std::invalid_argument("pairCorrelation: binCount must be >= 1");
    Real smallestPeriodicEdge = std::numeric_limits<Real>::infinity();  // [m]
    for (int d = 0; d < points.dim; ++d) {
        const auto a = static_cast<std::size_t>(d);
        if (points.periodic[a]) smallestPeriodicEdge = std::min(smallestPeriodicEdge, points.box[a]);
    }
    if (!(rMax > 0) || !(rMax < 0.5 * smallestPeriodicEdge))
        throw std::invalid_argument(
            "pairCorrelation: rMax must be > 0 and < half the smallest periodic box edge (" +
            std::to_string(0.5 * smallestPeriodicEdge) + "), got " + std::to_string(rMax));

    PairCorrelation result;
    result.rMax = rMax;
    result.binWidth = rMax / static_cast<Real>(binCount);
    result.pairCount.assign(binCount, 0);
    const CellGrid grid = buildCellGrid(points, rMax, 2 * n);
    if (points.dim == 2) {
        histogramPairs<2>(grid, rMax, result.binWidth, result.pairCount);
    } else {
        histogramPairs<3>(grid, rMax, result.binWidth, result.pairCount);
    }

    // eq. 5.10: g(r) = <pairs in shell> / (N(N-1)/(2V) * shell volume)
    const auto count = static_cast<Real>(n);
    const Real idealPairDensity = count * (count - 1) / (2 * points.volume());  // [1/m^D]
    result.r.resize(binCount);
    result.g.resize(binCount);
    result.idealPairCount.resize(binCount);
    for (std::size_t b = 0; b < binCount; ++b) {
        const Real inner = static_cast<Real>(b) * result.binWidth;  // [m]
        const Real outer = static_cast<Real>(b + 1) * result.binWidth;
        result.r[b] = 0.5 * (inner + outer);
        const Real shell = ballVolume(points.dim, outer) - ballVolume(points.dim, inner);  // [m^D]
        result.idealPairCount[b] = idealPairDensity * shell;
        result.g[b] = static_cast<Real>(result.pairCount[b]) / result.idealPairCount[b];
    }
    return result;
}

Real gContact(const PairCorrelation& correlation, Real sigma, Real window) {
    // Bins wholly above sigma with centre in [sigma, sigma (1 + window)].
    const Real lowest = sigma * (1 - 1e-12);  // [m] tolerance for a bin edge exactly at sigma
    const Real highest = sigma * (1 + window);
    Real sumR = 0, sumG = 0, sumRR = 0, sumRG = 0;
    std::size_t used = 0;
    for (std::size_t b = 0; b < correlation.r.size(); ++b) {
        const Real r = correlation.r[b];
        if (r - 0.5 * correlation.binWidth < lowest || r > highest) continue;
        const Real offset = r - sigma;  // [m] fit in r - sigma, so the intercept is g(sigma)
        sumR += offset;
        sumG += correlation.g[b];
        sumRR += offset * offset;
        sumRG += offset * correlation.g[b];
        ++used;
    }
    if (used < 2)
        throw std::invalid_argument(
            "gContact: fewer than 2 bins in [sigma, sigma (1 + window)]; use narrower bins");
    const auto m = static_cast<Real>(used);
    const Real slope = (m * sumRG - sumR * sumG) / (m * sumRR - sumR * sumR);  // [1/m]
    return (sumG - slope * sumR) / m;  // least-squares intercept at r = sigma
}

DensityDistribution densityDistribution(const PointSet& points, const DensityParams& params) {
    checkPointSet(points, "densityDistribution");
    const std::size_t n = points.size();
    if (n == 0) throw std::invalid_argument("densityDistribution: no particles");
    if (!(params.particlesPerBin > 0) || params.histogramBins == 0 || !(params.nuMax > 0))
        throw std::invalid_argument(
            "densityDistribution: particlesPerBin, histogramBins and nuMax must be > 0");
    const int dim = points.dim;

    // Spatial bins: target edge from ~particlesPerBin centres per bin, integer count per axis.
    const Real targetEdge =
        std::pow(params.particlesPerBin * points.volume() / static_cast<Real>(n), 1.0 / dim);  // [m]
    DensityDistribution result;
    std::size_t binTotal = 1;
    for (int d = 0; d < dim; ++d) {
        const auto a = static_cast<std::size_t>(d);
        const Real count = std::max<Real>(1, std::round(points.box[a] / targetEdge));
        result.bins[a] = static_cast<std::uint32_t>(count);
        result.binEdge[a] = points.box[a] / count;
        binTotal *= result.bins[a];
    }
    Real binVolume = 1;  // [m^D]
    for (int d = 0; d < dim; ++d) binVolume *= result.binEdge[static_cast<std::size_t>(d)];

    // Particle volume of the centres in each bin.
    result.localNu.assign(binTotal, 0);
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t bin = 0;
        for (int d = dim - 1; d >= 0; --d) {
            const auto a = static_cast<std::size_t>(d);
            Real xi = points.x[i * static_cast<std::size_t>(dim) + a];  // [m]
            if (points.periodic[a]) xi -= points.box[a] * std::floor(xi / points.box[a]);
            const Real cell = std::clamp<Real>(std::floor(xi / result.binEdge[a]), 0, result.bins[a] - 1);
            bin = bin * result.bins[a] + static_cast<std::size_t>(cell);
        }
        result.localNu[bin] += ballVolume(dim, points.radius[i]);
    }
    for (Real& nu : result.localNu) nu /= binVolume;

    // Bin-weighted histogram on [0, nuMax]; nuMax itself goes into the last bin.
    const Real width = params.nuMax / static_cast<Real>(params.histogramBins);
    result.nu.resize(params.histogramBins);
    for (std::size_t h = 0; h < params.histogramBins; ++h)
        result.nu[h] = (static_cast<Real>(h) + 0.5) * width;
    std::vector<std::size_t> counts(params.histogramBins, 0);
    std::size_t overflow = 0;
    for (const Real nu : result.localNu) {
        if (nu > params.nuMax) {
            ++overflow;
            continue;
        }
        ++counts[std::min(static_cast<std::size_t>(nu / width), params.histogramBins - 1)];
    }
    const auto spatialBins = static_cast<Real>(binTotal);
    result.probabilityDensity.resize(params.histogramBins);
    for (std::size_t h = 0; h < params.histogramBins; ++h)
        result.probabilityDensity[h] = static_cast<Real>(counts[h]) / (spatialBins * width);
    result.overflowFraction = static_cast<Real>(overflow) / spatialBins;

    std::vector<Real> sorted(result.localNu);
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t q = 0; q < kDensityQuantileLevels.size(); ++q)
        result.quantiles[q] = quantileSorted(sorted, kDensityQuantileLevels[q]);
    return result;
}

Real quantileSorted(const std::vector<Real>& sorted, Real level) {
    if (sorted.empty()) throw std::invalid_argument("quantileSorted: no values");
    const Real position = std::clamp<Real>(level, 0, 1) * static_cast<Real>(sorted.size() - 1);
    const auto below = static_cast<std::size_t>(std::floor(position));
    if (below + 1 >= sorted.size()) return sorted.back();
    const Real fraction = position - static_cast<Real>(below);
    return sorted[below] + fraction * (sorted[below + 1] - sorted[below]);
}

}  // namespace granulab::analysis
