// SPDX-License-Identifier: MIT
// Serial event-driven engine for hard disks (D = 2) and spheres (D = 3) in a periodic box
// (edmd spec sections 2.1-2.8, 2.10): lazy updates (each particle carries its own time t_st),
// one future event per particle in the queue, stale collisions recognised by collision
// counters and executed as free flights (2.6), cells with explicit crossing events and periodic
// wrap (2.7). Smooth collisions with constant normal restitution. Issue 5 groundwork: scene
// input, walls, gravity, rough spheres, the TC model and the measurements come next.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "edmd/event_queue.hpp"
#include "edmd/kinematics.hpp"

namespace granulab::edmd {

struct EngineConfig {
    Real box = 1;            ///< [m] edge of the periodic cube/square
    Real restitution = 1;    ///< normal restitution eps
    /// TC model (edmd spec 4.3, Luding & McNamara): a collision is elastic if either partner
    /// collided less than tc [s] before (prevents inelastic collapse); 0: off.
    Real tc = 0;
    Real cellSize = 0;       ///< [m] lower bound of the cell edge; 0: the largest diameter
};

struct EngineStats {
    std::uint64_t events = 0, collisions = 0, annulled = 0, cellCrossings = 0;
};

template <int D, class Queue = CalendarQueue>
class Engine {
public:
    using V = VecD<D>;
    /// Particles at positions x [m] (inside the box, not overlapping), velocities v [m/s],
    /// radii [m], masses [kg]; all at time 0.
    Engine(EngineConfig config, std::vector<V> x, std::vector<V> v, std::vector<Real> radius, std::vector<Real> mass);

    /// Executes events until the next one would be later than t_end [s]; returns the events done.
    std::uint64_t runUntil(Real tEnd);
    Real time() const noexcept { return m_now; }
    const EngineStats& stats() const noexcept { return m_stats; }
    std::uint32_t size() const noexcept { return static_cast<std::uint32_t>(m_s.size()); }

    /// Position and velocity of particle i extrapolated to the current time (no state change).
    V positionNow(std::uint32_t i) const noexcept { return m_s[i].x + m_s[i].v * (m_now - m_s[i].tst); }
    const V& velocity(std::uint32_t i) const noexcept { return m_s[i].v; }
    Real radius(std::uint32_t i) const noexcept { return m_s[i].radius; }
    Real mass(std::uint32_t i) const noexcept { return m_mass[i]; }
    /// Kinetic energy [J] and momentum [kg m/s].
    Real kineticEnergy() const noexcept;
    V momentum() const noexcept;
    /// Minimum-image separation vector r_i - r_j at the current time.
    V separation(std::uint32_t i, std::uint32_t j) const noexcept;

private:
    enum class Kind : std::uint8_t { None, Collision, Cell };
    struct Event {
        Kind kind = Kind::None;
        std::uint32_t partner = 0;         ///< particle, or 2 * dimension + (1 if upward) for cells
        std::uint64_t partnerCounter = 0;  ///< partner's collision counter when scheduled
    };

    void advance(std::uint32_t i, Real t) noexcept;
    void schedule(std::uint32_t i) noexcept;
    std::uint32_t cellIndex(const int c[D]) const noexcept;
    void cellCoords(std::uint32_t i, int c[D]) const noexcept;
    void insertIntoCell(std::uint32_t i, std::uint32_t cell) noexcept;
    void removeFromCell(std::uint32_t i) noexcept;
    V minimumImage(V d) const noexcept;

    /// What the event computation reads of every neighbour, in one cache line for spheres
    /// (random access per neighbour dominates the cost; spec 2.2's ParticleState).
    struct alignas(16) State {
        V x;            ///< [m] position at t_st
        V v;            ///< [m/s]
        Real tst = 0;   ///< [s] time of the last update
        Real radius = 0;
    };

    EngineConfig m_config;
    std::vector<State> m_s;
    std::vector<Real> m_mass;
    std::vector<std::uint64_t> m_counter;
    std::vector<Real> m_lastCollision;  ///< [s] time of each particle's last collision (TC model)
    std::vector<std::uint32_t> m_cell, m_next, m_prev, m_head;
    std::vector<Event> m_event;
    Queue m_queue;
    int m_cells = 1;        ///< cells per dimension
    Real m_cellEdge = 1;    ///< [m]
    Real m_now = 0;
    EngineStats m_stats;
};

}  // namespace granulab::edmd
