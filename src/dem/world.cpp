// SPDX-License-Identifier: MIT
// DEM world: the step pipeline, energies and the checkpoint state.
#include "dem/world.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "core/binary_io.hpp"
#include "core/idle_cores.hpp"
#include "core/parallel.hpp"

namespace granulab::dem {

const char* stageName(Stage s) noexcept {
    switch (s) {
        case Stage::Predict:
            return "predict";
        case Stage::Neighbors:
            return "neighbors";
        case Stage::Forces:
            return "forces";
        case Stage::Fluid:
            return "fluid";
        case Stage::Correct:
            return "correct";
        case Stage::Updaters:
            return "updaters";
        case Stage::Count:
            break;
    }
    return "?";
}

World::World(WorldConfig config, model::ParticleStore store, model::WallSet walls, LawTable laws,
             model::ShapePool shapes)
    : m_config(std::move(config)),
      m_store(std::move(store)),
      m_walls(std::move(walls)),
      m_laws(std::move(laws)),
      m_pool(std::move(shapes)),
      m_broad(makeBroadPhase(m_config.broadPhase)),
      m_integrator(makeIntegrator(m_config.integrator)),
      m_wallForce(m_walls.walls.size()),
      m_flow(m_config.flow),
      m_baseLaws(m_laws) {
    if (!m_broad) throw std::invalid_argument("unknown broad phase " + m_config.broadPhase);
    if (!m_integrator) throw std::invalid_argument("unknown integrator " + m_config.integrator.name);
    m_config.threads = std::max(1, m_config.threads);
    if (m_config.autoThreads)
        m_governor.setAutomatic(m_config.threads);
    else
        m_governor.setExplicit(m_config.threads);
    {  // the automatic count asks how many cores are idle before it tries a larger team
        auto idle = std::make_shared<IdleCores>();
        m_governor.setIdleProbe({[idle] { idle->start(); }, [idle] { return idle->idleSinceStart(); }});
    }
    m_minRadius = m_store.size() ? *std::min_element(m_store.radius.begin(), m_store.radius.end()) : 1e300;
    m_shapes.anyPolygon = m_pool.size() > 0;
    for (const ParticleId id : m_store.id) m_nextId = std::max<ParticleId>(m_nextId, id + 1);
    for (const Real r : m_store.radius) m_maxRadius = std::max(m_maxRadius, r);
    // The series owns the field source from here on (the config keeps the force parameters).
    if (m_config.fluid) m_field = std::make_unique<fluid::FieldSeries>(std::move(m_config.fluid->source));
}

void World::updateTeam() {
    if (m_governor.automatic()) {
        const bool polygons = m_shapes.anyPolygon;
        const std::size_t perThread = m_particlesPerThread > 0 ? m_particlesPerThread
                                      : polygons               ? kPolygonsPerThread
                                                               : kParticlesPerThread;
        const std::size_t n = m_store.size();
        const std::size_t useful = std::max<std::size_t>(1, n / perThread);
        m_governor.setWorkLimit(
            static_cast<int>(std::min<std::size_t>(useful, 1024)),
            fmt::format("{} particles are too few for 2 threads (the threaded size is {} {} per thread)", n,
                        perThread, polygons ? "particles with polygons among them" : "particles"));
    }
    applyTeam();
}

void World::setThreads(int threads) {
    if (threads > 0) {
        m_config.threads = threads;
        m_config.autoThreads = false;
        m_governor.setExplicit(threads);
    } else {
        m_config.threads = defaultThreads();
        m_config.autoThreads = true;
        m_governor.setAutomatic(m_config.threads);
    }
    updateTeam();
}

void World::applyTeam() noexcept {
    const int n = team();
    m_forceWork.threads = n;
    m_broad->setThreads(n);
    m_integrator->setThreads(n);
}

Real World::totalMass() const noexcept {
    Real m = 0;
    for (const Real mi : m_store.mass) m += mi;
    return m;
}

void World::applySizeScale(Real t) noexcept {
    const Real target = dem::sizeScale(*m_config.sizeCycle, t);
    if (target == m_scale) return;
    const Real ratio = target / m_scale;
    const Real ratio2 = ratio * ratio;
    for (Real& r : m_store.radius) r *= ratio;
    for (Real& ii : m_store.invInertia) ii /= ratio2;
    m_minRadius *= ratio;
    m_maxRadius *= ratio;
    m_scale = target;
    m_shapes.scale = target;
}

void World::applyLawChanges() {
    const auto& changes = m_config.lawChanges;
    bool changed = false;
    while (m_lawChangesDone < changes.size() && changes[m_lawChangesDone].step <= m_step) {
        m_laws = changes[m_lawChangesDone++].laws;
        changed = true;
    }
    if (changed) m_lawRebuildDue = true;  // the contact buckets follow the laws' forms
}

void World::exchangeParticles() {
    const Real t = time();
    const std::vector<std::uint32_t> leaving = m_flow.leaving(m_store, t);
    std::vector<NewParticle> entering =
        m_flow.entering(m_store, m_walls, m_pool, t, m_config.dt, gravityAt(t));
    if (leaving.empty() && entering.empty()) return;
    std::vector<std::uint32_t> oldToNew;
    const std::size_t before = m_store.size() - leaving.size();  // first slot of the new particles
    if (!leaving.empty()) {
        const std::size_t n = m_store.size();
        oldToNew.assign(n, kRemovedSlot);
        std::vector<std::uint32_t> keep;
        keep.reserve(n - leaving.size());
        std::size_t next = 0;
        for (std::uint32_t i = 0; i < n; ++i) {
            if (next < leaving.size() && leaving[next] == i) {
                ++next;
                continue;
            }
            oldToNew[i] = static_cast<std::uint32_t>(keep.size());
            keep.push_back(i);
        }
        m_store.keep(keep);
        m_integrator->permute(keep);
        auto& springs = m_config.springs;  // a spring whose particle left is gone with it
        springs.erase(std::remove_if(springs.begin(), springs.end(),
                                     [&](const PullSpring& sp) { return oldToNew[sp.slot] == kRemovedSlot; }),
                      springs.end());
        for (auto& sp : springs) sp.slot = oldToNew[sp.slot];
        m_broad->slotsRenumbered();
    }
    const Vec2 g = gravityAt(t);
    for (const NewParticle& p : entering) {  // at the current size scale s: radius s r, inertia s^2 I
        const std::size_t k =
            m_store.add(m_nextId++, p.position, p.velocity, p.angle, p.omega, p.radius * m_scale, p.mass,
                        p.inertia * m_scale * m_scale, p.material, p.shape);
        // Until the next force evaluation the new particle feels its weight (it touches nothing).
        m_store.fx[k] = p.mass * g.x;
        m_store.fy[k] = p.mass * g.y;
        if (p.shape != model::kDiskShape) m_shapes.anyPolygon = true;
    }
    m_flow.bookInserted(entering);
    m_minRadius = m_store.size() ? *std::min_element(m_store.radius.begin(), m_store.radius.end()) : 1e300;
    for (const NewParticle& p : entering) m_maxRadius = std::max(m_maxRadius, p.radius * m_scale);
    // No broad phase: removal renumbers the lists, new particles get their candidates directly.
    if (!oldToNew.empty()) m_list.removeSlots(oldToNew);
    if (!entering.empty())
        m_list.appendParticles(m_store, m_walls, before, m_config.skin, m_laws,
                               !m_integrator->singleEvaluation());
    m_flow.refreshCandidates(m_store, m_maxRadius, m_config.skin);
    updateTeam();
}

void World::evaluateForces(const BodyForces& body, const DriftVelocities& drift, bool trial) {
    m_shapes.pool = &m_pool;
    ContactLog* log = nullptr;
    if (m_recordContacts) {
        log = &m_contactLog;
        log->step = m_step;
    }
    computeForces(m_store, m_walls, m_list, m_laws, body, drift, m_config.dt, trial, m_stats, m_wallForce,
                  m_shapes, log, &m_forceWork);
}

void World::evaluateFieldForces(const BodyForces& body) {
    const FieldRanks ranks{m_fieldComm, std::min<std::size_t>(m_list.ownedEnd, m_store.size())};
    if (m_field)
        addFluidForces(m_store, *m_field, m_config.fluid->forces, body.gravity, m_fluidStats, m_voidage,
                       ranks);
    if (m_config.attraction)
        addAttraction(m_store, m_config.attraction->constant, m_config.attraction->cutoff, m_attractionCells,
                      ranks);
}

BodyForces World::bodyForcesAt(std::int64_t step) const noexcept {
    BodyForces b;
    b.gravity = gravityAt(static_cast<Real>(step) * m_config.dt);
    b.overlapGuard = m_config.overlapGuard;
    b.springs = m_config.springs.empty() ? nullptr : &m_config.springs;
    b.time = static_cast<Real>(step) * m_config.dt;
    b.weight = m_config.weight;
    b.particleContacts = m_config.particleContacts;
    b.wallContacts = m_config.wallContacts;
    for (const auto& w : m_config.damping)
        if (step >= w.fromStep && step < w.toStep) {
            b.gamma += w.gamma;
            b.gammaRotation += w.gammaRotation;
        }
    return b;
}

void World::rebuildNeighbors() {
    std::vector<std::uint32_t> oldToNew;
    const int every = m_config.sortEveryRebuilds;
    if (every > 0 && m_list.builds % static_cast<std::uint64_t>(every) == 0) {
        const auto order = m_broad->spatialOrder(m_store);
        if (!order.empty()) {
            m_store.permute(order);
            m_integrator->permute(order);
            oldToNew.resize(order.size());
            for (std::size_t k = 0; k < order.size(); ++k) oldToNew[order[k]] = static_cast<std::uint32_t>(k);
            for (auto& sp : m_config.springs) sp.slot = oldToNew[sp.slot];
            m_broad->slotsRenumbered();
        }
    }
    m_scaleAtRebuild = m_scale;
    m_lawRebuildDue = false;
    updateTeam();
    m_list.rebuild(m_store, m_walls, m_config.skin, time(), *m_broad, m_laws, oldToNew,
                   !m_integrator->singleEvaluation(), m_forceWork.threads);
    m_travelBound = 0;  // x0 = the positions now
    if (m_flow.active()) m_flow.refreshCandidates(m_store, m_maxRadius, m_config.skin);
}

void World::initialize() {
    m_walls.place(time());
    if (m_config.sizeCycle) applySizeScale(time());
    rebuildNeighbors();
    if (m_field) m_field->update(time());
    // A gc2d restart: the remembered contacts (slots of construction) before the set-up evaluation,
    // so that its forces hold the springs, and again after it, since the evaluation's bookkeeping
    // (Old_Area = the area now; a new contact's area) must not replace the state of the step that
    // wrote them (the areas of that step's predicted positions; pairs not listed had none).
    const bool restart = !m_config.rememberedContacts.empty();
    std::vector<RememberedContact> remembered = rememberedInSlots();
    if (restart) restoreContacts(remembered);
    // Set-up evaluation: nothing has moved yet, so no tangential displacement (drift = none).
    const BodyForces body = bodyForcesAt(m_step);
    evaluateForces(body, DriftVelocities{}, false);
    evaluateFieldForces(body);
    if (restart) {
        for (ContactList* l : {&m_list.pairs, &m_list.wallPairs}) {  // what the gci does not list: new
            std::fill(l->xi.begin(), l->xi.end(), 0.0);
            std::fill(l->areaOld.begin(), l->areaOld.end(), 0.0);
        }
        m_unrestoredContacts = m_config.rememberedContacts.size() - restoreContacts(remembered);
        m_config.rememberedContacts.clear();
    }
}

std::vector<RememberedContact> World::rememberedInSlots() const {
    std::vector<RememberedContact> contacts;
    if (m_config.rememberedContacts.empty()) return contacts;
    std::vector<std::uint32_t> slotOf(m_store.size());
    for (std::uint32_t k = 0; k < m_store.size(); ++k)
        if (m_store.id[k] < slotOf.size()) slotOf[m_store.id[k]] = k;  // ids are construction slots
    for (RememberedContact c : m_config.rememberedContacts) {
        if (c.unknown || c.a >= slotOf.size() || (!c.wall && c.b >= slotOf.size())) continue;
        c.a = slotOf[c.a];
        if (!c.wall) c.b = slotOf[c.b];
        contacts.push_back(c);
    }
    return contacts;
}

std::uint32_t World::step() {
    std::uint32_t status = beginStep();
    if (status & kStepFieldFailed) return status;
    {  // 2+3+5 neighbour check, broad phase and history transfer when needed
        ScopedStage t(m_timers, Stage::Neighbors);
        if (neighborsStale()) rebuildNeighbors();
    }
    return status | finishStep();
}

std::uint32_t World::beginStep() {
    m_stepStart = wallSeconds();
    const Real dt = m_config.dt;
    std::uint32_t status = kStepOk;
    Real maxSpeed;
    {  // 1 predict. reads: x, v, f; writes: x, v (half step)
        ScopedStage t(m_timers, Stage::Predict);
        // The threads integrate the slots of their last force tiles (parallelSlots); set here, at
        // every step, so that the pointer follows the workspace wherever the world is.
        m_integrator->setSlotCuts(&m_forceWork.slotCuts);
        maxSpeed = m_integrator->predict(m_store, dt);
    }
    ++m_step;
    m_travelBound +=
        m_integrator->speedBoundsDisplacement() ? maxSpeed * dt : std::numeric_limits<Real>::infinity();
    {  // 8 scene updaters (walls move and laws change before the forces of the new time)
        ScopedStage t(m_timers, Stage::Updaters);
        m_walls.advance(time(), dt, m_wallForce);
        if (m_config.sizeCycle) applySizeScale(time());
        if (m_lawChangesDone < m_config.lawChanges.size()) applyLawChanges();
        if (m_field) {
            try {  // the field of the new time (a file read when the next one is due)
                m_field->update(time());
            } catch (const std::exception& e) {
                m_fieldError = e.what();
                return status | kStepFieldFailed;
            }
        }
    }
    if (!std::isfinite(maxSpeed)) status |= kStepNonFinite;
    // A particle, or a wall sweeping through particles, moving half a radius in one step tunnels.
    if ((maxSpeed + m_walls.maxSpeedBetween(time() - dt, time())) * dt > 0.5 * m_minRadius)
        status |= kStepTunnelling;
    return status;
}

bool World::neighborsStale() const noexcept {
    if (m_lawRebuildDue) return true;
    // Walls sweeping towards particles, and particles grown since the rebuild, use up the skin.
    const Real growth = 2 * m_maxRadius * std::abs(m_scale - m_scaleAtRebuild) / m_scale;
    const Real wallTravel =
        m_walls.maxSpeedBetween(m_list.wallTime0, time()) * (time() - m_list.wallTime0) + growth;
    // No particle can have moved farther than m_travelBound: with a margin of 1 % of the limit
    // (far above the round-off of the positions' sums) the scan below would find none beyond it.
    const Real half = 0.5 * m_config.skin - wallTravel;
    if (m_list.x0.size() == m_store.size() && half > 0 && m_travelBound <= 0.99 * half) return false;
    return m_list.needsRebuild(m_store, m_config.skin, wallTravel, m_forceWork.threads,
                               &m_forceWork.slotCuts);
}

void World::correctSlotsOf(void* world, std::size_t begin, std::size_t end) noexcept {
    auto& w = *static_cast<World*>(world);
    w.m_integrator->correctSlots(w.m_store, w.m_config.dt, begin, end);
}

std::uint32_t World::finishStep(IterationLink* link) {
    std::uint32_t status = kStepOk;
    const Real dt = m_config.dt;
    // 4+6+7: force evaluation(s) at the trial state and correction, until the integrator accepts.
    // Iterating integrators see trial springs; the accepted ones are committed once per step.
    const bool trial = !m_integrator->singleEvaluation();
    // An elementwise correction runs inside the force stage, each thread on its own tiles' slots as
    // soon as their forces are complete (no parallel region of its own; the stage timers count it
    // under forces). Field forces and attraction are added after the contact forces: not then.
    const bool fused = m_integrator->correctsBySlots() && !trial && !m_field && !m_config.attraction;
    const BodyForces body = bodyForcesAt(m_step);
    for (int iteration = 0;; ++iteration) {
        {  // 4+6 narrow phase + contact laws + body forces. reads: x, v, omega; writes: f, torque, history
            ScopedStage t(m_timers, Stage::Forces);
            if (fused) {
                m_forceWork.finishSlots = &World::correctSlotsOf;
                m_forceWork.finishContext = this;
            }
            evaluateForces(body, m_integrator->driftVelocities(), trial);
            m_forceWork.finishSlots = nullptr;
        }
        if (m_field || m_config.attraction) {  // 6 fluid forces and attraction
            ScopedStage t(m_timers, Stage::Fluid);
            evaluateFieldForces(body);
        }
        ++m_forceEvaluations;
        bool accepted = true;
        if (!fused) {  // 7 correct. reads: f, torque; writes: x, v, omega
            ScopedStage t(m_timers, Stage::Correct);
            accepted = m_integrator->correct(m_store, dt, iteration);
        }
        if (link && trial) accepted = link->agree(accepted);
        if (accepted) break;
    }
    if (trial) m_list.commitHistory();
    if (m_stats.maxRelativeOverlap >= 1.0) status |= kStepDeepOverlap;
    if (m_flow.active() && !m_externalFlow) {  // 8 particles leave and enter (the only place N changes)
        ScopedStage t(m_timers, Stage::Updaters);
        exchangeParticles();
    }
    // The automatic thread count follows the step's wall time (the results do not depend on it).
    if (m_governor.stepDone(wallSeconds() - m_stepStart)) applyTeam();
    return status;
}

void World::replaceParticles(model::ParticleStore store, const std::vector<Real>& integratorRows,
                             const std::vector<PairHistory>& pairHistory,
                             const std::vector<PairHistory>& wallHistory, std::size_t ownedEnd,
                             bool countAsBuild, bool outputCopy) {
    const std::uint64_t builds = m_list.builds;
    m_store = std::move(store);
    const std::size_t n = m_store.size();
    if (StateColumns* state = m_integrator->state()) {
        const std::size_t k = state->columns.size();
        state->resize(n);
        for (std::size_t i = 0; i < n; ++i) state->setRow(i, integratorRows.data() + i * k);
    }
    m_broad->slotsRenumbered();
    for (auto& sp : m_config.springs) {  // a spring pulls on the rank that owns its particle
        sp.slot = kRemovedSlot;
        for (std::uint32_t k = 0; k < std::min(ownedEnd, n); ++k)
            if (m_store.id[k] == sp.id) sp.slot = k;
    }
    m_list.ownedEnd = static_cast<std::uint32_t>(std::min<std::size_t>(ownedEnd, 0xFFFFFFFFu));
    m_scaleAtRebuild = m_scale;
    m_lawRebuildDue = false;
    updateTeam();
    m_list.rebuildWith(m_store, m_walls, m_config.skin, time(), *m_broad, m_laws, pairHistory, wallHistory,
                       outputCopy || !m_integrator->singleEvaluation(), m_forceWork.threads);
    m_travelBound = 0;  // x0 = the positions now
    if (!countAsBuild) m_list.builds = builds;
    if (m_flow.active()) m_flow.refreshCandidates(m_store, m_maxRadius, m_config.skin, ownedEnd);
}

ParticleId World::admitParticles(const std::vector<NewParticle>& entering) {
    const ParticleId first = m_nextId;
    m_nextId += static_cast<ParticleId>(entering.size());
    m_flow.bookInserted(entering);
    for (const NewParticle& p : entering) {
        m_maxRadius = std::max(m_maxRadius, p.radius * m_scale);
        m_minRadius = std::min(m_minRadius, p.radius * m_scale);
        if (p.shape != model::kDiskShape) m_shapes.anyPolygon = true;
    }
    return first;
}

void World::adoptClock(const World& local) {
    m_step = local.m_step;
    m_forceEvaluations = local.m_forceEvaluations;
    m_walls = local.m_walls;
    m_scale = local.m_scale;
    m_shapes.scale = local.m_shapes.scale;
    m_scaleAtRebuild = local.m_scaleAtRebuild;
    m_minRadius = local.m_minRadius;
    m_maxRadius = local.m_maxRadius;
    m_laws = local.m_laws;
    m_lawChangesDone = local.m_lawChangesDone;
    m_list.builds = local.m_list.builds;
    m_timers = local.m_timers;
    m_wallForce = local.m_wallForce;
    m_flow = local.m_flow;
    m_pool = local.m_pool;
    m_nextId = local.m_nextId;
    m_shapes.anyPolygon = local.m_shapes.anyPolygon;
    std::stringstream flags;  // the integrator's flags (gear: started); its columns follow the particles
    local.m_integrator->save(flags);
    m_integrator->load(flags, local.m_store.size());
}

void World::evaluateForOutput() {
    if (m_list.pairs.xiTrial.size() != m_list.pairs.size() ||
        m_list.wallPairs.xiTrial.size() != m_list.wallPairs.size())
        return;  // the lists were built without trial columns: nothing may be written
    const BodyForces body = bodyForcesAt(m_step);
    const std::vector<Real> fx = m_store.fx, fy = m_store.fy, torque = m_store.torque;
    const std::vector<Vec2> wallForce = m_wallForce;
    // Closest features are updated in place: keep those of the run (a checkpoint follows).
    const std::vector<geom::FeatureCache> pairFeatures = m_list.pairs.features,
                                          wallFeatures = m_list.wallPairs.features;
    evaluateForces(body, DriftVelocities{}, true);  // trial columns: the accepted history stays
    if (m_field) m_field->update(time());           // the fluid statistics of the whole set
    evaluateFieldForces(body);
    m_store.fx = fx;
    m_store.fy = fy;
    m_store.torque = torque;
    m_wallForce = wallForce;
    m_list.pairs.features = pairFeatures;
    m_list.wallPairs.features = wallFeatures;
}

Energies World::energies() const noexcept {
    const auto& s = m_store;
    const Vec2 g = m_config.weight ? gravityAt(time()) : Vec2{};
    const auto sumSlots = [&](std::size_t begin, std::size_t end) {
        Energies e;
        for (std::size_t i = begin; i < end; ++i) {
            e.kinetic += 0.5 * s.mass[i] * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
            const Real inertia = s.invInertia[i] > 0 ? 1.0 / s.invInertia[i] : 0.0;
            e.rotational += 0.5 * inertia * s.omega[i] * s.omega[i];
            e.potential -= s.mass[i] * (g.x * s.x[i] + g.y * s.y[i]);
        }
        return e;
    };
    Energies e;
    const SlotTiles& tiles = m_list.tiles;
    if (tiles.slots == s.size() && tiles.count > 1) {  // per-tile sums added in tile order
        std::vector<Energies> partial(tiles.count);
        parallelFor(m_forceWork.threads, tiles.count, [&](std::size_t t) {
            partial[t] = sumSlots(tiles.begin(static_cast<std::uint32_t>(t)),
                                  tiles.end(static_cast<std::uint32_t>(t)));
        });
        for (const Energies& p : partial) {
            e.kinetic += p.kinetic;
            e.rotational += p.rotational;
            e.potential += p.potential;
        }
    } else {
        e = sumSlots(0, s.size());
    }
    e.elastic = contactEnergy(m_store, m_walls, m_list, m_laws, m_pool, m_scale, m_forceWork.threads);
    return e;
}

Vec2 World::momentum() const noexcept {
    Vec2 p;
    for (std::size_t i = 0; i < m_store.size(); ++i)
        p += Vec2{m_store.vx[i], m_store.vy[i]} * m_store.mass[i];
    return p;
}

std::size_t World::memoryBytes() const noexcept {
    return m_store.size() * model::ParticleStore::kBytesPerParticle + (m_field ? m_field->memoryBytes() : 0) +
           m_list.memoryBytes() + m_broad->memoryBytes() + m_integrator->memoryBytes() +
           m_pool.memoryBytes() + m_shapes.world.capacity() * sizeof(Vec2) + m_shapes.first.capacity() * 4 +
           m_forceWork.deferred.capacity() * sizeof(DeferredForce) +
           m_forceWork.counters.capacity() * sizeof(TileCounters) +
           m_forceWork.tileWallForce.capacity() * sizeof(Vec2);
}

namespace {
// "GNLBDME3": contact lists grouped by slot tiles (version 2: by law form only).
constexpr std::uint64_t kStateMagic = 0x33454d44424c4e47ULL;

void writeList(std::ostream& os, const ContactList& l) {
    writeVector(os, l.first);
    writeVector(os, l.second);
    writeVector(os, l.xi);
    writeVector(os, l.zeta);
    writeVector(os, l.areaOld);
    writeVector(os, l.features);
    writeVector(os, l.bucketStart);
}
void readList(std::istream& is, ContactList& l) {
    readVector(is, l.first);
    readVector(is, l.second);
    readVector(is, l.xi);
    readVector(is, l.zeta);
    readVector(is, l.areaOld);
    readVector(is, l.features);
    readVector(is, l.bucketStart);
}
}  // namespace

std::size_t World::restoreContacts(const std::vector<RememberedContact>& contacts) {
    std::size_t found = 0;
    const auto indexOf = [](const ContactList& l) {
        std::unordered_map<std::uint64_t, std::size_t> index;
        for (std::size_t k = 0; k < l.size(); ++k) index.emplace(pairKey(l.first[k], l.second[k]), k);
        return index;
    };
    const auto pairIndex = indexOf(m_list.pairs), wallIndex = indexOf(m_list.wallPairs);
    const auto set = [&](ContactList& l, const std::unordered_map<std::uint64_t, std::size_t>& index,
                         std::uint32_t first, std::uint32_t second, const RememberedContact& c) {
        const auto it = index.find(pairKey(first, second));
        if (it == index.end()) return;
        l.xi[it->second] = c.xi;
        if (!l.areaOld.empty()) l.areaOld[it->second] = c.areaOld;
        ++found;
    };
    for (const RememberedContact& c : contacts) {
        if (c.wall) {
            if (c.b < m_walls.walls.size())
                set(m_list.wallPairs, wallIndex, c.a, m_walls.walls[c.b].firstSegment, c);
        } else {  // a pair is kept as (lower slot, higher slot); xi is the same either way round
            set(m_list.pairs, pairIndex, std::min(c.a, c.b), std::max(c.a, c.b), c);
        }
    }
    return found;
}

std::vector<RememberedContact> World::rememberedContacts() const {
    std::vector<RememberedContact> out;
    const auto collect = [&](const ContactList& l, bool wall) {
        for (std::size_t k = 0; k < l.size(); ++k) {
            const Real area = l.areaOld.empty() ? 0 : l.areaOld[k];
            if (l.xi[k] == 0 && area == 0) continue;
            const std::uint32_t b = wall ? m_walls.segments[l.second[k]].wall : l.second[k];
            out.push_back({l.first[k], b, wall, false, l.xi[k], area});
        }
    };
    collect(m_list.pairs, false);
    collect(m_list.wallPairs, true);
    return out;
}

void World::saveState(std::ostream& os) const {
    writePod(os, kStateMagic);
    writePod<std::int64_t>(os, m_step);
    m_store.save(os);
    writeList(os, m_list.pairs);
    writeList(os, m_list.wallPairs);
    writeVector(os, m_list.x0);
    writeVector(os, m_list.y0);
    writePod(os, m_list.wallTime0);
    writePod(os, m_list.builds);
    writePod(os, m_forceEvaluations);
    m_integrator->save(os);
    m_walls.save(os);
    m_pool.save(os);
    m_flow.save(os);
    writePod<std::uint64_t>(os, m_nextId);
    writePod(os, m_scale);
    writePod(os, m_scaleAtRebuild);
}

void World::loadState(std::istream& is) {
    m_travelBound = std::numeric_limits<Real>::infinity();  // not in the file: the scan decides
    const auto magic = readPod<std::uint64_t>(is);
    if (magic == 0x32454d44424c4e47ULL)
        throw std::runtime_error(
            "a DEM checkpoint of an earlier granulab (before the threaded step); "
            "rerun the scene from the start");
    if (magic != kStateMagic) throw std::runtime_error("not a granulab DEM checkpoint");
    m_step = readPod<std::int64_t>(is);
    const std::size_t particles = m_store.size();
    m_store.load(is);
    const auto& s = m_store;
    // With sources and outlets the count changes during a run; otherwise it is the scene's.
    if (s.size() != particles && !m_flow.active())
        throw std::runtime_error("checkpoint corrupt (particle count)");
    for (const auto* col : {&s.x, &s.y, &s.vx, &s.vy, &s.angle, &s.omega, &s.radius, &s.mass, &s.invMass})
        if (!std::all_of(col->begin(), col->end(), [](Real v) { return std::isfinite(v); }))
            throw std::runtime_error(
                "checkpoint corrupt (a particle position, velocity or mass is not finite)");
    readList(is, m_list.pairs);
    readList(is, m_list.wallPairs);
    // Slots and segments index the arrays of the step: a damaged one must not reach it.
    const auto indicesFit = [](const ContactList& l, std::size_t firstEnd, std::size_t secondEnd) {
        return l.first.size() == l.second.size() &&
               std::all_of(l.first.begin(), l.first.end(), [&](std::uint32_t k) { return k < firstEnd; }) &&
               std::all_of(l.second.begin(), l.second.end(), [&](std::uint32_t k) { return k < secondEnd; });
    };
    if (!indicesFit(m_list.pairs, s.size(), s.size()) ||
        !indicesFit(m_list.wallPairs, s.size(), m_walls.segments.size()))
        throw std::runtime_error("checkpoint corrupt (contact list)");
    readVector(is, m_list.x0);
    readVector(is, m_list.y0);
    m_list.wallTime0 = readPod<Real>(is);
    m_list.builds = readPod<std::uint64_t>(is);
    m_forceEvaluations = readPod<std::uint64_t>(is);
    m_integrator->load(is, s.size());
    if (!m_integrator->singleEvaluation()) {
        for (auto* l : {&m_list.pairs, &m_list.wallPairs}) {
            l->xiTrial.assign(l->size(), 0.0);
            l->zetaTrial.assign(l->zeta.size(), 0.0);
            l->areaOldTrial.assign(l->areaOld.size(), 0.0);
        }
    }
    m_walls.load(is, time());
    m_pool.load(is);
    m_flow.load(is);
    m_nextId = readPod<std::uint64_t>(is);
    m_scale = readPod<Real>(is);
    m_scaleAtRebuild = readPod<Real>(is);
    if (!(m_scale > 0) || !std::isfinite(m_scale) || !(m_scaleAtRebuild > 0))
        throw std::runtime_error("checkpoint corrupt (size scale)");
    m_shapes.scale = m_scale;
    for (std::size_t k = 0; k < s.size(); ++k)
        if (s.material[k] >= m_laws.materialCount() ||
            (s.shape[k] != model::kDiskShape && s.shape[k] >= m_pool.size()) || !(s.radius[k] > 0) ||
            s.id[k] >= m_nextId)
            throw std::runtime_error("checkpoint corrupt (particle material, shape, radius or id)");
    m_shapes.anyPolygon = m_pool.size() > 0;
    auto& springs = m_config.springs;  // slots of the restored store; a spring's particle may have left
    for (auto& sp : springs) {
        sp.slot = kRemovedSlot;
        for (std::uint32_t k = 0; k < s.size(); ++k)
            if (s.id[k] == sp.id) sp.slot = k;
    }
    springs.erase(std::remove_if(springs.begin(), springs.end(),
                                 [](const PullSpring& sp) { return sp.slot == kRemovedSlot; }),
                  springs.end());
    m_laws = m_baseLaws;  // the laws in force at the restored step
    m_lawChangesDone = 0;
    while (m_lawChangesDone < m_config.lawChanges.size() &&
           m_config.lawChanges[m_lawChangesDone].step <= m_step)
        m_laws = m_config.lawChanges[m_lawChangesDone++].laws;
    if (!m_list.restoreLayout(s.size(), m_laws))
        throw std::runtime_error("checkpoint corrupt (contact list tiles)");
    m_minRadius = s.size() ? *std::min_element(s.radius.begin(), s.radius.end()) : 1e300;
    for (const Real r : s.radius) m_maxRadius = std::max(m_maxRadius, r);
    if (m_flow.active()) m_flow.refreshCandidates(m_store, m_maxRadius, m_config.skin);
    // Wall forces of the restored step are re-derived at the next step; stats start empty.
    m_stats = ForceStats{};
    updateTeam();
}

}  // namespace granulab::dem
