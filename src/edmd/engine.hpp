// SPDX-License-Identifier: MIT
// Serial event-driven engine for hard disks (D = 2) and spheres (D = 3) (edmd spec sections
// 2.1-2.8, 2.10, checklist items 1-17): lazy updates (each particle carries its own time t_st),
// one future event per particle in the queue, stale collisions recognised by collision
// counters and executed as free flights (2.6), cells with explicit crossing events and periodic
// wrap (2.7), hard plane walls on non-periodic axes, uniform gravity (parabolic flights),
// smooth or rough inelastic collisions with constant or speed-dependent restitution, the TC
// model, growing or shrinking spheres, polydisperse radii and masses. Output by extrapolation
// (no state change), checkpoints bit for bit.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <iosfwd>
#include <vector>

#include "edmd/event_queue.hpp"
#include "edmd/kinematics.hpp"
#include "edmd/restitution.hpp"

namespace granulab::edmd {

struct EngineConfig {
    std::array<Real, 3> box{1, 1, 1};             ///< [m] box edge per axis, origin at 0
    std::array<bool, 3> periodic{true, true, true};  ///< false: hard plane walls at 0 and box
    Restitution restitution;                      ///< normal restitution between particles
    Real wallRestitution = 1;                     ///< normal restitution at the walls
    /// Rough spheres (edmd Eq. 2.6-2.8): tangential restitution phi in [-1, 1] (-1: smooth, no
    /// spin is tracked); inertiaFactor z = I/(m a^2) (0.4 solid sphere, 0.5 solid disk).
    Real tangentialRestitution = -1;
    Real inertiaFactor = 0.4;
    /// TC model (edmd spec 4.3, Luding & McNamara): a collision (also with a wall) is elastic if
    /// either partner collided less than tc [s] before (prevents inelastic collapse); 0: off.
    Real tc = 0;
    std::array<Real, 3> gravity{0, 0, 0};         ///< [m/s^2]
    Real growthRate = 0;  ///< [m/s] u_a: every radius grows as a(t) = a(0) + u_a t (edmd Eq. 2.16); periodic boxes only
    Real cellSize = 0;    ///< [m] lower bound of the cell edge; 0: the largest diameter (rounded up to fit the box)

    bool rough() const noexcept { return tangentialRestitution > -1; }
};

struct EngineStats {
    std::uint64_t events = 0, collisions = 0, annulled = 0, cellCrossings = 0, wallCollisions = 0;
    std::uint64_t tcElastic = 0;  ///< collisions made elastic by the TC rule
    std::uint64_t regrids = 0;    ///< cell grids rebuilt because growing spheres outgrew them
};

template <int D, class Queue = CalendarQueue>
class Engine {
public:
    using V = VecD<D>;
    /// Particles at positions x [m] (inside the box, not overlapping), velocities v [m/s],
    /// radii [m] (at time 0), masses [kg]; all at time 0. Throws std::invalid_argument when the
    /// box holds fewer than 3 cells per periodic axis or the input is inconsistent.
    Engine(EngineConfig config, std::vector<V> x, std::vector<V> v, std::vector<Real> radius, std::vector<Real> mass);

    /// Executes events until the next one would be later than t_end [s]; afterwards time() is
    /// t_end. Returns the events done.
    std::uint64_t runUntil(Real tEnd);
    /// Executes events until `collisions` more collisions have happened or the next event would
    /// be later than t_end; time() is then the time of the last event.
    std::uint64_t runCollisions(std::uint64_t collisions, Real tEnd = kNoEvent);
    /// Elastic pre-run done (edmd spec 4.2 step 4): brings every particle to the current time,
    /// makes it time 0 and resets collision counters, TC clocks, statistics and accumulators.
    void restartClock();
    /// Replaces the collision rules (restitution, TC, roughness) from now on.
    void setCollisionRules(const Restitution& restitution, Real wallRestitution, Real tc);

    Real time() const noexcept { return m_now; }
    const EngineStats& stats() const noexcept { return m_stats; }
    const EngineConfig& config() const noexcept { return m_config; }
    std::uint32_t size() const noexcept { return static_cast<std::uint32_t>(m_s.size()); }
    std::array<int, 3> cellsPerAxis() const noexcept { return m_cells; }

