// SPDX-License-Identifier: MIT
// Clusters of a hard-sphere/disk gas snapshot and their size statistics (edmd spec section 5.2
// "Clusters", "Moments", "Largest cluster", "Reduced moments", "tau_p", footnote 5; used in 5.5-5.6).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "analysis/point_set.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

/// Connected components of the "closer than delta" graph (friends of friends).
struct ClusterResult {
    /// Cluster of every particle, 0 .. sizes.size()-1. Labels are numbered in the order of each
    /// cluster's lowest particle index (particle 0 is in cluster 0), so results are deterministic.
    std::vector<std::uint32_t> label;
    std::vector<std::uint32_t> sizes;  ///< particles per label; singletons (free particles) count
};

/// Finds the clusters of `points` (edmd spec 5.2, eq. 5.11): particles i and j are linked iff their
/// centre distance (minimum image on periodic axes) is < (r_i + r_j) (1 + deltaRatio), i.e. the
/// surface gap is < delta with delta/2a = deltaRatio for equal radii a (spec: 0.1 throughout).
/// Union-find (path halving, union by size) over a cell grid of edge >= the largest link distance;
/// O(N) for a gas. Velocities and masses are not read. Throws std::invalid_argument for a
/// malformed PointSet or deltaRatio < 0. Thread-safe (no shared state).
ClusterResult findClusters(const PointSet& points, Real deltaRatio = 0.1);

/// Cluster-size statistics of one snapshot (edmd spec 5.2, eqs. 5.12-5.14).
struct ClusterStats {
    std::size_t clusterCount = 0;           ///< n_tot = sum_s n_s (singletons included)
    std::size_t particleCount = 0;          ///< N
    std::array<Real, 4> moment{};           ///< M_k, k = 0..3: (1/n_tot) sum_s s^k n_s (eq. 5.12); M_0 = 1
    std::uint32_t largest = 0;              ///< N_x, size of the largest cluster
    Real largestFraction = 0;               ///< q_x = N_x / N (eq. 5.13)
    std::array<Real, 4> reducedMoment{};    ///< M'_k = M_k - N_x^k / n_tot (eq. 5.14), k = 0..3
    std::vector<std::uint32_t> sizeCounts;  ///< n_s indexed by s = 0..N_x (n_0 = 0)
    std::vector<Real> smoothedCounts;       ///< smoothHoles(sizeCounts) (footnote 5), for plotting
};

/// Statistics of the cluster sizes `sizes` (as in ClusterResult) of a snapshot of `particleCount`
/// particles. Throws std::invalid_argument if the sizes do not add up to particleCount or one is 0.
/// All members are 0 / empty for an empty snapshot.
ClusterStats computeClusterStats(const std::vector<std::uint32_t>& sizes, std::size_t particleCount);

/// Hole smoothing of a size histogram for log-log plots (edmd spec 5.2 footnote 5): for consecutive
/// non-zero entries n_r, n_s (r < s) the entries r+1..s are all set to n_s/(s - r), i.e. the count
/// of size s is spread evenly over the run of zeros below it. Below the first non-zero entry r = 0
/// is used (n_1..n_s := n_s/s). Index 0 is kept as is (0). The sum of the counts is unchanged, and
/// a lone largest cluster appears as ~1/s.
std::vector<Real> smoothHoles(const std::vector<std::uint32_t>& sizeCounts);

/// tau_p: the time of the peak of M'_2 (edmd spec 5.2, eq. 5.15). Takes the largest sample
/// (the first one on ties); when it is interior, the parabola through it and its two neighbours
/// (spacing may be uneven) is maximised and its vertex time returned, which lies between the two
/// neighbours. At an end point that end's time is returned. The refinement is in the variable
/// given: pass log(tau) to refine on a logarithmic time axis. Throws std::invalid_argument if the
/// vectors are empty or differ in length.
Real tauPeak(const std::vector<Real>& times, const std::vector<Real>& reducedM2);

}  // namespace granulab::analysis
