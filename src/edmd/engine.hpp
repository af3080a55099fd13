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
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <vector>

#include "core/error.hpp"
#include "edmd/cell_window.hpp"
#include "edmd/event_queue.hpp"
#include "edmd/id_slot_map.hpp"
#include "edmd/kinematics.hpp"
#include "edmd/restitution.hpp"

namespace granulab::edmd {

struct EngineConfig {
    std::array<Real, 3> box{1, 1, 1};                ///< [m] box edge per axis, origin at 0
    std::array<bool, 3> periodic{true, true, true};  ///< false: hard plane walls at 0 and box
    Restitution restitution;                         ///< normal restitution between particles
    Real wallRestitution = 1;                        ///< normal restitution at the walls
    /// Rough spheres (edmd Eq. 2.6-2.8): tangential restitution phi in [-1, 1] (-1: smooth, no
    /// spin is tracked); inertiaFactor z = I/(m a^2) (0.4 solid sphere, 0.5 solid disk).
    Real tangentialRestitution = -1;
    Real inertiaFactor = 0.4;
    /// TC model (edmd spec 4.3, Luding & McNamara): a collision (also with a wall) is elastic if
    /// either partner collided less than tc [s] before (prevents inelastic collapse); 0: off.
    Real tc = 0;
    std::array<Real, 3> gravity{0, 0, 0};  ///< [m/s^2]
    /// [m/s] u_a: every radius grows as a(t) = a(0) + u_a t (edmd Eq. 2.16); periodic boxes only.
    Real growthRate = 0;
    /// [m] lower bound of the cell edge; 0: the largest diameter (rounded up to fit the box).
    Real cellSize = 0;
    /// Target number of cells per particle C/N (edmd spec 2.4, AT-6); 0: 1.5 in 2D and 8 in 3D,
    /// the measured optima at low density. Fewer cells where the diameter, cellSize or the box
    /// (periodic axes need 3 cells) do not allow as many.
    Real cellsPerParticle = 0;
    /// Every axis' cell count a power of two (the nearest to the target that the diameter
    /// allows): the Morton blocks of the parallel engine (edmd spec 3.1). A serial run with it
    /// uses the parallel engine's grid, so the two agree event for event.
    bool powerOfTwoCells = false;

