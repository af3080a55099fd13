// SPDX-License-Identifier: MIT
// Velocity statistics of a hard-sphere/disk gas snapshot (edmd spec section 5.2 "Kinetic energy",
// "Velocity distribution"; 4.4 for T = 2E/D; used in 5.3, Fig. 5.7): moments per axis, kinetic
// energy and granular temperature, and the distribution of Cartesian velocity components.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "analysis/point_set.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

/// Moments of a set of velocity components.
struct ComponentStats {
    Real mean = 0;      ///< [m/s] <v>
    Real variance = 0;  ///< [m^2/s^2] <(v - <v>)^2> (1/N normalisation)
    Real kurtosis = 0;  ///< <(v - <v>)^4> / <(v - <v>)^2>^2; 3 for a Gaussian; NaN if the variance is 0
};

/// Velocity statistics of one snapshot.
struct VelocityStats {
    std::array<ComponentStats, 3> axis{};  ///< per Cartesian axis (axis 2 unused, zero, in 2D)
    /// All D*N components together: mean = average of the axis means; variance and kurtosis use each
    /// component relative to its own axis mean (a drift along one axis does not widen the pool).
    ComponentStats pooled;
    Real kineticEnergy = 0;  ///< [J] E = (1/N) sum_i m_i v_i^2 / 2, total (mean flow not removed), spec 5.2
    Real temperature = 0;    ///< [J] granular temperature T = 2E/D (k_B = 1), spec 4.4
};

/// Moments, E and T of the velocities of `points` (unit masses when mass is empty; moments are
/// unweighted by mass). Throws std::invalid_argument for N = 0, v not holding dim values per
/// particle, or a mass vector of the wrong length.
VelocityStats velocityStats(const PointSet& points);

/// Probability density of the Cartesian velocity components, per axis (spec Fig. 5.7: plot ln p
/// against v^2; a Gaussian is a straight line).
struct VelocityHistogram {
    Real vMax = 0;        ///< [m/s] the range is [-vMax, vMax]
    Real binWidth = 0;    ///< [m/s]
    std::vector<Real> v;  ///< [m/s] bin centres
    /// [s/m] p(v_d) per axis and bin: count / (N binWidth); axis 2 empty in 2D.
    std::array<std::vector<Real>, 3> density;
    std::array<Real, 3> outsideFraction{};  ///< fraction of components outside [-vMax, vMax] per axis
};

/// Histogram of the velocity components on [-k sqrt(T/m), +k sqrt(T/m)] (symmetric about 0, not
/// about the mean), T from velocityStats, m the mean particle mass [kg] (1 when mass is empty),
/// binCount bins. Throws std::invalid_argument as velocityStats does, for binCount = 0, k <= 0 or
/// T = 0.
VelocityHistogram velocityHistogram(const PointSet& points, std::size_t binCount, Real k = 5);

}  // namespace granulab::analysis
