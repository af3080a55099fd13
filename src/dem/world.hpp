// SPDX-License-Identifier: MIT
// The DEM world and its straight-line step (DESIGN.md "The DEM step"), each stage timed. In the
// order they run: 1 predict, 8 scene updaters (walls move and law changes apply before the forces
// of the new time; particles leave and enter at the end of the step, the only place N changes),
// 2+3+5 neighbour check and, when needed, rebuild (broad phase, history transfer), 4+6 forces
// (polygon world corners, narrow phase fused with the laws, body forces), 7 correct; 4+6+7 repeat
// until an iterating integrator accepts the step. Stage 9 (observers) runs in the caller, which
// owns all I/O.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/thread_governor.hpp"
#include "core/timer.hpp"
#include "dem/broad_phase.hpp"
#include "dem/fluid_forces.hpp"
#include "dem/forces.hpp"
#include "dem/integrator.hpp"
#include "dem/law_table.hpp"
#include "dem/neighbor_list.hpp"
#include "dem/particle_flow.hpp"
#include "dem/schedules.hpp"
#include "model/particle_store.hpp"
#include "model/walls.hpp"

namespace granulab::dem {

enum class Stage { Predict, Neighbors, Forces, Fluid, Correct, Updaters, Count };
const char* stageName(Stage s) noexcept;

/// Global viscous damping active for steps with fromStep <= step < toStep.
struct DampingWindow {
    Real gamma = 0, gammaRotation = 0;
    std::int64_t fromStep = 0, toStep = 0;
};

/// The remembered state of one contact (a gc2d gci; dem/setup.hpp): particle slot a with particle
/// slot b, or with wall b; `unknown`: named ids the scene does not have (counted, not restored).
struct RememberedContact {
    std::uint32_t a = 0, b = 0;
    bool wall = false;
    bool unknown = false;
    Real xi = 0;       ///< [m] tangential spring
    Real areaOld = 0;  ///< [m^2] overlap area of the last step
};

struct WorldConfig {
    Real dt = 0;   ///< [s]
    Vec2 gravity;  ///< [m/s^2]
    std::vector<DampingWindow> damping;
    Real skin = 0;               ///< [m] neighbour-list skin
    int sortEveryRebuilds = 16;  ///< spatial re-sort of slots every k-th rebuild (0: never)
    /// gc2d restart: contacts whose history initialize() restores (slots at construction)
    std::vector<RememberedContact> rememberedContacts;
    Real overlapGuard = 0;  ///< see BodyForces::overlapGuard
    IntegratorParams integrator;
    std::string broadPhase = "cell_grid";
    int threads = 1;  ///< threads of the step (run.threads); the results do not depend on it
    /// run.threads = 0: `threads` is the most (the cores), the step's wall time chooses the count
    /// (core/thread_governor.hpp); false: exactly `threads`.
    bool autoThreads = false;
    std::vector<PullSpring> springs;                 ///< slots refer to the store given to the World
    std::optional<GravitySchedule> gravitySchedule;  ///< replaces `gravity` when set (gc2d 6.6)
    std::optional<SizeCycle> sizeCycle;              ///< global size scaling s(t) (gc2d 2.4)
    FlowConfig flow;                                 ///< sources, inlets, outlets (step 8)
    /// Contact laws replaced at a step (gc2d 6.7: friction or cohesion switched off at t).
    struct LawChange {
        std::int64_t step = 0;
        LawTable laws;
    };
    std::vector<LawChange> lawChanges;  ///< ascending steps
    bool weight = true;                 ///< m g on every particle (cfddem #Fg)
    bool particleContacts = true;       ///< particle-particle contacts (cfddem #FP)
    bool wallContacts = true;           ///< particle-wall contacts (cfddem #FB)
    /// One-way coupling to a flow field (cfddem spec 5); absent: no fluid.
    struct Fluid {
        fluid::FieldSource source;  ///< moved into the World's FieldSeries (World::field()) at construction
        FluidForceConfig forces;
    };
    std::optional<Fluid> fluid;
    /// Mutual attraction (cfddem spec 5.6); absent: off.
    struct Attraction {
        Real constant = 0;  ///< [m^3/(kg s^2)] G
        Real cutoff = 0;    ///< [m] 0: all pairs
    };
    std::optional<Attraction> attraction;
};

/// Bit flags returned by World::step (STYLE.md: step() never throws).
enum StepStatus : std::uint32_t {
    kStepOk = 0,
    kStepNonFinite = 1u << 0,    ///< NaN or infinity in the particle state
    kStepTunnelling = 1u << 1,   ///< a particle moved more than half its radius in one step
    kStepDeepOverlap = 1u << 2,  ///< an overlap reached the smaller radius
    kStepFieldFailed = 1u << 3,  ///< a flow field could not be loaded (World::fieldError())
};

struct Energies {
    Real kinetic = 0;     ///< [J] translational
    Real rotational = 0;  ///< [J]
    Real potential = 0;   ///< [J] gravitational, -m g . x
    Real elastic = 0;     ///< [J] stored in contact springs
    Real total() const noexcept { return kinetic + rotational + potential + elastic; }
};

class World {
public:
    World(WorldConfig config, model::ParticleStore store, model::WallSet walls, LawTable laws,
          model::ShapePool shapes = {});

