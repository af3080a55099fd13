// SPDX-License-Identifier: MIT
// Particles in and out (DESIGN.md step 8, the only stage where N changes): gc2d drop sources
// (spec 6.5, ABS/REL placement, shrinking width), cfddem inlets (spec 4.2, emission rule Eq. 4.1)
// and outlets (spec 4.3: crossing an edge outward) or sink regions. The flow decides what enters
// and what leaves; dem::World applies it to the store, the integrator and the contact lists.
// Every random draw comes from (seed, element, insertion number), so the flow state is a few
// counters and a resumed run inserts the same particles.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "model/dem_def.hpp"
#include "model/mass_model.hpp"
#include "model/particle_store.hpp"
#include "model/shape_pool.hpp"
#include "model/walls.hpp"

namespace granulab::dem {

/// What an insertion element inserts (resolved from model::InsertDef).
struct InsertTemplate {
    std::uint32_t material = 0;
    Real density = 0;  ///< [kg/m^2] or [kg/m^3] by the mass model
    model::MassModel massModel = model::MassModel::Disk;
    std::optional<model::ShapeDef> shape;  ///< nullopt: disk
    model::SizeDistDef radius;             ///< disks [m]
    Vec2 velocity;                         ///< [m/s]
    Real angle = 0, omega = 0;             ///< [rad], [rad/s]
    int attempts = 20;
    std::uint32_t sharedShape = model::kDiskShape;  ///< pool index of a deterministic [[shape]]
};

struct DropSource {  // gc2d DROPSOURCE
    std::string name;
    InsertTemplate what;
    Vec2 position;  ///< [m]
    bool relative = false;
    Real width = 0, widthEnd = 0;           ///< [m]
    Real interval = 0.1, from = 0, to = 1;  ///< [s]
};

struct Inlet {  // cfddem inlet edge
    std::string name;
    InsertTemplate what;
    Vec2 a, b;      ///< [m] n_out = left of a -> b
    Real rate = 0;  ///< [1/s]
    Real from = 0, to = 1e300;
    bool inset = true;
};

struct Outlet {  // cfddem outlet edge or a sink region
    std::string name;
    bool isRegion = false;
    Vec2 a, b;
    Real xmin = 0, ymin = 0, xmax = 0, ymax = 0;
    bool removeInside = true;
    Real openAt = 0;  ///< [s]
};

struct FlowConfig {
    std::uint64_t seed = 1;
    std::vector<DropSource> sources;
    std::vector<Inlet> inlets;
    std::vector<Outlet> outlets;
    bool any() const noexcept { return !sources.empty() || !inlets.empty() || !outlets.empty(); }
};

/// One particle to insert.
struct NewParticle {
    Vec2 position, velocity;
    Real angle = 0, omega = 0, radius = 0, mass = 0, inertia = 0;
    std::uint32_t material = 0;
    std::uint32_t shape = model::kDiskShape;
};

/// Counters of the flow (all since t = 0; saved in checkpoints).
struct FlowCounters {
    std::vector<std::uint64_t> sourceDrops;  ///< drops due so far per source (inserted + skipped)
    std::vector<std::uint64_t> sourceSkipped;
    std::vector<std::uint64_t> inletEmitted;  ///< emissions per inlet (inserted + skipped)
    std::vector<std::uint64_t> inletSkipped;
    std::vector<std::uint64_t> outletRemoved;
    std::vector<Real> outletMass;  ///< [kg]
    std::uint64_t inserted = 0, removed = 0, skipped = 0;
    Real massIn = 0, massOut = 0;  ///< [kg]
};

class ParticleFlow {
public:
    ParticleFlow() = default;
    explicit ParticleFlow(FlowConfig config);

    bool active() const noexcept { return m_config.any(); }
    const FlowConfig& config() const noexcept { return m_config; }
    const FlowCounters& counters() const noexcept { return m_counters; }

    /// Slots (ascending) of the particles that left through an open outlet at time t [s]; their
    /// count and mass are booked per outlet. Only the candidates of refreshCandidates are tested.
    std::vector<std::uint32_t> leaving(const model::ParticleStore& s, Real t);
    /// The particles that can reach an outlet before the next neighbour rebuild: those within
    /// `maxRadius` + `skin` [m] of its capture zone (no particle moves more than skin/2 between
    /// rebuilds). Called at every rebuild and whenever particles enter or leave.
    /// Only slots below `end` are candidates (a domain's owned particles; default: all).
    void refreshCandidates(const model::ParticleStore& s, Real maxRadius, Real skin,
                           std::size_t end = static_cast<std::size_t>(-1));
    /// True when a source drop or an inlet emission is due at time t (what `entering` would
    /// try), without drawing anything.
    bool insertionDue(Real t, Real dt) const noexcept;
    /// The counters that every domain of a decomposed run books for its own particles only
    /// (removals); the others advance alike on every rank.
    FlowCounters& countersForDomain() noexcept { return m_counters; }
    /// Particles entering at time t, the end of a step of length dt [s], placed overlap-free
    /// against the store and the solid walls (retry, then skip and count); `gravity` [m/s^2]
    /// tells REL sources which grains are still falling.
    std::vector<NewParticle> entering(const model::ParticleStore& s, const model::WallSet& walls,
                                      model::ShapePool& pool, Real t, Real dt, Vec2 gravity);
    /// Books particles that `entering` returned and the world inserted.
    void bookInserted(const std::vector<NewParticle>& added) noexcept;

    void save(std::ostream& os) const;
    void load(std::istream& is);

private:
    FlowConfig m_config;
    FlowCounters m_counters;
    std::vector<std::vector<std::uint32_t>> m_near;  ///< candidate slots per outlet, ascending
};

}  // namespace granulab::dem