    /// Position [m] (wrapped into the box on periodic axes) and velocity [m/s] of particle i
    /// extrapolated to the current time; the schedule is not touched.
    V positionNow(std::uint32_t i) const noexcept;
    V velocityNow(std::uint32_t i) const noexcept;
    /// Angular velocity [rad/s] (zero unless rough; 2D: the z component in [2]).
    Vec3 omega(std::uint32_t i) const noexcept { return m_omega.empty() ? Vec3{} : m_omega[i]; }
    Real radius(std::uint32_t i) const noexcept { return m_s[i].radius + m_config.growthRate * m_now; }
    Real mass(std::uint32_t i) const noexcept { return m_mass[i]; }
    /// Collisions particle i has suffered (particles and walls) since the last restartClock().
    std::uint64_t collisions(std::uint32_t i) const noexcept { return m_counter[i]; }
    /// Kinetic energy [J] (translational), rotational energy [J], potential energy in gravity [J]
    /// (zero at the origin), momentum [kg m/s], all at the current time.
    Real kineticEnergy() const noexcept;
    Real rotationalEnergy() const noexcept;
    Real potentialEnergy() const noexcept;
    V momentum() const noexcept;
    /// Sum over executed particle collisions of r_ij . J_ij [kg m^2/s] (contact vector times
    /// the impulse on i), cumulative: the collisional virial (edmd spec 7 item 27). Pressure over
    /// a window dt: P = (2 <E_kin> + virial/dt) / (D V).
    Real collisionalVirial() const noexcept { return m_virial; }
    /// Energy lost in collisions so far [J] (kinetic + rotational), cumulative.
    Real dissipatedEnergy() const noexcept { return m_dissipated; }
    /// Minimum-image separation vector r_i - r_j at the current time.
    V separation(std::uint32_t i, std::uint32_t j) const noexcept;
    /// Bytes held by the engine (particle state, cells, events, queue).
    std::size_t memoryBytes() const noexcept;

    /// Complete state in a binary stream; loadState restores it so that the run continues bit
    /// for bit (the configuration must be the same; the caller checks that).
    void saveState(std::ostream& os) const;
    void loadState(std::istream& is);

private:
    enum class Kind : std::uint8_t { None, Collision, Cell, Wall };
    struct Event {
        std::uint32_t partner = 0;         ///< particle; for cells and walls 2 * axis + (1 if upward)
        std::uint32_t partnerCounter = 0;  ///< partner's collision counter when scheduled
        Kind kind = Kind::None;
    };

    std::uint64_t run(Real tEnd, std::uint64_t collisionLimit);
    void advance(std::uint32_t i, Real t) noexcept;
    void schedule(std::uint32_t i) noexcept;
    template <bool Gravity, bool Growing>
    void scheduleImpl(std::uint32_t i) noexcept;
    void collide(std::uint32_t i, std::uint32_t j, Real t) noexcept;
    void collideWall(std::uint32_t i, std::uint32_t wall, Real t) noexcept;
    void crossCell(std::uint32_t i, std::uint32_t face) noexcept;
    bool elasticByTc(std::uint32_t i, std::uint32_t j, Real t) const noexcept;
    void buildCells();
    void regrid();
    std::uint32_t cellIndex(const int c[D]) const noexcept;
    void cellCoords(std::uint32_t i, int c[D]) const noexcept;
    void insertIntoCell(std::uint32_t i, std::uint32_t cell) noexcept;
    void removeFromCell(std::uint32_t i) noexcept;
    V minimumImage(V d) const noexcept;
    void rescheduleAll() noexcept;

    /// What the event computation reads of every neighbour, in one cache line for spheres
    /// (random access per neighbour dominates the cost; spec 2.2's ParticleState).
    struct alignas(16) State {
        V x;            ///< [m] position at t_st
        V v;            ///< [m/s] velocity at t_st
        Real tst = 0;   ///< [s] time of the last update
        Real radius = 0;  ///< [m] radius at time 0 (growing spheres: a(t) = radius + u_a t)
    };

    EngineConfig m_config;
    std::vector<State> m_s;
    std::vector<Real> m_mass;
    std::vector<Vec3> m_omega;          ///< [rad/s] rough spheres only
    std::vector<std::uint32_t> m_counter;  ///< collision counters (wrap-around is harmless: only equality is tested)
    std::vector<Real> m_lastCollision;  ///< [s] time of each particle's last collision (TC model only)
    std::vector<std::uint32_t> m_cell, m_next, m_prev, m_head;
    std::vector<Event> m_event;
    Queue m_queue;
    std::array<int, 3> m_cells{1, 1, 1};     ///< cells per axis
    std::array<Real, 3> m_cellEdge{1, 1, 1}; ///< [m]
    std::array<Real, 3> m_invCellEdge{1, 1, 1};
    Real m_regridTime = kNoEvent;  ///< [s] growing spheres outgrow the cells at this time
    Real m_maxRadius0 = 0;         ///< [m] largest radius at time 0
    bool m_gravity = false;
    Real m_now = 0;
    Real m_virial = 0;
    Real m_dissipated = 0;
    EngineStats m_stats;
};

}  // namespace granulab::edmd