    /// First neighbour build and force evaluation (skipped after loadState). Throws
    /// std::runtime_error when the flow field of t cannot be loaded.
    void initialize();
    /// Advances one step; returns StepStatus flags. It is beginStep, neighborsStale and
    /// rebuildNeighbors when stale, then finishStep: a domain decomposition (dem/parallel/) runs
    /// those parts itself, with its halo exchange between them.
    std::uint32_t step();

    // ---- The step in parts ----------------------------------------------------------------
    /// Stage 1 (predict) and the scene updaters before the forces; StepStatus flags.
    std::uint32_t beginStep();
    /// Stage 2: true when the lists must be rebuilt before the forces (skin used up, law change).
    bool neighborsStale() const noexcept;
    /// Stages 3+5: broad phase and history transfer (with a spatial re-sort every k-th time).
    void rebuildNeighbors();
    /// Between two force evaluations of an iterating integrator: `agree` returns whether every
    /// part of a decomposed world accepts the step (and, if not, brings the ghosts' trial state
    /// up to date). One call per iteration, never per particle.
    class IterationLink {
    public:
        virtual ~IterationLink() = default;
        virtual bool agree(bool acceptedHere) = 0;
    };
    /// Stages 4, 6, 7 and the particles in and out; StepStatus flags.
    std::uint32_t finishStep(IterationLink* link = nullptr);

