// SPDX-License-Identifier: MIT
// Stage 6 of the DEM step, fluid part (cfddem spec 5, Tab. 3.1; docs/physics/fluid.md): one-way
// coupling of spherical particles to an imported flow field: drag on the relative velocity
// (fluid/drag_laws.hpp), static buoyancy -rho_f V g (Eq. 3.63), the pressure-gradient force
// -V grad p where the field carries p; and the seed's mutual Newtonian attraction (spec 5.6),
// all pairs or within a cutoff on a cell grid. The particles' volume is that of a sphere of their
// radius, V = 4/3 pi R^3. On the ranks of a domain decomposition (FieldRanks) the voidage cells
// and the attraction between all pairs reach beyond the ghost layer: they gather what they need
// from every rank (docs/physics/dem-mpi.md).
#pragma once
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "dem/cell_bins.hpp"
#include "fluid/drag_laws.hpp"
#include "fluid/field_series.hpp"
#include "model/particle_store.hpp"

namespace granulab {
class Communicator;
}

namespace granulab::dem {

/// This process's place in a domain decomposition (dem/parallel/), as the field stage sees it:
/// the slots [0, owned) of the store are this rank's particles, the others ghosts of its
/// neighbours'. `comm` nullptr: one process, every particle its own. Every rank calls the field
/// stage at the same evaluations (the stage runs collectives).
struct FieldRanks {
    Communicator* comm = nullptr;
    std::size_t owned = 0;
};

struct FluidForceConfig {
    fluid::DragLaw drag;
    fluid::FluidProperties fluid;
    bool buoyancy = true;
    bool pressureGradient = false;
    Real pressureToPascal = 1;  ///< factor from the field's pressure to [Pa] (rho_f for kinematic p)
    Real depth = 0;             ///< [m] slab thickness of the voidage cells (di_felice; 0: largest diameter)
    Real voidageCell = 0;       ///< [m] voidage cell edge (di_felice; 0: max(node spacing, 8 R_max))
};

struct FluidStats {
    std::uint64_t outside = 0;  ///< particles outside the field's domain at the last evaluation
    Real maxReynolds = 0;       ///< largest particle Reynolds number (0 without viscosity)
    Real minVoidage = 1;        ///< di_felice: smallest voidage seen
    Vec2 drag;                  ///< [N] total drag force
};

/// Scratch kept between evaluations (no allocation in the steady state): the voidage grid and the
/// interpolant of the cell each particle slot was in (fluid::LocalPatch; a patch is valid for any
/// particle inside its cell, so slots renumbered since only cost a lookup).
struct VoidageScratch {
    CellBins bins;                                               ///< particles by voidage cell (one process)
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;  ///< (cell key, slot) (ranks)
    std::vector<Real> eps;                                       ///< voidage at each particle
    std::vector<fluid::LocalPatch> patches;                      ///< by slot, of the current field
    std::uint64_t patchesGeneration = ~0ull;  ///< FieldSeries::generation() the patches belong to
};

/// Adds the fluid forces to s.fx, s.fy (torques: none, spec 5.1). `g` [m/s^2] the gravity of the
/// evaluation (buoyancy uses it even when the weight is switched off, as the seed does). On ranks
/// the voidage cells sum every rank's owned particles (one reduction and one all-gather of the
/// occupied cells), so each cell holds what it holds on one process, summed in rank order.
void addFluidForces(model::ParticleStore& s, const fluid::FieldSeries& field, const FluidForceConfig& c,
                    Vec2 g, FluidStats& stats, VoidageScratch& scratch, const FieldRanks& ranks = {});

/// Mutual attraction F = G m_i m_j / d^2 along the centre line (cfddem Eq. 3.72), skipping
/// coincident centres; all pairs (cutoff 0) or pairs closer than `cutoff` [m] through a cell grid
/// (`bins` is scratch; particles spread far apart use a sparse layout, never all pairs). Pairs in a
/// fixed order, so the sums are deterministic. On ranks, a cutoff stays within the ghost layer (the
/// domain widens it); all pairs gather every rank's owned particles each evaluation and sum, for
/// each owned particle, the pulls of all others in rank and slot order.
void addAttraction(model::ParticleStore& s, Real constant, Real cutoff, CellBins& bins,
                   const FieldRanks& ranks = {});

}  // namespace granulab::dem