    bool rough() const noexcept { return tangentialRestitution > -1; }
};

struct EngineStats {
    std::uint64_t events = 0, collisions = 0, annulled = 0, cellCrossings = 0, wallCollisions = 0;
    std::uint64_t tcElastic = 0;  ///< collisions made elastic by the TC rule
    std::uint64_t regrids = 0;    ///< cell grids rebuilt because growing spheres outgrew them
};

/// Cells per axis of the engine's grid (edmd spec 2.4; EngineConfig's cell keys) for n
/// particles whose largest radius is amax [m]. Throws std::invalid_argument when a periodic
/// axis holds fewer than 3 cells.
template <int D>
std::array<int, 3> chooseCellGrid(const EngineConfig& config, std::uint32_t n, Real amax);

/// Cell coordinate along one axis of a position x [m] on a grid of `cells` cells of inverse
/// edge invEdge = cells / L [1/m], clamped to the grid: the one rounding that the serial and the
/// parallel engine both use, so that they put every particle in the same cell.
inline std::uint16_t cellCoordinate(Real x, Real invEdge, int cells) noexcept {
    return static_cast<std::uint16_t>(std::clamp(static_cast<int>(std::floor(x * invEdge)), 0, cells - 1));
}
/// The same for a particle of velocity v [m/s] on a grid of edge L / cells [m]: one on a cell
/// face (as the face crossings see it, edmd Eq. 2.22-2.25: lo = k edge) and moving across it
/// belongs to the cell it enters anyway. Otherwise it would cross at dt = 0: a lattice whose
/// sites fall on cell faces would start with a quarter of its events at one instant.
inline std::uint16_t cellCoordinate(Real x, Real v, Real invEdge, Real edge, int cells) noexcept {
    int k = cellCoordinate(x, invEdge, cells);
    if (v < 0 && k > 0 && x <= k * edge)
        --k;
    else if (v > 0 && k + 1 < cells && x >= (k + 1) * edge)
        ++k;
    return static_cast<std::uint16_t>(k);
}

/// Position of an event in the global order: time, then the particle's global id (edmd spec
/// 3.8 [I]: ties broken by id, so that serial and parallel runs execute the same order).
/// A received record of a particle comes before that particle's own event of the same instant
/// (the record is the state after an earlier event of that instant, dt = 0 events).
struct EventKey {
    Real time = kNoEvent;    ///< [s]
    std::uint32_t id = 0;    ///< global particle id
    std::uint32_t kind = 0;  ///< 0: a received record, 1: an event
    friend bool operator<(const EventKey& a, const EventKey& b) noexcept {
        return a.time < b.time || (a.time == b.time && (a.id < b.id || (a.id == b.id && a.kind < b.kind)));
    }
};

/// One particle's complete state, independent of storage slots and ranks: what the parallel
/// engine's halo copies, migrations, rollback checkpoints and rank-count-independent checkpoints
/// carry (edmd spec 3.4, 3.8). Plain data (sent as bytes).
struct ParticleRecord {
    std::uint32_t id = 0;                 ///< global particle id
    std::uint32_t counter = 0;            ///< collision counter (spec 2.6)
    std::array<std::uint16_t, 3> cell{};  ///< cell coordinates per axis
    /// Scheduled event: kind (0 none, 1 particle, 2 cell face, 3 wall face, 4 not yet
    /// predicted), face for kinds 2 and 3.
    std::uint8_t eventKind = 4;
    std::uint8_t eventFace = 0;
    std::array<Real, 3> x{};                ///< [m] position at tst
    std::array<Real, 3> v{};                ///< [m/s] velocity at tst
    Real tst = 0;                           ///< [s] time of the last update
    Real eventTime = kNoEvent;              ///< [s]
    std::uint32_t eventPartner = 0;         ///< global id of the partner (kind 1)
    std::uint32_t eventPartnerCounter = 0;  ///< its counter when scheduled
    Real radius0 = 0;                       ///< [m] radius at time 0 (a(t) = radius0 + u_a t)
    Real mass = 0;                          ///< [kg]
    std::array<Real, 3> omega{};            ///< [rad/s] (rough spheres)
    Real lastCollision = -kNoEvent;         ///< [s] time of the last collision (TC model)
};

/// The engine's state that is not per particle (clock, statistics, accumulators, rules).
struct EngineGlobals {
    Real now = 0;
    EngineStats stats;
    Real virial = 0, dissipated = 0;
    Restitution restitution;
    Real wallRestitution = 1, tc = 0, growthRate = 0;
};

/// A parallel rank's view of the cell grid (edmd spec 3.1, 3.6): owned cells (interior or
/// border: next to another rank's cell), halo cells (another rank's cells next to an owned
/// one, holding virtual copies of its particles) and foreign cells (none of these).
enum class CellRole : std::uint8_t { Foreign = 0, Interior = 1, Border = 2, Halo = 3 };
/// A cell this rank owns (its particles are real here).
inline bool ownedRole(CellRole r) noexcept {
    return r == CellRole::Interior || r == CellRole::Border;
}
struct DomainLayout {
    std::array<int, 3> cells{1, 1, 1};  ///< cells per axis of the global grid
    std::vector<CellRole> role;         ///< per window index (domain only)
    /// Per window index: 1 for an interior cell with a border cell among its 3^D neighbours. A
    /// collision of a particle there can reach a border cell (its partner stays within those
    /// 3^D cells until the collision), so it is announced as a border event.
    std::vector<std::uint8_t> fringe;
    std::uint32_t globalParticles = 0;  ///< N: ids are 0 .. N-1
    /// The cells this rank keeps tables for (its own and its halo; domain only). Cells
    /// outside it are foreign.
    CellWindow window;
    /// One rank's part of a parallel run; false: a serial engine (every cell owned; role,
    /// fringe and window ignored).
    bool domain = false;
    /// A serial engine's layout: the grid only.
    static DomainLayout serial(const std::array<int, 3>& cells) {
        DomainLayout layout;
        layout.cells = cells;
        return layout;
    }
};

/// Why the last run() stopped short of its end (issue 11's progress watchdog).
enum class Stall : std::uint8_t {
    None,
    Clock,        ///< the clock stood still over a window of events (collapse, jamming, a Zeno loop)
    NoCollision,  ///< a collision-count run made no collision over a long window of events
};

template <int D, class Queue = CalendarQueue>
class Engine {
public:
    using V = VecD<D>;
    /// Particles at positions x [m] (inside the box, not overlapping), velocities v [m/s],
    /// radii [m] (at time 0), masses [kg]; all at time 0. Throws std::invalid_argument when the
    /// box holds fewer than 3 cells per periodic axis or the input is inconsistent.
    Engine(EngineConfig config, std::vector<V> x, std::vector<V> v, std::vector<Real> radius,
           std::vector<Real> mass);

