// SPDX-License-Identifier: MIT
// Structure of a hard-sphere/disk gas snapshot (edmd spec section 5.2 "Pair correlation",
// "Density distribution"; used in 5.4): the pair correlation g(r) with its contact value, and the
// distribution of the coarse-grained local volume fraction with its quantiles.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "analysis/point_set.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

/// g(r) sampled in bins of equal width on [0, rMax).
struct PairCorrelation {
    Real rMax = 0;                         ///< [m] upper end of the last bin
    Real binWidth = 0;                     ///< [m]
    std::vector<Real> r;                   ///< [m] bin centres
    std::vector<Real> g;                   ///< pair correlation per bin (dimensionless; 1 for an ideal gas)
    std::vector<std::uint64_t> pairCount;  ///< unordered pairs with distance in the bin
    /// Pairs expected in the bin for an ideal gas: N(N-1)/(2V) times the shell volume [m^D]; so
    /// g = pairCount / idealPairCount, and pairCount is binomial with p = idealPairCount/(N(N-1)/2).
    std::vector<Real> idealPairCount;
};

/// Pair correlation g(r) of `points` (edmd spec eq. 5.10 with the erratum delta(r_ij - r)): a
/// histogram of minimum-image centre distances r_ij < rMax [m] over all unordered pairs, in
/// binCount bins, normalised by the shell volume of each bin (2D: pi (r2^2 - r1^2), 3D:
/// 4/3 pi (r2^3 - r1^3)) times the ideal pair density N(N-1)/(2V). Radii are not read.
/// Non-periodic axes get no edge correction (g is biased low within rMax of such walls).
/// Throws std::invalid_argument unless 0 < rMax < half the smallest periodic box edge,
/// binCount >= 1 and N >= 2. Cost O(N * neighbours within rMax) with a cell grid of edge >= rMax.
PairCorrelation pairCorrelation(const PointSet& points, Real rMax, std::size_t binCount);

/// Contact value g(sigma) [dimensionless], sigma = 2a [m] for equal radii a (spec eq. 4.35):
/// an unweighted linear least-squares fit of g against r over the bins that lie wholly above sigma
/// (lower edge >= sigma) and whose centre is <= sigma (1 + window), extrapolated to r = sigma.
/// A bin straddling sigma is skipped because the part of its shell below sigma is empty and would
/// bias it low. Throws std::invalid_argument when fewer than 2 bins qualify (use narrower bins
/// or a wider window).
Real gContact(const PairCorrelation& correlation, Real sigma, Real window = 0.1);

/// Coarse-graining and histogram settings for densityDistribution.
struct DensityParams {
    Real particlesPerBin = 40;        ///< mean number of centres per spatial bin (spec 5.2: ~40)
    std::size_t histogramBins = 100;  ///< bins of the nu histogram
    Real nuMax = 1;                   ///< histogram range is [0, nuMax]
};

/// Quantile levels reported by densityDistribution (spec 5.2, Fig. 5.12): 1, 10, 25, 50, 75, 90, 99 %.
inline constexpr std::array<Real, 7> kDensityQuantileLevels{0.01, 0.10, 0.25, 0.50, 0.75, 0.90, 0.99};

/// Distribution of the local volume fraction over the spatial bins.
struct DensityDistribution {
    std::array<std::uint32_t, 3> bins{1, 1, 1};  ///< spatial bins per axis (1 on unused axes)
    std::array<Real, 3> binEdge{0, 0, 0};        ///< [m] spatial bin edge per axis
    std::vector<Real> localNu;                   ///< local volume fraction per spatial bin, x index fastest
    std::vector<Real> nu;                        ///< histogram bin centres on [0, nuMax]
    /// Fraction of spatial bins per unit nu, per histogram bin (integrates to 1 - overflowFraction).
    std::vector<Real> probabilityDensity;
    Real overflowFraction = 0;        ///< fraction of spatial bins with local nu > nuMax
    std::array<Real, 7> quantiles{};  ///< local nu at kDensityQuantileLevels (quantileSorted)
};

/// Local volume-fraction distribution (edmd spec 5.2 "Density distribution", Figs. 5.10, 5.12):
/// the box is cut into a grid of bins; the target edge is (particlesPerBin V/N)^(1/D), then each
/// axis gets round(box/target) >= 1 bins of edge box/bins, so an integer number of bins fits every
/// axis (edges differ from the target, and between axes, by at most a factor ~1 +- 1/(2 bins)).
/// Local nu of a bin = sum over the centres in it of the particle volume (2D pi r^2 [m^2],
/// 3D 4/3 pi r^3 [m^3], per particle radius) / bin volume. Each spatial bin has weight 1 in the
/// histogram ("bin-weighted"). Throws std::invalid_argument for N = 0 or bad parameters.
DensityDistribution densityDistribution(const PointSet& points, const DensityParams& params = {});

/// Quantile of ascending `sorted` values at level in [0, 1]: linear interpolation between order
/// statistics at position h = level (n - 1), zero-based (Hyndman & Fan type 7, numpy's default):
/// Q = v[floor h] + (h - floor h) (v[floor h + 1] - v[floor h]). Throws for empty input.
Real quantileSorted(const std::vector<Real>& sorted, Real level);

}  // namespace granulab::analysis
