// SPDX-License-Identifier: MIT
// The parallel event-driven engine (edmd spec 3.1-3.9): domain layout from the Morton blocks,
// sections and steps, rollback, careful re-execution, load balancing, gathering. The protocol
// and its choices for the open points of spec 9 item 12 are in docs/physics/edmd-parallel.md.
#include "edmd/parallel/parallel_engine.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "core/interrupt.hpp"
#include "core/timer.hpp"

namespace granulab::edmd {

namespace {
constexpr int kTagStep = 11;
constexpr int kTagCareful = 12;
constexpr int kTagAnnounce = 13;

template <class T>
void append(ByteBuffer& buffer, const T& value) {
    const auto at = buffer.size();
    buffer.resize(at + sizeof(T));
    std::memcpy(buffer.data() + at, &value, sizeof(T));
}

template <class T>
T readAt(const ByteBuffer& buffer, std::size_t at) {
    if (at + sizeof(T) > buffer.size()) throw std::runtime_error("edmd parallel: truncated message");
    T value;
    std::memcpy(&value, buffer.data() + at, sizeof(T));
    return value;
}

ByteBuffer packRecords(const std::vector<ParticleRecord>& records) {
    return packPod(std::span<const ParticleRecord>(records));
}

/// Appends the records held in b from byte `from` on to `out`.
void unpackRecords(const ByteBuffer& b, std::vector<ParticleRecord>& out, std::size_t from = 0) {
    unpackPod(b, out, from);
}

double elapsedSince(double t0) {
    return wallSeconds() - t0;
}
}  // namespace

template <int D>
ParallelEngine<D>::ParallelEngine(Communicator& comm, EngineConfig config, ParallelConfig parallel,
                                  const std::vector<V>& x, const std::vector<V>& v,
                                  const std::vector<Real>& radius, const std::vector<Real>& mass)
    : m_comm(comm), m_config(config), m_parallel(parallel) {
    const std::size_t n = x.size();
    if (v.size() != n || radius.size() != n || mass.size() != n)
        throw std::invalid_argument(
            "edmd::ParallelEngine: position, velocity, radius and mass counts differ");
    std::vector<ParticleRecord> all(n);
    for (std::size_t i = 0; i < n; ++i) {
        ParticleRecord& r = all[i];
        r.id = static_cast<std::uint32_t>(i);
        for (int d = 0; d < D; ++d) {
            r.x[d] = x[i][d];
            r.v[d] = v[i][d];
        }
        r.radius0 = radius[i];
        r.mass = mass[i];
        r.eventKind = 4;  // predicted at construction, at time 0, like the serial engine
    }
    EngineGlobals g;
    g.restitution = config.restitution;
    g.wallRestitution = config.wallRestitution;
    g.tc = config.tc;
    g.growthRate = config.growthRate;
    start(g, std::move(all));
}

template <int D>
ParallelEngine<D>::ParallelEngine(Communicator& comm, EngineConfig config, ParallelConfig parallel,
                                  const EngineGlobals& globals, std::vector<ParticleRecord> records)
    : m_comm(comm), m_config(config), m_parallel(parallel) {
    // The summed statistics stay on the root; the other ranks start their shares at zero.
    EngineGlobals g = globals;
    if (!comm.root()) {
        g.stats = {};
        g.virial = g.dissipated = 0;
    }
    start(g, std::move(records));
}

template <int D>
ParallelEngine<D>::~ParallelEngine() = default;

template <int D>
void ParallelEngine<D>::start(const EngineGlobals& globals, std::vector<ParticleRecord> all) {
    if (m_config.growthRate != 0 || globals.growthRate != 0)
        throw std::invalid_argument("edmd::ParallelEngine: growing spheres run on the serial engine only");
    m_globalCount = static_cast<std::uint32_t>(all.size());
    for (auto& r : all)
        if (r.id >= all.size())
            throw std::invalid_argument("edmd::ParallelEngine: particle ids must be 0 .. N-1");
    m_cells = gridFor(m_config, all);
    std::array<int, D> cells;
    for (int d = 0; d < D; ++d) cells[d] = m_cells[d];
    m_morton = std::make_unique<MortonGrid<D>>(cells);
    const auto weight = [this](std::uint64_t s, int k) {
        return static_cast<double>(m_morton->realCellsIn(s, k));
    };
    m_map = std::make_unique<DomainMap>(DomainMap::initial(m_comm.size(), m_morton->totalBits(), weight));
    // Cells of records that carry no cell yet (the initial state) from their positions.
    for (auto& r : all)
        if (r.eventKind == 4 && r.tst == globals.now)
            for (int d = 0; d < D; ++d)
                r.cell[d] = cellCoordinate(r.x[d], r.v[d], m_cells[d] / m_config.box[d],
                                           m_config.box[d] / m_cells[d], m_cells[d]);
    m_barrier = globals.now;
    buildLayout();
    distribute(std::move(all), true, globals);
    // First interval: ten mean times to a particle's next event (about ten events per particle).
    std::vector<ParticleRecord> mine = m_kernel->records(true);
    std::array<double, 2> sum{0, 0};
    for (const auto& r : mine)
        if (r.eventTime < kNoEvent) {
            sum[0] += r.eventTime - m_barrier;
            sum[1] += 1;
        }
    m_comm.allSum(sum);
    m_interval = m_parallel.initialSyncInterval > 0 ? m_parallel.initialSyncInterval
                                                    : (sum[1] > 0 ? 10 * sum[0] / sum[1] : 1.0);
    if (!(m_interval > 0)) m_interval = 1.0;
    m_interval = std::min(m_interval, m_parallel.maxSyncInterval);
    commitBarrier(m_barrier);
}

template <int D>
std::array<int, 3> ParallelEngine<D>::gridFor(EngineConfig config,
                                              const std::vector<ParticleRecord>& records) {
    Real amax = 0;
    for (const auto& r : records) amax = std::max(amax, r.radius0);
    return chooseCellGrid<D>(config, static_cast<std::uint32_t>(records.size()), amax);
}

template <int D>
std::uint64_t ParallelEngine<D>::mortonOf(const std::array<int, 3>& c) const noexcept {
    std::array<int, D> cd;
    for (int d = 0; d < D; ++d) cd[d] = c[d];
    return m_morton->indexOfCell(cd);
}

template <int D>
int ParallelEngine<D>::ownerOf(const std::array<int, 3>& c) const noexcept {
    const std::uint32_t w = m_window.indexOf<D>(c);
    return w != CellWindow::kOutside ? m_owner[w] : m_map->owner(mortonOf(c));
}

template <int D>
void ParallelEngine<D>::recipients(const std::array<std::uint16_t, 3>& cell, std::vector<int>& out) const {
    // The ranks that own a cell of the 3^D neighbourhood hold this cell as their own or in their
    // halo; every change of a particle in it goes to them.
    m_window.forEachInGridAround<D>(cell, m_config.periodic, [&](const std::array<int, 3>& c) {
        const int r = ownerOf(c);
        if (r != m_comm.rank() && std::find(out.begin(), out.end(), r) == out.end()) out.push_back(r);
    });
}

template <int D>
void ParallelEngine<D>::buildLayout() {
    // The window: this rank's block (a box of real cells, morton.hpp) and one ring of halo.
    const int me = m_comm.rank();
    const DomainBlock& block = m_map->blockOf(me);
    std::array<int, D> lo, hi;
    m_morton->realBox(block.start, block.log2Size, lo, hi);
    std::array<int, 3> lo3{0, 0, 0}, hi3{1, 1, 1};
    for (int d = 0; d < D; ++d) {
        lo3[d] = lo[d];
        hi3[d] = hi[d];
    }
    m_window = CellWindow::around<D>(m_cells, m_config.periodic, lo3, hi3, 1);
    const auto count = static_cast<std::uint32_t>(m_window.count());
    m_owner.resize(count);
    for (std::uint32_t w = 0; w < count; ++w) m_owner[w] = m_map->owner(mortonOf(m_window.coordsOf<D>(w)));
    m_layout.cells = m_cells;
    m_layout.window = m_window;
    m_layout.domain = true;
    m_layout.role.assign(count, CellRole::Foreign);
    m_layout.globalParticles = m_globalCount;
    m_neighbourIndex.assign(static_cast<std::size_t>(m_comm.size()), -1);
    m_neighbours.clear();
    // One pass: the other ranks around each cell, and whether this rank owns a cell there. A
    // change of a virtual particle (a collision executed here, a migration out) goes to every
    // rank around its halo cell, so the neighbours are the ranks around the halo cells (within
    // two cells of this rank's own): records go directly, never forwarded (a forwarded record
    // would arrive late).
    std::vector<int> around;
    for (std::uint32_t w = 0; w < count; ++w) {
        around.clear();
        bool touchesMine = false;
        m_window.forEachInGridAround<D>(
            m_window.coordsOf<D>(w), m_config.periodic, [&](const std::array<int, 3>& c) {
                const int r = ownerOf(c);
                if (r == me)
                    touchesMine = true;
                else if (std::find(around.begin(), around.end(), r) == around.end())
                    around.push_back(r);
            });
        if (m_owner[w] == me) {
            m_layout.role[w] = around.empty() ? CellRole::Interior : CellRole::Border;
        } else if (touchesMine) {
            m_layout.role[w] = CellRole::Halo;
            for (const int r : around)  // the cell's owner is among them
                if (m_neighbourIndex[static_cast<std::size_t>(r)] < 0) {
                    m_neighbourIndex[static_cast<std::size_t>(r)] = 0;
                    m_neighbours.push_back(r);
                }
        }
    }
    // Fringe: interior cells with a border cell among their 3^D neighbours (all in the window).
    m_layout.fringe.assign(count, 0);
    for (std::uint32_t w = 0; w < count && m_parallel.fringeBorderEvents; ++w) {
        if (m_layout.role[w] != CellRole::Interior) continue;
        m_window.forEachAround<D>(m_window.coordsOf<D>(w), m_config.periodic, [&](std::uint32_t index) {
            if (m_layout.role[index] != CellRole::Interior) m_layout.fringe[w] = 1;
        });
    }
    std::sort(m_neighbours.begin(), m_neighbours.end());
    for (std::size_t k = 0; k < m_neighbours.size(); ++k)
        m_neighbourIndex[static_cast<std::size_t>(m_neighbours[k])] = static_cast<int>(k);
    m_cellLoad.assign(balancing() ? count : 0, 0);
}

template <int D>
void ParallelEngine<D>::distribute(std::vector<ParticleRecord> owned, bool everyRecord,
                                   const EngineGlobals& globals) {
    const double t0 = wallSeconds();
    const auto coords = [](const ParticleRecord& r) {
        return std::array<int, 3>{r.cell[0], r.cell[1], r.cell[2]};
    };
    std::vector<ParticleRecord> local;
    if (everyRecord) {  // every rank holds every record: keep the owned and halo ones
        for (auto& r : owned) {
            const std::uint32_t w = m_window.indexOf<D>(r.cell);
            const CellRole role = w == CellWindow::kOutside ? CellRole::Foreign : m_layout.role[w];
            if (role == CellRole::Foreign) continue;
            if (role == CellRole::Halo) r.eventKind = 4;  // a copy: its owner schedules it
            local.push_back(r);
        }
    } else {
        // Owned records to their new owners, then halo copies to the ranks around them.
        std::vector<std::vector<ParticleRecord>> out(static_cast<std::size_t>(m_comm.size()));
        for (const auto& r : owned) out[static_cast<std::size_t>(ownerOf(coords(r)))].push_back(r);
        std::vector<ByteBuffer> buffers;
        for (auto& o : out) buffers.push_back(packRecords(o));
        std::vector<ParticleRecord> mine;
        for (const auto& b : m_comm.allToAll(std::move(buffers))) unpackRecords(b, mine);
        m_stats.migrationsIn += mine.size();
        std::vector<std::vector<ParticleRecord>> copies(static_cast<std::size_t>(m_comm.size()));
        std::vector<int> around;
        for (const auto& r : mine) {
            around.clear();
            recipients(r.cell, around);
            ParticleRecord copy = r;
            copy.eventKind = 4;
            for (const int k : around) copies[static_cast<std::size_t>(k)].push_back(copy);
        }
        buffers.clear();
        for (auto& c : copies) buffers.push_back(packRecords(c));
        local = std::move(mine);
        for (const auto& b : m_comm.allToAll(std::move(buffers))) unpackRecords(b, local);
    }
    rebuildKernel(globals, std::move(local));
    m_stats.rebuildSeconds += elapsedSince(t0);
}

template <int D>
void ParallelEngine<D>::rebuildKernel(const EngineGlobals& globals, std::vector<ParticleRecord> records) {
    m_kernel = std::make_unique<Kernel>(m_config, m_layout, globals, std::move(records));
    if (balancing()) m_kernel->countCellEvents();
    m_collisionLog.clear();
    m_kernel->setCollisionLog(m_logging ? &m_collisionLog : nullptr);
}

template <int D>
void ParallelEngine<D>::commitBarrier(Real t) {
    const double t0 = wallSeconds();
    m_kernel->setTime(t);
    m_barrier = t;
    m_kernel->takeCellEvents(m_cellLoad);
    m_stats.slotsReclaimed += m_kernel->reclaimDeadSlots();  // before the copy: both stay ~N/P + halo
    m_checkpointGlobals = m_kernel->globals();
    m_kernel->injectCausalityError(Kernel::kNever);  // a forced error belongs to one section
    if (m_checkpoint)
        *m_checkpoint = *m_kernel;
    else
        m_checkpoint = std::make_unique<Kernel>(*m_kernel);
    m_collisionLog.clear();
    m_stats.rebuildSeconds += elapsedSince(t0);
}

template <int D>
void ParallelEngine<D>::rollback() {
    const double t0 = wallSeconds();
    m_stats.eventsUndone += m_kernel->stats().events - m_checkpointGlobals.stats.events;
    *m_kernel = *m_checkpoint;
    m_collisionLog.clear();
    m_kernel->setCollisionLog(m_logging ? &m_collisionLog : nullptr);
    m_stats.rebuildSeconds += elapsedSince(t0);
}

template <int D>
void ParallelEngine<D>::exchange(EventKey limit, std::vector<EventKey>* announced) {
    // Phase 1: every change since the last exchange to the ranks around its old and new cell;
    // receive the same from every neighbour (spec 3.8 steps 4-5).
    const double t0 = wallSeconds();
    const std::size_t nb = m_neighbours.size();
    m_kernel->drainChanges(m_changes);
    auto& out = m_outgoing;  // reused step after step: no allocation once warm
    out.resize(nb);
    for (auto& o : out) o.clear();
    auto& to = m_recipients;
    for (const auto& ch : m_changes) {
        to.clear();
        recipients(ch.oldCell, to);
        if (ch.record.cell != ch.oldCell) recipients(ch.record.cell, to);
        for (const int r : to) {
            const int k = m_neighbourIndex[static_cast<std::size_t>(r)];
            if (k < 0) throw std::logic_error("edmd parallel: a change for a rank that is not a neighbour");
            out[static_cast<std::size_t>(k)].push_back(ch.record);
        }
    }
    const int tag = announced ? kTagStep : kTagCareful;
    for (std::size_t k = 0; k < nb; ++k) {
        ByteBuffer b = packRecords(out[k]);
        m_stats.recordsSent += out[k].size();
        m_stats.bytesSent += b.size();
        m_comm.send(m_neighbours[k], tag, std::move(b));
    }
    auto& in = m_incoming;
    for (std::size_t k = 0; k < nb; ++k) {
        const ByteBuffer b = m_comm.receive(m_neighbours[k], tag);
        in.clear();
        unpackRecords(b, in);
        for (const auto& r : in) {
            const bool late = r.tst < m_kernel->time();
            if (m_kernel->receive(r) && late) ++m_stats.lateRecords;  // an error is remembered
        }
    }
    if (announced) {
        // Phase 2 (spec 3.8 step 1): the received updates that are next in this rank's order
        // are applied now, so that the particles they give or change here are predicted before
        // this rank announces its next border event (else a migration or a collision executed
        // by a neighbour would hold that neighbour back for a step); the announcement is the
        // earliest border event or pending update of an owned particle.
        m_kernel->applyPendingInOrder(limit);
        const EventKey announce = m_announced = m_kernel->nextBorderKey();
        for (std::size_t k = 0; k < nb; ++k)
            m_comm.send(m_neighbours[k], kTagAnnounce, packPod(std::span(&announce, 1)));
        announced->assign(nb, EventKey{});
        std::vector<EventKey> one;
        for (std::size_t k = 0; k < nb; ++k) {
            one.clear();
            unpackPod(m_comm.receive(m_neighbours[k], kTagAnnounce), one);
            if (one.size() != 1) throw std::runtime_error("edmd parallel: malformed announcement");
            (*announced)[k] = one[0];
        }
    }
    ++m_stats.steps;
    m_stats.communicationSeconds += elapsedSince(t0);
}

template <int D>
bool ParallelEngine<D>::runSection(EventKey limit, Real& errorTime) {
    std::vector<EventKey> announced;
    bool inFlight = false;
    for (;;) {
        exchange(limit, &announced);
        const double t0 = wallSeconds();
        if (inFlight) {
            const std::vector<double> result = m_comm.waitMin();
            if (result[0] < kNoEvent) {
                errorTime = result[0];
                m_stats.communicationSeconds += elapsedSince(t0);
                return false;
            }
            if (result[2] == 0) {  // a rank's clock stood still (inelastic collapse)
                m_domainStalled = true;
                m_stats.communicationSeconds += elapsedSince(t0);
                return false;
            }
            if (result[1] > 0) {  // no rank had anything below the limit
                m_stats.communicationSeconds += elapsedSince(t0);
                return true;
            }
        }
        const std::array<double, 3> mine{m_kernel->causalityError(), m_kernel->nextKey() < limit ? 0.0 : 1.0,
                                         m_kernel->domainStalled() ? 0.0 : 1.0};
        m_comm.startMin(mine);
        inFlight = true;
        m_stats.communicationSeconds += elapsedSince(t0);
        if (m_kernel->causalityError() < kNoEvent) continue;  // wait for the others to learn it
        // Local step end (spec 3.7): the earliest neighbour announcement; the step also ends
        // after this rank's announced border event (or a later one that replaced it). An
        // earlier, unannounced border event (a particle that entered the border zone) does not
        // end it: the neighbours' steps were not held back by it.
        EventKey end = limit;
        for (const EventKey& a : announced) end = std::min(end, a);
        const double t1 = wallSeconds();
        m_kernel->runDomain(end, m_announced);
        m_stats.computeSeconds += elapsedSince(t1);
    }
}

template <int D>
Real ParallelEngine<D>::runCareful(Real target, Real past) {
    // Event by event in the global (time, id) order: no causality error is possible. Runs until
    // the earliest pending event of all ranks is later than `past` (or reaches target); returns
    // the new barrier time (every event before it done).
    ++m_stats.carefulSections;
    for (;;) {
        exchange(EventKey{}, nullptr);
        // Impossible in global event order; a dropped late record would go unnoticed here.
        if (m_kernel->causalityError() < kNoEvent)
            throw std::logic_error("edmd parallel: a causality error in an event-by-event section");
        const double t0 = wallSeconds();
        const EventKey next = m_kernel->nextKey();
        std::array<double, 1> t{next.time};
        m_comm.allMin(t);
        // (id, kind) as one number: records before events of the same particle and instant.
        std::array<double, 1> id{next.time == t[0] ? 2.0 * next.id + next.kind : kNoEvent};
        m_comm.allMin(id);
        m_stats.communicationSeconds += elapsedSince(t0);
        // Every rank decides alike, right after an exchange: no record is in flight.
        if (!(t[0] < target) || t[0] > past) return std::min(t[0], target);
        if (next.time == t[0] && 2.0 * next.id + next.kind == id[0])
            m_kernel->runDomain(EventKey{next.time, next.id, next.kind + 1});
    }
}

template <int D>
void ParallelEngine<D>::runUntil(Real tEnd) {
    run(tEnd, ~std::uint64_t{0});
}

template <int D>
void ParallelEngine<D>::runCollisions(std::uint64_t collisions, Real tEnd) {
    const std::uint64_t now = globalCollisions();
    run(tEnd, collisions > ~std::uint64_t{0} - now ? ~std::uint64_t{0} - 1 : now + collisions);
}

template <int D>
std::uint64_t ParallelEngine<D>::globalCollisions() {
    std::array<std::uint64_t, 1> c{m_kernel->stats().collisions};
    m_comm.allSum(c);
    return c[0];
}

template <int D>
EventKey ParallelEngine<D>::kthCollision(std::uint64_t k) {
    // Each rank's log is in its own key order; the k smallest of all are among the first k of
    // each. The root merges them and tells everybody.
    const std::size_t mine = static_cast<std::size_t>(std::min<std::uint64_t>(k, m_collisionLog.size()));
    ByteBuffer answer;
    const std::vector<ByteBuffer> parts =
        m_comm.gather(packPod(std::span<const EventKey>(m_collisionLog.data(), mine)));
    if (m_comm.root()) {
        std::vector<EventKey> all;
        for (const auto& part : parts) unpackPod(part, all);
        if (all.size() < k) throw std::logic_error("edmd parallel: fewer logged collisions than counted");
        std::nth_element(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(k - 1), all.end());
        append(answer, all[k - 1]);
    }
    answer = m_comm.broadcast(std::move(answer));
    return readAt<EventKey>(answer, 0);
}

template <int D>
void ParallelEngine<D>::run(Real tEnd, std::uint64_t target) {
    m_interrupted = false;
    m_stall = Stall::None;
    const bool byCount = target != ~std::uint64_t{0};
    if (byCount != m_logging) {
        m_logging = byCount;
        m_collisionLog.clear();
        m_kernel->setCollisionLog(m_logging ? &m_collisionLog : nullptr);
    }
    std::uint64_t atBarrier = byCount ? globalCollisions() : 0;
    if (byCount && atBarrier >= target) return;
    // The key of the collision that completes the count, once a section has passed it.
    EventKey stopKey{kNoEvent, 0};
    Real forcedTarget = kNoEvent;
    int quietSections = 0;
    while (m_barrier < tEnd) {
        // A signal on any rank stops every rank at this barrier (a resumable state).
        std::array<double, 1> signal{interruptRequested() ? 1.0 : 0.0};
        m_comm.allMax(signal);
        if (signal[0] > 0) {
            m_interrupted = true;
            break;
        }
        EventKey limit{std::min({forcedTarget, m_barrier + m_interval, tEnd}), 0};
        const bool toStop = stopKey < limit;
        if (toStop) limit = stopKey;
        forcedTarget = kNoEvent;
        if (m_parallel.forcedErrorEvery > 0 &&
            (m_stats.sections + m_stats.rollbacks + 1) % m_parallel.forcedErrorEvery == 0 &&
            static_cast<int>((m_stats.sections + m_stats.rollbacks) %
                             static_cast<std::uint64_t>(m_comm.size())) == m_comm.rank())
            m_kernel->injectCausalityError(64);
        Real errorTime = kNoEvent;
        if (runSection(limit, errorTime)) {
            if (byCount && !toStop) {
                const std::uint64_t now = globalCollisions();
                if (now >= target) {
                    // Passed the count: repeat the section from the barrier up to the k-th
                    // collision (the serial engine stops right after it).
                    stopKey = kthCollision(target - atBarrier);
                    stopKey.kind = 2;  // after the collision event (kind 1) of that particle
                    rollback();
                    continue;
                }
                quietSections = now == atBarrier ? quietSections + 1 : 0;
                atBarrier = now;
            }
            if (toStop) m_kernel->applyReceivedUntil(limit.time);
            commitBarrier(limit.time);
            ++m_stats.sections;
            m_interval = std::min(m_interval * 1.1, m_parallel.maxSyncInterval);
            if (toStop) break;
            if (quietSections >= 64) {  // a count that can never be reached
                m_stall = Stall::NoCollision;
                break;
            }
            if (balancing()) balance();
            continue;
        }
        if (m_domainStalled) {  // every rank back to the barrier's consistent state, and stop
            m_domainStalled = false;
            rollback();
            m_stall = Stall::Clock;
            break;
        }
        // Causality error somewhere (spec 3.4): everybody back to the barrier; the section is
        // repeated up to the error time. At the barrier itself: event by event past it.
        ++m_stats.rollbacks;
        rollback();
        m_interval = std::max(m_interval * 0.5, 1e-300);
        if (errorTime > m_barrier) {
            forcedTarget = errorTime;
        } else {
            const Real reached = runCareful(std::min(tEnd, stopKey.time), m_barrier);
            commitBarrier(reached);
            ++m_stats.sections;
            if (byCount) {
                atBarrier = globalCollisions();
                // Simultaneous collisions at the barrier passed the count: stop at that instant.
                if (atBarrier >= target) break;
            }
        }
    }
}

template <int D>
void ParallelEngine<D>::balance() {
    // Loads of the two halves of this rank's block: events per cell since the last balancing
    // (spec 3.2's "current collision frequency"), all ranks over the same interval.
    const DomainBlock& block = m_map->blockOf(m_comm.rank());
    const std::uint64_t half = block.log2Size > 0 ? (std::uint64_t{1} << (block.log2Size - 1)) : 1;
    std::array<double, 2> halves{0, 0};
    for (std::uint32_t cell = 0; cell < m_cellLoad.size(); ++cell) {
        if (m_cellLoad[cell] == 0 || m_owner[cell] != m_comm.rank()) continue;
        const std::uint64_t m = mortonOf(m_window.coordsOf<D>(cell));
        halves[m - block.start < half ? 0 : 1] += static_cast<double>(m_cellLoad[cell]);
    }
    const std::vector<double> all = m_comm.allGather(halves);
    std::vector<std::array<double, 2>> loads(static_cast<std::size_t>(m_comm.size()));
    for (std::size_t r = 0; r < loads.size(); ++r) loads[r] = {all[2 * r], all[2 * r + 1]};
    double total = 0;
    for (const auto& l : loads) total += l[0] + l[1];
    if (total < 1000.0 * m_comm.size()) return;  // too few events to judge; keep counting
    std::fill(m_cellLoad.begin(), m_cellLoad.end(), 0);
    const auto moves = m_map->rebalance(loads, m_parallel.balanceThreshold);
    if (moves.empty()) return;
    m_stats.balanceMoves += moves.size();
    const EngineGlobals g = m_kernel->globals();
    std::vector<ParticleRecord> owned = m_kernel->records(true);
    buildLayout();
    distribute(std::move(owned), false, g);
    commitBarrier(m_barrier);
}

template <int D>
void flyRecordTo(ParticleRecord& r, Real t, const EngineConfig& config) noexcept {
    // As Engine::positionSlot and velocitySlot, so that gathered states equal the serial ones.
    const Real dt = t - r.tst;
    for (int d = 0; d < D; ++d) {
        const Real g = config.gravity[d];
        Real x = flightPosition(r.x[d], r.v[d], g, dt);
        if (config.periodic[d]) {
            if (x < 0)
                x += config.box[d];
            else if (x >= config.box[d])
                x -= config.box[d];
        }
        r.x[d] = x;
        r.v[d] = flightVelocity(r.v[d], g, dt);
    }
    r.tst = t;
}

template void flyRecordTo<2>(ParticleRecord&, Real, const EngineConfig&) noexcept;
template void flyRecordTo<3>(ParticleRecord&, Real, const EngineConfig&) noexcept;

template <int D>
std::vector<ParticleRecord> ParallelEngine<D>::gatherNow() {
    std::vector<ParticleRecord> mine = m_kernel->records(true);
    for (auto& r : mine) flyRecordTo<D>(r, m_barrier, m_config);
    std::vector<ParticleRecord> all;
    for (const auto& b : m_comm.gather(packRecords(mine))) unpackRecords(b, all);
    std::sort(all.begin(), all.end(),
              [](const ParticleRecord& a, const ParticleRecord& b) { return a.id < b.id; });
    return all;
}

template <int D>
EngineGlobals ParallelEngine<D>::globals() {
    EngineGlobals g = m_kernel->globals();
    std::array<std::uint64_t, 7> counts{g.stats.events,        g.stats.collisions,     g.stats.annulled,
                                        g.stats.cellCrossings, g.stats.wallCollisions, g.stats.tcElastic,
                                        g.stats.regrids};
    m_comm.allSum(counts);
    g.stats = {counts[0], counts[1], counts[2], counts[3], counts[4], counts[5], counts[6]};
    std::array<double, 2> sums{g.virial, g.dissipated};
    m_comm.allSum(sums);
    g.virial = sums[0];
    g.dissipated = sums[1];
    g.now = m_barrier;
    return g;
}

template <int D>
EngineGlobals ParallelEngine<D>::gatherState(std::vector<ParticleRecord>& records) {
    records.clear();
    for (const auto& b : m_comm.gather(packRecords(m_kernel->records(true)))) unpackRecords(b, records);
    std::sort(records.begin(), records.end(),
              [](const ParticleRecord& a, const ParticleRecord& b) { return a.id < b.id; });
    return globals();
}

template <int D>
std::size_t ParallelEngine<D>::memoryBytes() const noexcept {
    return m_kernel->memoryBytes() + (m_checkpoint ? m_checkpoint->memoryBytes() : 0) +
           m_owner.capacity() * sizeof(std::int32_t) + m_layout.role.capacity() + m_layout.fringe.capacity() +
           m_cellLoad.capacity() * sizeof(std::uint64_t);
}

template class ParallelEngine<2>;
template class ParallelEngine<3>;

}  // namespace granulab::edmd