    /// Executes events until the next one would be later than t_end [s]; afterwards time() is
    /// t_end. Returns the events done. Both run calls stop early, after a whole event, when
    /// stalled() (the clock stands still) or when interruptRequested() (core/interrupt.hpp,
    /// polled every 4096 events; then interrupted() is true and time() is that of the last event).
    std::uint64_t runUntil(Real tEnd);
    /// Executes events until `collisions` more collisions have happened or the next event would
    /// be later than t_end; time() is then the time of the last event. Stops early when
    /// stalled() (the clock stands still, or no collision happens over a long window).
    std::uint64_t runCollisions(std::uint64_t collisions, Real tEnd = kNoEvent);
    /// The watchdog's verdict on the last run (Stall::None: it reached its end). A stalled
    /// engine keeps a consistent state at time(); running it again continues the stall.
    Stall stalled() const noexcept { return m_stall; }
    /// Events of one watchdog window: the clock must move within it (N-proportional, so that
    /// any legitimate burst of simultaneous events fits; bounded, so a stall ends in seconds).
    std::uint64_t watchdogWindow() const noexcept { return 16 * std::uint64_t{size()} + (1u << 17); }
    /// The last run call stopped early on SIGINT/SIGTERM.
    bool interrupted() const noexcept { return m_interrupted; }
    /// Elastic pre-run done (edmd spec 4.2 step 4): brings every particle to the current time,
    /// makes it time 0 and resets collision counters, TC clocks, statistics and accumulators.
    void restartClock();
    /// Growing spheres (edmd spec 4.5) from now on at u [m/s] per radius (0: fixed radii): the
    /// radii keep their current values, the cells and the schedule are rebuilt. Throws
    /// std::invalid_argument for growth in a box that is not periodic on every axis.
    void setGrowthRate(Real u);
    /// Replaces the collision rules (restitution, TC, roughness) from now on.
    void setCollisionRules(const Restitution& restitution, Real wallRestitution, Real tc);

    Real time() const noexcept { return m_now; }
    const EngineStats& stats() const noexcept { return m_stats; }
    const EngineConfig& config() const noexcept { return m_config; }
    std::uint32_t size() const noexcept { return static_cast<std::uint32_t>(m_s.size()); }
    std::array<int, 3> cellsPerAxis() const noexcept { return m_cells; }

