// SPDX-License-Identifier: MIT
// Stage 4+6 of the DEM step (DESIGN.md): narrow phase of disk-disk and disk-wall candidates
// fused with the contact laws, plus body forces (gravity, global viscous damping).
#pragma once
#include <cstdint>
#include <vector>

#include "dem/integrator.hpp"
#include "dem/law_table.hpp"
#include "dem/neighbor_list.hpp"
#include "model/particle_store.hpp"
#include "model/walls.hpp"

namespace granulab::dem {

struct BodyForces {
    Vec2 gravity;             ///< [m/s^2]
    Real overlapGuard = 0;    ///< skip particle pairs whose overlap exceeds this fraction of the
                              ///< smaller radius (cfddem spec section 3.1); 0: off
    Real gamma = 0;           ///< [kg/s] global viscous damping F = -gamma v
    Real gammaRotation = 0;   ///< [kg m^2/s] torque = -gammaRotation omega
};

struct ForceStats {
    std::uint64_t contacts = 0;      ///< touching particle pairs
    std::uint64_t wallContacts = 0;  ///< touching particle-segment pairs
    Real maxRelativeOverlap = 0;     ///< largest overlap / smaller radius of the contact
    std::uint64_t guardSkips = 0;    ///< particle pairs skipped by the overlap guard
};

/// Overwrites f and torque with body forces, then adds all contact forces. Updates the
/// tangential history of every candidate (reset to zero when not touching): the spring grows by
/// the contact-point displacement of this step, drift velocity * dt. `trialHistory`: read the
/// accepted springs and write trial springs (committed by the caller once the step is accepted).
/// reads: x, v (for damping), drift velocities, omega, radius, mass; writes: f, torque, list histories, stats,
/// wallForce[w] = total contact force [N] the particles exert on wall w (size = wall count).
void computeForces(model::ParticleStore& s, const model::WallSet& walls, NeighborList& list,
                   const LawTable& laws, const BodyForces& body, const DriftVelocities& drift, Real dt,
                   bool trialHistory, ForceStats& stats,
                   std::vector<Vec2>& wallForce) noexcept;

/// Elastic energy [J] stored in all contacts (normal and tangential springs); no side effects.
Real contactEnergy(const model::ParticleStore& s, const model::WallSet& walls, const NeighborList& list,
                   const LawTable& laws) noexcept;

}  // namespace granulab::dem
