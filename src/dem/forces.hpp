// SPDX-License-Identifier: MIT
// Stages 4+6 of the DEM step (DESIGN.md): body forces (gravity, global viscous damping, pull
// springs), then the narrow phase of every candidate (particle pairs and particle-wall pairs, disks
// and polygons) fused with the contact laws: overlap-depth kernels for disks (dem/forces_depth.hpp),
// gc2d area kernels for any shapes (dem/forces_area_pairs.hpp). Also the polygon world corners
// (stage 2 geometry, ShapeContext) and the elastic energy of the contacts.
#pragma once
#include <cstdint>
#include <vector>

#include "dem/contact_log.hpp"
#include "dem/integrator.hpp"
#include "dem/law_table.hpp"
#include "dem/neighbor_list.hpp"
#include "geom/convex_contact.hpp"
#include "geom/rotation.hpp"
#include "model/particle_store.hpp"
#include "model/shape_pool.hpp"
#include "model/walls.hpp"

namespace granulab::dem {

/// A spring pulling one particle (gc2d spec section 3.8; model::SpringDef).
struct PullSpring {
    ParticleId id = 0;
    std::uint32_t slot = 0;  ///< current slot of the particle (World keeps it in step)
    Real stiffness = 0;      ///< [N/m]
    Vec2 attach;             ///< [m] body frame
    Vec2 pullStart;          ///< [m]
    Vec2 velocity;           ///< [m/s] of the free end while moving
    Real from = 0, to = 0;   ///< [s]
    /// Free end at time t [m].
    Vec2 freeEnd(Real t) const noexcept {
        const Real tc = t < from ? from : (t > to ? to : t);
        return pullStart + velocity * (tc - from);
    }
};

struct BodyForces {
    Vec2 gravity;            ///< [m/s^2]
    Real overlapGuard = 0;   ///< skip particle pairs whose overlap exceeds this fraction of the
                             ///< smaller radius (cfddem spec section 3.1); 0: off
    Real gamma = 0;          ///< [kg/s] global viscous damping F = -gamma v
    Real gammaRotation = 0;  ///< [kg m^2/s] torque = -gammaRotation omega
    const std::vector<PullSpring>* springs = nullptr;
    Real time = 0;                 ///< [s] of the evaluation (spring motion)
    bool weight = true;            ///< apply m g (cfddem #Fg)
    bool particleContacts = true;  ///< evaluate particle pairs (cfddem #FP)
    bool wallContacts = true;      ///< evaluate particle-wall pairs (cfddem #FB)
};

/// Polygon shapes and their orientation at the current force evaluation (gc2d spec section 5.4,
/// steps 2-3: computed once per particle, not per contact).
struct ShapeContext {
    const model::ShapePool* pool = nullptr;
    std::vector<Vec2> world;           ///< [m] world corners of all polygons, slot order
    std::vector<std::uint32_t> first;  ///< first world corner of each slot (polygons only)
    geom::FeatureStats featureStats;   ///< closest-feature work since the last reset
    geom::RotationCache rotations;     ///< cos, sin of each slot's angle (geom/rotation.hpp)
    bool anyPolygon = false;
    Real scale = 1;  ///< global size scaling s(t) of the body corners (gc2d 2.4, Eq. 2.30/2.31)
    /// Recomputes the world corners from positions, angles and the scale s (gc2d Eq. 2.35, angle
    /// counter-clockwise), on `threads` threads; dem/shape_context.cpp.
    void update(const model::ParticleStore& s, int threads = 1,
                const std::vector<std::uint32_t>* cuts = nullptr);
};

struct ForceStats {
    std::uint64_t contacts = 0;      ///< touching particle pairs
    std::uint64_t wallContacts = 0;  ///< touching particle-segment pairs
    Real maxRelativeOverlap = 0;     ///< largest overlap / smaller radius of the contact
    std::uint64_t guardSkips = 0;    ///< particle pairs skipped by the overlap guard
    void add(const ForceStats& o) noexcept {
        contacts += o.contacts;
        wallContacts += o.wallContacts;
        maxRelativeOverlap =
            o.maxRelativeOverlap > maxRelativeOverlap ? o.maxRelativeOverlap : maxRelativeOverlap;
        guardSkips += o.guardSkips;
    }
};

/// The share of a cross pair (its grains in two tiles) for its second grain, gathered by that
/// grain's tile after all tiles have run (dem/neighbor_list.hpp).
struct DeferredForce {
    Real fx, fy;  ///< [N]
    Real torque;  ///< [N m]
};

/// Counters one tile's thread writes while it runs, on a cache line of its own (no false
/// sharing between threads: the closest-feature counters change at every polygon pair).
struct alignas(64) TileCounters {
    ForceStats stats;
    geom::FeatureStats features;
};

/// Scratch of the threaded force evaluation, kept between steps (sized when the tiles change).
struct ForceWorkspace {
    int threads = 1;                      ///< threads of the evaluation
    std::vector<DeferredForce> deferred;  ///< one per cross pair
    std::vector<TileCounters> counters;   ///< one per tile
    /// [N] force of each tile's contacts on each wall: tile t's block starts at t * wallStride
    /// (a whole number of cache lines).
    std::vector<Vec2> tileWallForce;
    std::size_t wallStride = 0;
    std::vector<ContactLog> tileLogs;  ///< filled on the steps that record contacts
    /// The threads' runs of tiles: thread k takes tiles [cuts[k], cuts[k + 1]) (forces.cpp splitTiles).
    std::vector<std::uint32_t> cuts;
    std::vector<double> tileWork;  ///< work of each tile, for the split
    /// [s] measured time of each tile's pairs and walls, smoothed over steps (on several threads
    /// only; empty or 0 where not yet measured).
    std::vector<double> tileSeconds;
    /// The same runs in slots: thread k's tiles cover slots [slotCuts[k], slotCuts[k + 1]). The
    /// other per-particle stages follow them (parallelSlots), so that a thread integrates the
    /// grains whose forces it summed. Empty on one thread.
    std::vector<std::uint32_t> slotCuts;
    /// When set, called by each thread with the slots [begin, end) of its tiles as soon as their
    /// forces are complete (after its gathers), inside the force stage's parallel region: World
    /// fuses the integrator's correction here (Integrator::correctsBySlots), which saves a
    /// parallel region per step and finds the forces still in the core's cache. It must touch
    /// only those slots. nullptr: none.
    void (*finishSlots)(void* context, std::size_t begin, std::size_t end) noexcept = nullptr;
    void* finishContext = nullptr;
};

/// Overwrites f and torque with body forces, then adds all contact forces. Updates the
/// tangential history of every candidate (reset to zero when not touching): the spring grows by
/// the contact-point displacement of this step, drift velocity * dt. `trialHistory`: read the
/// accepted springs and write trial springs (committed by the caller once the step is accepted).
/// reads: x, v, omega, angle, radius, mass, invMass, invInertia, material, shape, drift velocities;
/// writes: f, torque, list histories (and feature caches), stats, shapes (world corners),
/// wallForce[w] = total contact force [N] the particles exert on wall w (size = wall count).
/// `shapes`: polygon shapes (contacts of the gc2d area law; may be empty for disk-only scenes).
/// `log`: when given, cleared and filled with every touching contact's record (snapshot steps),
/// tile by tile. `ws`: the scratch and thread count (nullptr: a local one, one thread).
/// The result does not depend on ws->threads: every grain's forces are added in the order fixed
/// by the list's tiles (body forces, springs, then its tile's pairs and walls in list order, then
/// the deferred shares of cross pairs in gather order).
void computeForces(model::ParticleStore& s, const model::WallSet& walls, NeighborList& list,
                   const LawTable& laws, const BodyForces& body, const DriftVelocities& drift, Real dt,
                   bool trialHistory, ForceStats& stats, std::vector<Vec2>& wallForce, ShapeContext& shapes,
                   ContactLog* log = nullptr, ForceWorkspace* ws = nullptr) noexcept;

/// Elastic energy [J] stored in all contacts (normal, tangential and rolling springs); no side effects.
/// For the gc2d area law, whose force has no potential in general, the normal part is estimated
/// as F_n h_eff / 2 (exact for flat faces). `shapes`: the polygon shapes (world corners are
/// computed here from the store).
Real contactEnergy(const model::ParticleStore& s, const model::WallSet& walls, const NeighborList& list,
                   const LawTable& laws, const model::ShapePool& shapes, Real scale = 1, int threads = 1);

}  // namespace granulab::dem