    /// Per-particle queries by particle index i (below, to collisions(i)): serial engines only;
    /// a domain engine holds a part of the particles and answers through records().
    /// Position [m] (wrapped into the box on periodic axes) and velocity [m/s] of particle i
    /// extrapolated to the current time; the schedule is not touched.
    V positionNow(std::uint32_t i) const noexcept;
    V velocityNow(std::uint32_t i) const noexcept;
    /// Angular velocity [rad/s] (zero unless rough; 2D: the z component in [2]).
    Vec3 omega(std::uint32_t i) const noexcept { return m_omega.empty() ? Vec3{} : m_omega[m_slot[i]]; }
    Real radius(std::uint32_t i) const noexcept { return radiusSlot(m_slot[i]); }
    Real mass(std::uint32_t i) const noexcept { return massSlot(m_slot[i]); }
    /// Collisions particle i has suffered (particles and walls) since the last restartClock().
    std::uint64_t collisions(std::uint32_t i) const noexcept { return m_s[m_slot[i]].counter; }
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
    /// Bytes held by the engine (particle state, cells, events, queue); per particle about 64 +
    /// 8 (event) + 2 D (cell) + 4 (id map) + the queue + 4 C/N (cell heads) for spheres.
    std::size_t memoryBytes() const noexcept;

    /// Complete state in a binary stream; loadState restores it so that the run continues bit
    /// for bit (the configuration must be the same; the caller checks that).
    void saveState(std::ostream& os) const;
    void loadState(std::istream& is);

    // ---- records and the domain mode (edmd spec 3; edmd/parallel/parallel_engine.hpp) ----