    // ---- Domain decomposition (dem/parallel/domain_world.hpp) -------------------------------
    /// Replaces every particle by `store`, whose slots from `ownedEnd` on are ghosts (their
    /// forces are not used and they have no wall contacts), sets the integrator state from
    /// `integratorRows` (the integrator's column count per slot, slot after slot) and rebuilds the
    /// lists with the given history (keys in the new slots). Radius bounds, ids, walls and the
    /// clock are kept. `countAsBuild`: a migration that counts in neighbors().builds (not the
    /// first split or a gathered copy). `outputCopy`: the lists get trial columns, for
    /// evaluateForOutput.
    void replaceParticles(model::ParticleStore store, const std::vector<Real>& integratorRows,
                          const std::vector<PairHistory>& pairHistory,
                          const std::vector<PairHistory>& wallHistory, std::size_t ownedEnd,
                          bool countAsBuild, bool outputCopy = false);
    /// The integrator's per-particle columns (nullptr: it keeps none). Fetch it once per loop:
    /// each call is a virtual one.
    const StateColumns* integratorState() const noexcept { return m_integrator->state(); }
    /// The same, for the halo exchange (ghost rows only are written).
    StateColumns* integratorStateForHalo() noexcept { return m_integrator->state(); }
    /// The particle state, for the halo exchange (ghost slots only are written).
    model::ParticleStore& storeForHalo() noexcept { return m_store; }
    /// Wall forces of all ranks (the halo sums them after the forces).
    std::vector<Vec2>& wallForceForSum() noexcept { return m_wallForce; }
    /// Particles in and out are the domain decomposition's (finishStep leaves them alone).
    void setExternalFlow(bool on) noexcept { m_externalFlow = on; }
    /// The communicator of the domain decomposition for the field stage (voidage cells, attraction
    /// between all pairs), which gathers from every rank; nullptr: one process.
    void setFieldCommunicator(Communicator* comm) noexcept { m_fieldComm = comm; }
    /// Slots (ascending, owned ones only) that leave through an outlet at the current time; booked.
    std::vector<std::uint32_t> flowLeaving() { return m_flow.leaving(m_store, time()); }
    /// What enters at the current time, placed against `everyone` (every rank's particles, the
    /// same on every rank) and the walls; the drops are booked (not the insertions).
    std::vector<NewParticle> flowEntering(const model::ParticleStore& everyone) {
        return m_flow.entering(everyone, m_walls, m_pool, time(), m_config.dt, gravityAt(time()));
    }
    ParticleFlow& flowForDomain() noexcept { return m_flow; }
    /// [m] the smallest radius of all ranks (tunnelling guard), after particles left.
    void setMinRadius(Real r) noexcept { m_minRadius = r; }
    /// Books particles that enter (flowEntering) and returns the id of the first: ids, radius
    /// bounds and the polygon flag follow them as in a one-rank run. The caller stores them.
    ParticleId admitParticles(const std::vector<NewParticle>& entering);
    /// The gathered copy of a decomposed run: takes the step, walls, size scale, laws, counters
    /// and integrator flags of `local` (one rank's world of the same scene).
    void adoptClock(const World& local);
    /// Evaluates the forces of the current state for outputs only: statistics (fluid ones too),
    /// wall forces and, when recordContacts is on, the contact log; the particles' forces and the accepted
    /// history are kept (the springs are not advanced: the drift is zero).
    void evaluateForOutput();

