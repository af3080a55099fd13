// SPDX-License-Identifier: MIT
// Contact-force statistics of a DEM snapshot (gc2d spec section 7 item 3; the polar force plots
// of section 8.6): the direction distribution P(alpha) and the magnitude distribution P(F/<F>).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "analysis/table.hpp"
#include "core/types.hpp"

namespace granulab::analysis {

struct ForceDirectionParams {
    std::size_t bins = 72;     ///< B bins on [-pi, pi) (>= 1)
    bool includeWalls = true;  ///< wall contacts add the force on the grain once
};

/// P(alpha), alpha = atan2(Fy, Fx).
struct ForceDirections {
    std::vector<Real> alpha;           ///< [rad] bin centres on [-pi, pi)
    std::vector<Real> density;         ///< [1/rad] P(alpha), integrates to 1 (NaN without forces)
    std::vector<std::uint64_t> count;  ///< forces per bin
    std::uint64_t forces = 0;          ///< forces counted (grain pairs twice, walls once)
    std::uint64_t zeroForces = 0;      ///< contacts skipped because F = 0 (no direction)
    std::vector<std::string> notes;
};

/// Every grain-grain contact adds +F and -F (P(alpha) = P(alpha +- pi)), every wall contact (when
/// includeWalls) the force on its grain once; alpha = pi falls in the first bin with -pi. Contacts
/// with F = 0 are skipped. Throws std::invalid_argument for bins == 0. Cost O(C).
ForceDirections forceDirections(const ContactFrame& contacts, const ForceDirectionParams& params = {});

/// Table "force_directions": alpha [rad], P [1/rad], forces [1].
Table toTable(const ForceDirections& result);

struct ForceMagnitudeParams {
    std::size_t bins = 50;      ///< bins on [0, maxRatio) (>= 1)
    Real maxRatio = 5;          ///< upper end of the F/<F> range (> 0); larger ratios are overflow
    bool includeWalls = false;  ///< also the wall contacts
};

/// P(F/<F>) of |F|.
struct ForceMagnitudes {
    std::vector<Real> ratio;           ///< F/<F> bin centres
    std::vector<Real> density;         ///< P(F/<F>) [1]: fraction of contacts per unit ratio
    std::vector<std::uint64_t> count;  ///< contacts per bin
    Real meanForce = 0;                ///< [N] <F> = mean |F| (NaN without contacts)
    std::uint64_t contacts = 0;        ///< contacts counted (zero forces included)
    Real overflowFraction = 0;         ///< fraction with F/<F> >= maxRatio (density integrates to 1 - this)
    std::vector<std::string> notes;
};

/// Magnitudes |F| = |(fx, fy)| of the grain-grain contacts (and wall contacts when includeWalls),
/// histogram of F/<F> normalised by all counted contacts. Throws std::invalid_argument for
/// bins == 0 or maxRatio <= 0. Cost O(C).
ForceMagnitudes forceMagnitudes(const ContactFrame& contacts, const ForceMagnitudeParams& params = {});

/// Table "force_magnitudes": F/<F> [1], P [1], contacts [1]; notes mean_force [N], overflow.
Table toTable(const ForceMagnitudes& result);

}  // namespace granulab::analysis