    /// An engine from records (their scheduled events kept, kind 4 predicted now) on the grid of
    /// `layout`. Without layout.domain every cell is owned (a serial engine, e.g. resumed from
    /// a rank-count-independent checkpoint); else a domain engine: particles in halo cells are
    /// virtual copies (no events of their own, spec 3.6).
    Engine(EngineConfig config, const DomainLayout& layout, const EngineGlobals& globals,
           std::vector<ParticleRecord> records);
    /// An exact copy (every array, the queues, the domain data): the parallel engine's rollback
    /// copy, taken and restored at memory speed instead of from records.
    Engine(const Engine& other);
    Engine& operator=(const Engine& other);
    /// Every particle's record (owned ones only if realOnly), sorted by id; events as scheduled.
    std::vector<ParticleRecord> records(bool realOnly) const;
    EngineGlobals globals() const;
    /// The cells this engine keeps tables for (serial: the whole grid; domain mode: the
    /// layout's window). takeCellEvents and DomainLayout::role use its indices.
    const CellWindow& window() const noexcept { return m_window; }
    /// The next event or received update, and the next one that can touch another rank's
    /// particles (a border event, spec 3.6, or a pending update): what a step announces.
    EventKey nextKey() const noexcept;
    EventKey nextBorderKey() const noexcept;
    /// Executes events and received updates in key order while their key is below `limit`;
    /// stops after the first border event whose key is not below `stopAfterBorderFrom` (the
    /// announced one: a step ends with it, spec 3.8 step 3).
    std::uint64_t runDomain(EventKey limit, EventKey stopAfterBorderFrom = EventKey{});
    /// runDomain stopped because the clock stood still over a watchdog window (an inelastic
    /// collapse); it does nothing more.
    bool domainStalled() const noexcept { return m_domain && m_domain->stalled; }
    /// Applies every received update of time <= t [s] (a section that ended inside an instant,
    /// after the k-th collision: the partner's record made by it is applied, as in the serial
    /// engine, while the events after it wait).
    void applyReceivedUntil(Real t);
    /// Applies the received updates that come before every scheduled event (and below
    /// `limit`), in order: what runDomain would do next before any event.
    void applyPendingInOrder(EventKey limit);
    /// A neighbour's record of a particle in an owned or halo cell (or that left them), applied
    /// at its time tst in key order (queued; applied at once when it is a late virtual copy
    /// that nothing has read since). Returns false on a causality error (spec 3.8 steps 5-6):
    /// the record is earlier than what this rank has already done with that particle's
    /// neighbourhood; causalityError() is then the earliest such time.
    bool receive(const ParticleRecord& record);
    Real causalityError() const noexcept;
    /// A changed particle that other ranks may see: its record (with its cell after the change)
    /// and its cell before, in grid coordinates (both cells decide who receives it).
    struct Change {
        ParticleRecord record;
        std::array<std::uint16_t, 3> oldCell{};
    };
    /// Domain mode: frees the slots of particles that left this rank's cells and halo when they
    /// are an eighth of all (at least 256); slots are never reused in between, so a long run
    /// would otherwise grow with every particle that ever passed through the halo. Physically a
    /// no-op (every order is by id); the parallel engine calls it at barriers. Returns the
    /// slots freed.
    std::uint32_t reclaimDeadSlots();
    /// Moves the changes since the last call to `out` (cleared first), in the order made.
    void drainChanges(std::vector<Change>& out);
    /// Particles this engine owns (domain mode: those in its own cells; else all).
    std::uint32_t ownedCount() const noexcept;
    /// Sets the clock to t >= time() (all events up to t done): the end of a parallel section.
    void setTime(Real t) noexcept { m_now = std::max(m_now, t); }
    /// Adds the events executed per owned cell since the last call to `perCell` (by window
    /// index, sized to the window) and restarts the count: the load measure of the balancing (spec 3.2).
    void takeCellEvents(std::vector<std::uint64_t>& perCell);
    /// Starts counting events per cell (off by default: a write per event that only the load
    /// balancing needs).
    void countCellEvents();
    /// Simulated causality error (tests of the rollback): the first record received after
    /// `events` more local events is treated as late (kNever: none).
    void injectCausalityError(std::uint64_t events) noexcept;
    static constexpr std::uint64_t kNever = ~std::uint64_t{0};
    /// Appends the key of every particle collision executed from now on to `log` (nullptr: no
    /// log): the parallel engine's collision-count stops find the k-th collision of a section.
    void setCollisionLog(std::vector<EventKey>* log) noexcept;

private:
    struct DomainData;
    // ---- events (spec 2.2 "Event", 8 bytes): the partner field encodes the kind.
    static constexpr std::uint32_t kNone = 0xFFFFFFFFu;  ///< no event (t = +inf) / end of a cell list
    /// + face: cell crossing, face = 2 axis + (1 if upward).
    static constexpr std::uint32_t kCellBase = 0xFFFFFFF0u;
    static constexpr std::uint32_t kWallBase = 0xFFFFFFE0u;    ///< + face: plane wall at that face of the box
    static constexpr std::uint32_t kMaxParticles = kWallBase;  ///< slots below this are particles
    struct Event {
        std::uint32_t partner = kNone;     ///< particle slot, kCellBase + face, kWallBase + face or kNone
        std::uint32_t partnerCounter = 0;  ///< partner's collision counter when scheduled (collisions only)
    };
    /// What the event computation reads of every neighbour, one cache line for spheres (random
    /// access per neighbour dominates the cost; spec 2.2's ParticleState). Indexed by slot:
    /// particles are kept in cell order (re-sorted every kSortEvery N events) so that the
    /// particles of neighbouring cells lie close in memory; m_slot maps the caller's particle
    /// indices to slots.
    struct alignas(D == 3 ? 64 : 16) State {
        V x;                         ///< [m] position at t_st
        V v;                         ///< [m/s] velocity at t_st
        Real tst = 0;                ///< [s] time of the last update
        std::uint32_t next = kNone;  ///< next slot in the same cell (singly linked, ascending after a sort)
        std::uint32_t counter = 0;   ///< collision counter (wrap-around is harmless: only equality is tested)
    };
    using CellCoords = std::array<std::uint16_t, D>;  ///< integer cell coordinates per axis
    static constexpr int kMaxCellsPerAxis = 65535;
    /// Events between two spatial sorts, in units of N (a sort costs about as much as N events).
    static constexpr std::uint64_t kSortEvery = 16;
    /// Touching pairs approaching slower than this fraction of their relative speed graze
    /// (round-off of r.w is ~1e-16 |r||w|; image shifts across a periodic box add ~1e-16 L/a).
    static constexpr Real kGrazing = 1e-10;