    std::int64_t stepIndex() const noexcept { return m_step; }
    Real time() const noexcept { return static_cast<Real>(m_step) * m_config.dt; }
    const WorldConfig& config() const noexcept { return m_config; }
    const model::ParticleStore& store() const noexcept { return m_store; }
    const model::WallSet& walls() const noexcept { return m_walls; }
    const NeighborList& neighbors() const noexcept { return m_list; }
    const LawTable& laws() const noexcept { return m_laws; }
    const ForceStats& forceStats() const noexcept { return m_stats; }
    /// Closest-feature work of polygon contacts since t = 0 (or the resume).
    const geom::FeatureStats& featureStats() const noexcept { return m_shapes.featureStats; }
    const model::ShapePool& shapes() const noexcept { return m_pool; }
    /// Springs with their current slots.
    const std::vector<PullSpring>& springs() const noexcept { return m_config.springs; }
    /// Sources, inlets and outlets with their counters.
    const ParticleFlow& flow() const noexcept { return m_flow; }
    /// Gravity [m/s^2] at the current time (the schedule's, if any).
    Vec2 gravity() const noexcept { return gravityAt(time()); }
    /// Total mass of the particles [kg].
    Real totalMass() const noexcept;
    /// [m] largest radius since t = 0 at the current size scale.
    Real maxRadius() const noexcept { return m_maxRadius; }
    /// Current global size scale s (1 without [size_scaling]).
    Real sizeScale() const noexcept { return m_scale; }
    /// Total contact force [N] on each wall at the last force evaluation.
    /// Contact records: when on, every force evaluation fills contactLog() (the last evaluation
    /// of a step wins). The DEM adapter turns it on for the steps that end at a snapshot.
    void recordContacts(bool on) noexcept { m_recordContacts = on; }
    const ContactLog& contactLog() const noexcept { return m_contactLog; }
    const std::vector<Vec2>& wallForce() const noexcept { return m_wallForce; }
    const StageTimers<Stage>& timers() const noexcept { return m_timers; }
    const char* broadPhaseName() const noexcept { return m_broad->name(); }
    const char* integratorName() const noexcept { return m_integrator->name(); }
    /// The configured count: run.threads, or the cores for the automatic count (autoThreads).
    int threads() const noexcept { return m_config.threads; }
    /// Threads the step uses now: exactly run.threads when it is given; with the automatic count,
    /// the governor's choice, at most one thread per kParticlesPerThread particles
    /// (kPolygonsPerThread with polygons), below which a thread costs more than it saves. The
    /// results do not depend on it.
    int team() const noexcept { return m_governor.team(); }
    /// From the next step on, exactly `threads` threads (as run.threads = threads > 0; 0: the automatic
    /// count again). The results do not depend on it.
    void setThreads(int threads);
    /// How the thread count was chosen (reason(), trials).
    const ThreadGovernor& threadGovernor() const noexcept { return m_governor; }
    static constexpr std::size_t kParticlesPerThread = 512;
    static constexpr std::size_t kPolygonsPerThread = 256;
    /// Replaces both work limits of the automatic count (tests use it).
    void setParticlesPerThread(std::size_t particles) {
        m_particlesPerThread = particles;
        updateTeam();
    }
    /// The flow field series (nullptr without [fluid]) and the fluid forces' statistics of the
    /// last evaluation.
    const fluid::FieldSeries* field() const noexcept { return m_field.get(); }
    const FluidStats& fluidStats() const noexcept { return m_fluidStats; }
    /// Replaces the fluid statistics by those of every rank's last evaluation (the domain's
    /// gather, after evaluateForOutput: the ranks evaluated where one process does).
    void setFluidStats(const FluidStats& stats) noexcept { m_fluidStats = stats; }
    /// Why the last step returned kStepFieldFailed.
    const std::string& fieldError() const noexcept { return m_fieldError; }
    /// Force evaluations since t = 0 (more than the steps for an iterating predictor-corrector).
    std::uint64_t forceEvaluations() const noexcept { return m_forceEvaluations; }

    Energies energies() const noexcept;
    /// Total linear momentum [kg m/s].
    Vec2 momentum() const noexcept;
    /// Bytes held by the engine (store, neighbour list, broad phase).
    std::size_t memoryBytes() const noexcept;

    // ---- gc2d restart files (a gso's state and a gci's contacts; io/gsi_scene.hpp) ----------
    /// Sets the clock to step `step` (t0 = step dt) before initialize().
    void setStartStep(std::int64_t step) noexcept { m_step = step; }
    /// The Gear predictor's scaled derivatives, 12 per particle in slot order (model::ParticleDef::gear);
    /// false when the integrator keeps none.
    bool restoreDerivatives(const std::vector<Real>& perSlot) {
        return m_integrator->restoreDerivatives(perSlot);
    }
    /// The same for writing a gso; empty when there is none.
    std::vector<Real> integratorDerivatives() const { return m_integrator->derivatives(); }
    /// Gives the listed contacts their history (pairs not in the neighbour list are skipped);
    /// initialize() calls it with WorldConfig::rememberedContacts. Returns how many were found.
    std::size_t restoreContacts(const std::vector<RememberedContact>& contacts);
    /// The contacts of WorldConfig::rememberedContacts that initialize() could not restore (ids
    /// unknown to the scene, or bodies not in contact range).
    std::size_t unrestoredContacts() const noexcept { return m_unrestoredContacts; }
    /// Every contact with a history (a tangential spring or an overlap area), for a gco.
    std::vector<RememberedContact> rememberedContacts() const;
    /// WorldConfig::rememberedContacts in the current slots (the particles may have been re-sorted).
    std::vector<RememberedContact> rememberedInSlots() const;

