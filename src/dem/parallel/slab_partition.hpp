// SPDX-License-Identifier: MIT
// The DEM domain decomposition's split of space into slabs, one per rank (issue 16; gc2d spec
// section 5.4 runs the phases on threads, this goes beyond one machine): the cuts along one
// axis, the owner of a point, the ranks that need a particle as a ghost, and cuts that give
// every rank the same share of a weight (particles plus contacts: piles and silos are dense at
// the bottom and empty above, so equal widths would leave most ranks idle).
#pragma once
#include <span>
#include <vector>

#include "core/communicator.hpp"
#include "core/types.hpp"

namespace granulab::dem {

struct SlabPartition {
    int axis = 0;            ///< 0: slabs across x, 1: across y
    std::vector<Real> cuts;  ///< [m] ranks - 1 ascending cuts; rank r owns [cuts[r-1], cuts[r])

    int ranks() const noexcept { return static_cast<int>(cuts.size()) + 1; }
    /// [m] the slab of rank r (the outer ones are open: -inf, +inf).
    Real lower(int r) const noexcept;
    Real upper(int r) const noexcept;
    /// The rank whose slab holds coordinate c [m].
    int owner(Real c) const noexcept;
    /// Calls fn(rank) for every rank other than `owner` whose slab widened by `halo` [m] holds
    /// c, in ascending order: those ranks keep the particle as a ghost.
    template <class Fn>
    void forGhostRanks(Real c, Real halo, int ownerRank, Fn&& fn) const {
        for (int r = ownerRank - 1; r >= 0 && c < upper(r) + halo; --r) fn(r);  // descending, then
        for (int r = ownerRank + 1; r < ranks() && c >= lower(r) - halo; ++r) fn(r);
    }
};

/// Equal slabs over [lo, hi] [m] along `axis`.
SlabPartition uniformSlabs(int axis, Real lo, Real hi, int ranks);

/// Collective: cuts that give every rank the same share of the total weight, from a histogram
/// of 256 bins per rank over the particles' extent (every rank passes its own particles'
/// coordinates along `axis` [m] and weights; the result is the same on every rank). A rank
/// whose share falls inside one bin gets a cut interpolated within it. Without any weight (no
/// particles yet: a pile that a source will build) the slabs are equal over [lo, hi].
SlabPartition balancedSlabs(Communicator& comm, int axis, std::span<const Real> coords,
                            std::span<const Real> weights, Real lo, Real hi);

}  // namespace granulab::dem