    /// The particle whose next event is being predicted, brought to the current time.
    struct Subject {
        std::uint32_t slot;  ///< its slot
        V x;                 ///< [m] position now
        V v;                 ///< [m/s] velocity now
        Real radius;         ///< [m] radius now
    };
    /// The earliest event found so far while predicting (spec 2.8: only the earliest is kept).
    struct Prediction {
        Real dt = kNoEvent;  ///< [s] from now
        Event ev;
    };
    /// The neighbour cells of a cell: up to 3 per axis (fewer at a wall), each as its
    /// contribution to the cell index and the image shift [m] of its particles across a periodic
    /// boundary (spec 2.4 [I], image shifts).
    struct Neighbourhood {
        std::uint32_t offset[3][3] = {};
        Real shift[3][3] = {};
        int count[3] = {1, 1, 1};
    };

    std::uint64_t run(Real tEnd, std::uint64_t collisionLimit);
    void advance(std::uint32_t s, Real t) noexcept;
    void schedule(std::uint32_t s) noexcept;
    template <bool Gravity, bool Growing, bool Uniform>
    void scheduleImpl(std::uint32_t s) noexcept;
    /// Cell-face crossings and plane walls of the subject's cell (edmd Eq. 2.22-2.25).
    template <bool Gravity>
    void predictFaces(const Subject& p, const CellCoords& c, Prediction& next) const noexcept;
    Neighbourhood neighbourhood(const CellCoords& c) const noexcept;
    /// The key of the earliest scheduled event (+infinity when there is none).
    EventKey topEventKey() const noexcept {
        return size() > 0 ? EventKey{m_queue.topTime(), m_id[m_queue.top()], 1} : EventKey{};
    }
    /// Domain mode: the key of the earliest received update (+infinity when there is none).
    EventKey pendingKey() const noexcept;
    /// Domain mode: [s] the last prediction of a border or fringe particle around c.
    Real lastReadAround(const CellCoords& c) const noexcept;
    /// Domain mode: no particle in the 3^D cells around c has a state later than t [s].
    bool settledAround(const CellCoords& c, Real t) const noexcept;
    /// Collisions with the particles of the neighbour cells (edmd Eq. 2.18-2.21).
    template <bool Gravity, bool Growing, bool Uniform>
    void predictPairs(const Subject& p, const Neighbourhood& nb, Prediction& next) const noexcept;
    /// Collision time [s] of the subject with slot j at relative position r [m] and velocity w
    /// [m/s]; false when the pair cannot collide before `bound` [s] (fixed radii: a cheap test
    /// before the square root) or j is the subject (growing radii).
    template <bool Growing, bool Uniform>
    bool pairTime(const Subject& p, std::uint32_t j, const V& r, const V& w, Real bound,
                  Real& dt) const noexcept;
    /// Stores the predicted event of slot s and queues it at now + dt.
    void push(std::uint32_t s, const Prediction& next) noexcept;
    /// Gravity [m/s^2] as a D-vector.
    V gravityVector() const noexcept {
        V g;
        for (int d = 0; d < D; ++d) g[d] = m_config.gravity[d];
        return g;
    }
    void collide(std::uint32_t s, std::uint32_t j, Real t) noexcept;
    void collideWall(std::uint32_t s, std::uint32_t wall, Real t) noexcept;
    void crossCell(std::uint32_t s, std::uint32_t face) noexcept;
    bool elasticByTc(std::uint32_t s, std::uint32_t j, Real t) const noexcept;
    /// Cell geometry from the current largest radius (spec 2.4) and every particle's cell from
    /// its position at t_st.
    void buildCells();
    /// Counting sort of the slots by cell index; relinks the cell lists, remaps events and the
    /// id map; rebuilds the queue if `requeue`. Physically a no-op (only slots change).
    void sortParticles(bool requeue);
    void regrid();
    /// Window index of a cell that lies in the window (the per-cell tables' index).
    std::uint32_t cellIndex(const CellCoords& c) const noexcept;
    /// CellWindow::local for a grid coordinate known to lie in the window: without the outside
    /// test (hot: every link, unlink and prediction); the wrap compiles to a conditional move.
    int windowCoordinate(int d, int c) const noexcept {
        int l = c - m_window.origin[d];
        l += l < 0 ? m_cells[d] : 0;
        GL_ASSERT(l < m_window.extent[d], "edmd::Engine: cell outside the window");
        return l;
    }
    void linkCell(std::uint32_t s) noexcept;
    void unlinkCell(std::uint32_t s) noexcept;
    V minimumImage(V d) const noexcept;
    /// r_i - r_j of two stored positions through the same image arithmetic as the event
    /// prediction ((x_i -/+ L) - x_j across a periodic boundary), so that a collision and its
    /// prediction agree on the sign of the approach speed.
    V contactVector(const V& xi, const V& xj) const noexcept;
    void rescheduleAll() noexcept;
    Real radiusSlot(std::uint32_t s) const noexcept {
        return (m_radius.empty() ? m_uniformRadius : m_radius[s]) + m_config.growthRate * m_now;
    }
    Real massSlot(std::uint32_t s) const noexcept { return m_mass.empty() ? m_uniformMass : m_mass[s]; }
    V positionSlot(std::uint32_t s) const noexcept;
    V velocitySlot(std::uint32_t s) const noexcept;