    /// Complete dynamic state for a bit-for-bit resume.
    void saveState(std::ostream& os) const;
    void loadState(std::istream& is);

private:
    /// Gives the automatic thread count the work limit of the particle count now, then applyTeam().
    void updateTeam();
    /// Hands team() to the force workspace, the integrator and the broad phase.
    void applyTeam() noexcept;
    void evaluateForces(const BodyForces& body, const DriftVelocities& drift, bool trial);
    /// The integrator's correction of slots [begin, end) of `world` (ForceWorkspace::finishSlots).
    static void correctSlotsOf(void* world, std::size_t begin, std::size_t end) noexcept;
    /// Fluid forces and mutual attraction (after the contact forces; stage Fluid).
    void evaluateFieldForces(const BodyForces& body);
    BodyForces bodyForcesAt(std::int64_t step) const noexcept;
    Vec2 gravityAt(Real t) const noexcept {
        return m_config.gravitySchedule ? dem::gravityAt(*m_config.gravitySchedule, t) : m_config.gravity;
    }
    /// Stage 8 at the end of a step: particles leave through outlets and enter from sources.
    void exchangeParticles();
    /// Applies the law changes due at the current step.
    void applyLawChanges();
    /// Sets the global size scale to s(t): radii and polygon corners times s, mass kept, moment of
    /// inertia times s^2 (gc2d 2.4, the spec's resolution of the ambiguity).
    void applySizeScale(Real t) noexcept;

    WorldConfig m_config;
    model::ParticleStore m_store;
    model::WallSet m_walls;
    LawTable m_laws;
    model::ShapePool m_pool;
    ShapeContext m_shapes;  ///< pool pointer refreshed at every use (World is movable)
    std::unique_ptr<BroadPhase> m_broad;
    std::unique_ptr<Integrator> m_integrator;
    NeighborList m_list;
    ForceStats m_stats;
    ForceWorkspace m_forceWork;
    std::size_t m_particlesPerThread = 0;  ///< 0: kParticlesPerThread / kPolygonsPerThread
    ThreadGovernor m_governor;
    /// [m] bound on every particle's displacement since the neighbour list's positions were taken:
    /// the sum of the largest speed times dt (integrators whose speed bounds the displacement);
    /// infinite when unknown (other integrators, after a resume). Below the skin's half the
    /// neighbour check skips its O(N) scan: it would find no rebuild due either.
    Real m_travelBound = std::numeric_limits<Real>::infinity();
    double m_stepStart = 0;  ///< [s] wall clock at beginStep, for the governor
    std::vector<Vec2> m_wallForce;
    ContactLog m_contactLog;
    bool m_recordContacts = false;
    StageTimers<Stage> m_timers;
    std::int64_t m_step = 0;
    std::size_t m_unrestoredContacts = 0;
    std::uint64_t m_forceEvaluations = 0;
    Real m_minRadius = 0;
    Real m_maxRadius = 0;  ///< [m] largest radius since t = 0 (outlet capture zones)
    ParticleFlow m_flow;
    ParticleId m_nextId = 0;              ///< id of the next inserted particle
    std::size_t m_lawChangesDone = 0;     ///< entries of m_config.lawChanges applied
    bool m_lawRebuildDue = false;         ///< a law change regroups the lists before the next forces
    bool m_externalFlow = false;          ///< particles in and out are the domain decomposition's
    Communicator* m_fieldComm = nullptr;  ///< the field stage's ranks (setFieldCommunicator)
    LawTable m_baseLaws;                  ///< the laws of t = 0
    Real m_scale = 1;                     ///< global size scale s of the radius column and corners
    Real m_scaleAtRebuild = 1;            ///< s at the last neighbour rebuild
    std::unique_ptr<fluid::FieldSeries> m_field;
    FluidStats m_fluidStats;
    VoidageScratch m_voidage;
    CellBins m_attractionCells;
    std::string m_fieldError;
};

}  // namespace granulab::dem