    // ---- domain mode (engine_domain.cpp)
    bool realSlot(std::uint32_t s) const noexcept;
    /// Bytes of the domain data (0 for a serial engine).
    std::size_t domainMemoryBytes() const noexcept;
    /// Slot of a particle id, kNone if not held here.
    std::uint32_t slotOfId(std::uint32_t id) const noexcept {
        return m_domain ? m_domain->slots.find(id) : m_slot[id];
    }
    CellRole roleOf(std::uint32_t s) const noexcept;
    /// Role of the cell with grid coordinates c[0..D) (Foreign outside the window).
    template <class Coords>
    CellRole roleOfCell(const Coords& c) const noexcept {
        const std::uint32_t w = m_window.indexOf<D>(c);
        return w == CellWindow::kOutside ? CellRole::Foreign : m_domain->role[w];
    }
    void noteChange(std::uint32_t s, const CellCoords& oldCell);
    void scheduleDomain(std::uint32_t s) noexcept;
    void scheduleDomainBorder(std::uint32_t s) noexcept;
    void applyPending();
    std::uint32_t applyRecord(const ParticleRecord& r);
    std::uint32_t addSlot(std::uint32_t id);
    /// Reserves room for n slots in every per-slot array.
    void reserveSlots(std::size_t n);
    /// Calls f(array) for every per-slot array in use (the optional ones only when present);
    /// a new per-particle array is added here.
    template <class F>
    void forEachSlotArray(F&& f) {
        f(m_s);
        f(m_event);
        f(m_cellOf);
        f(m_id);
        if (!m_radius.empty()) f(m_radius);
        if (!m_mass.empty()) f(m_mass);
        if (!m_omega.empty()) f(m_omega);
        if (!m_lastCollision.empty()) f(m_lastCollision);
    }
    void killSlot(std::uint32_t s) noexcept;
    ParticleRecord recordOf(std::uint32_t s) const;
    void setFromRecord(std::uint32_t s, const ParticleRecord& r);

    EngineConfig m_config;
    BigVector<State> m_s;
    BigVector<Event> m_event;
    BigVector<CellCoords> m_cellOf;  ///< cell of each slot
    /// Slot of each particle id (serial; a domain engine keeps DomainData::slots instead).
    BigVector<std::uint32_t> m_slot;
    BigVector<std::uint32_t> m_id;  ///< global particle id of each slot (the queues' tie keys)
    std::vector<Real> m_radius;     ///< [m] radius at time 0 per slot; empty if all equal (m_uniformRadius)
    std::vector<Real> m_mass;       ///< [kg] per slot; empty if all equal (m_uniformMass)
    Real m_uniformRadius = 0, m_uniformMass = 1;
    std::vector<Vec3> m_omega;                  ///< [rad/s] per slot, rough spheres only
    std::vector<Real> m_lastCollision;          ///< [s] per slot: time of the last collision (TC model only)
    BigVector<std::uint32_t> m_head;            ///< first slot of each window cell
    Queue m_queue;                              ///< keyed by slot
    std::array<int, 3> m_cells{1, 1, 1};        ///< cells per axis of the whole grid
    CellWindow m_window;                        ///< the cells with tables here (serial: all)
    bool m_windowGiven = false;                 ///< m_window comes from a DomainLayout
    std::array<int, 3> m_forcedCells{0, 0, 0};  ///< cells per axis given by a DomainLayout (0: chosen)
    std::array<std::uint32_t, 3> m_stride{1, 1, 1};  ///< window index stride per axis
    std::array<Real, 3> m_cellEdge{1, 1, 1};         ///< [m]
    std::array<Real, 3> m_invCellEdge{1, 1, 1};
    Real m_regridTime = kNoEvent;  ///< [s] growing spheres outgrow the cells at this time
    Real m_maxRadius0 = 0;         ///< [m] largest radius at time 0
    bool m_gravity = false;
    Real m_now = 0;
    Real m_virial = 0;
    Real m_dissipated = 0;
    std::uint64_t m_nextSort = 0;  ///< value of m_stats.events at which the next spatial sort happens
    EngineStats m_stats;
    Stall m_stall = Stall::None;
    /// The watchdog's current window: it ends at `events`; the clock and the collision count
    /// at its start; windows in a row without a collision.
    struct Watch {
        std::uint64_t events = 0;
        Real time = 0;
        std::uint64_t collisions = 0, quietWindows = 0;
    } m_watch;
    /// Event count of the next housekeeping (interrupt poll, watchdog, sort): the minimum of
    /// their due counts; 0 after anything that changes one of them.
    std::uint64_t m_checkAt = 0;
    /// Starts a fresh watchdog window at the current state (construction, restart, load).
    void resetWatchdog() noexcept;
    bool m_interrupted = false;            ///< the last run() stopped on an interrupt request
    std::unique_ptr<DomainData> m_domain;  ///< domain mode only

    /// Per-rank data of the domain mode (engine_domain.cpp).
    struct PendingRecord {
        ParticleRecord record;
        std::uint64_t arrival = 0;
    };
    struct DomainData {
        IdSlotMap slots;                    ///< slot of each particle held here (own and halo)
        std::uint32_t globalParticles = 0;  ///< N: ids are 0 .. N-1
        std::vector<CellRole> role;         ///< per window index
        std::vector<std::uint8_t> fringe;   ///< per window index (DomainLayout::fringe)
        std::vector<std::uint32_t>
            cellEvents;                  ///< per window index: events since takeCellEvents (if counted)
        AddressableHeap border;          ///< per slot: the time of its event if a border event
        std::vector<std::uint8_t> dead;  ///< per slot: left this rank's cells (slot not reused)
        std::uint32_t deadCount = 0;     ///< slots marked dead
        std::vector<Change> changes;
        std::vector<PendingRecord> pending;  ///< received updates, a min-heap by (tst, id, arrival)
        std::uint64_t arrivals = 0;          ///< records received so far (the arrival order)
        /// Per window index: [s] the last time a particle in this border or fringe cell was
        /// predicted (a prediction reads the particles in the 3^D cells around it).
        std::vector<Real> readTime;
        Real error = kNoEvent;                          ///< [s] earliest causality error
        std::uint64_t injectAt = ~std::uint64_t{0};     ///< test hook: event count of a forced error
        std::vector<EventKey>* collisionLog = nullptr;  ///< keys of executed collisions (optional)
        std::uint32_t owned = 0;
        // Progress watchdog of runDomain, as the serial run()'s: the clock must move in a window.
        std::uint64_t watchAt = 0;
        Real watchTime = 0;
        bool stalled = false;
    };
};

}  // namespace granulab::edmd
