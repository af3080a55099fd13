// SPDX-License-Identifier: MIT
// Records and the domain mode of the event-driven engine (edmd spec sections 3.4-3.8; checklist
// items 35-40): an engine built from slot-independent particle records (rank-count-independent
// checkpoints, rollback copies, migrations), and one rank's part of the parallel engine: the
// owned cells (interior and border), the halo of virtual particles (copies of the neighbours'
// border particles, no events of their own), a second queue of border events (events that can
// touch another rank's particles), the records of changed border particles that go to the
// neighbours, and received records applied at their own time in the global event order (time,
// then id). Received records earlier than what this rank already did with that neighbourhood
// are causality errors (spec 3.8 steps 5 and 6); the driver (edmd/parallel/parallel_engine.cpp)
// then rolls every rank back.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/error.hpp"
#include "edmd/engine.hpp"

namespace granulab::edmd {

namespace {
constexpr std::uint8_t kKindNone = 0, kKindParticle = 1, kKindCell = 2, kKindWall = 3, kKindPredict = 4;

/// Min-heap order of pending records: earliest (tst, id) at the front, then in arrival order
/// (several records of one particle at one instant, dt = 0 events such as a crossing of two
/// faces at a cell corner, are applied in the order they were made).
template <class Pending>
bool laterRecord(const Pending& a, const Pending& b) noexcept {
    const EventKey ka{a.record.tst, a.record.id}, kb{b.record.tst, b.record.id};
    return kb < ka || (!(ka < kb) && b.arrival < a.arrival);
}
}  // namespace

template <int D, class Queue>
Engine<D, Queue>::Engine(EngineConfig config, const DomainLayout& layout, const EngineGlobals& globals,
                         std::vector<ParticleRecord> records)
    : m_config(config) {
    std::size_t cellCount = 1;
    for (int d = 0; d < D; ++d) {
        if (!(m_config.box[d] > 0)) throw std::invalid_argument("edmd::Engine: box edges must be positive");
        if (layout.cells[d] < 1 || layout.cells[d] > kMaxCellsPerAxis)
            throw std::invalid_argument("edmd::Engine: cells per axis out of range");
        m_forcedCells[d] = layout.cells[d];
        cellCount *= static_cast<std::size_t>(layout.cells[d]);
    }
    if (layout.domain) {  // a domain engine: tables for its window only
        if (layout.window.cells != layout.cells || layout.role.size() != layout.window.count() ||
            (!layout.fringe.empty() && layout.fringe.size() != layout.role.size()))
            throw std::invalid_argument("edmd::Engine: the domain layout's roles do not match its window");
        m_window = layout.window;
        m_windowGiven = true;
    }
    const auto n = static_cast<std::uint32_t>(records.size());
    const std::uint32_t idCount = !layout.domain ? n : layout.globalParticles;
    m_config.restitution = globals.restitution;
    m_config.wallRestitution = globals.wallRestitution;
    m_config.tc = globals.tc;
    m_config.growthRate = globals.growthRate;
    m_now = globals.now;
    m_stats = globals.stats;
    m_virial = globals.virial;
    m_dissipated = globals.dissipated;
    for (int d = 0; d < D; ++d) m_gravity = m_gravity || m_config.gravity[d] != 0;
    // Slots in cell order (neighbours close in memory), ties by id.
    const auto cellKey = [&](const ParticleRecord& r) {
        std::uint64_t k = 0, stride = 1;
        for (int d = 0; d < D; ++d) {
            k += stride * r.cell[d];
            stride *= static_cast<std::uint64_t>(layout.cells[d]);
        }
        return k;
    };
    std::sort(records.begin(), records.end(), [&](const ParticleRecord& a, const ParticleRecord& b) {
        const auto ka = cellKey(a), kb = cellKey(b);
        return ka < kb || (ka == kb && a.id < b.id);
    });
    if (n) {
        m_uniformRadius = records[0].radius0;
        m_uniformMass = records[0].mass;
    }
    const bool equalRadii = std::all_of(records.begin(), records.end(), [&](const ParticleRecord& r) {
        return r.radius0 == m_uniformRadius;
    });
    const bool equalMasses = std::all_of(records.begin(), records.end(),
                                         [&](const ParticleRecord& r) { return r.mass == m_uniformMass; });
    if (!equalRadii) m_radius.resize(n);
    if (!equalMasses) m_mass.resize(n);
    if (m_config.rough()) m_omega.assign(n, Vec3{});
    if (m_config.tc > 0) m_lastCollision.assign(n, -kNoEvent);
    m_s.resize(n);
    m_event.assign(n, Event{});
    m_cellOf.resize(n);
    m_id.resize(n);
    IdSlotMap slots;  // a domain engine's id map: its own and halo particles only
    if (!layout.domain) m_slot.assign(idCount, kNone);
    for (std::uint32_t s = 0; s < n; ++s) {
        const ParticleRecord& r = records[s];
        if (r.id >= idCount || (layout.domain ? slots.find(r.id) : m_slot[r.id]) != kNone)
            throw std::invalid_argument("edmd::Engine: particle record with an id out of range or twice");
        for (int d = 0; d < D; ++d)
            if (r.cell[d] >= layout.cells[d] || (m_windowGiven && m_window.local(d, r.cell[d]) < 0))
                throw std::invalid_argument(
                    "edmd::Engine: particle record in a cell outside the grid or window");
        if (!(r.radius0 > 0) || !(r.mass > 0) || !std::isfinite(r.tst))
            throw std::invalid_argument("edmd::Engine: particle record with a bad radius, mass or time");
        m_id[s] = r.id;
        if (layout.domain)
            slots.set(r.id, s);
        else
            m_slot[r.id] = s;
        setFromRecord(s, r);
        m_maxRadius0 = std::max(m_maxRadius0, r.radius0);
    }
    buildCells();  // the layout's grid; every slot's cell then comes from its record
    // A serial engine chooses its grid again when growing spheres outgrow it (as it would have).
    if (!layout.domain) m_forcedCells = {0, 0, 0};
    for (std::uint32_t s = 0; s < n; ++s)
        for (int d = 0; d < D; ++d) m_cellOf[s][d] = records[s].cell[d];
    for (std::uint32_t s = n; s-- > 0;) linkCell(s);  // ascending slot order in every cell list
    m_nextSort = m_stats.events + kSortEvery * std::max<std::uint64_t>(n, 1);
    if (layout.domain) {
        m_domain = std::make_unique<DomainData>();
        // Room for the halo's comings and goings between two reclaimDeadSlots(); before any
        // pointer into the per-slot arrays (the queues' tie keys) is taken.
        reserveSlots(n + n / 8 + 1024);
        m_domain->slots = std::move(slots);
        m_domain->globalParticles = idCount;
        m_domain->role = layout.role;
        m_domain->fringe = layout.fringe;
        m_domain->fringe.resize(layout.role.size(), 0);
        m_domain->readTime.assign(layout.role.size(), -kNoEvent);
        m_domain->border.setTieKeys(m_id.data());
        m_domain->border.reset(n);
        m_domain->dead.assign(n, 0);
    }
    m_queue.setTieKeys(m_id.data());
    m_queue.reset(n);
    m_queue.beginBulk();  // until retune() below
    // Scheduled events as recorded (partners by id); kind 4 is predicted now, in slot order.
    std::vector<std::uint32_t> predict;
    for (std::uint32_t s = 0; s < n; ++s) {
        if (!realSlot(s)) continue;
        if (m_domain) ++m_domain->owned;
        const ParticleRecord& r = records[s];
        Event ev;
        Real t = r.eventTime;
        switch (r.eventKind) {
            case kKindNone:
                t = kNoEvent;
                break;
            case kKindParticle:
                // A partner this rank does not hold cannot be met before the event (it would be
                // in a neighbour cell); the event then only re-predicts at its time.
                ev.partner = r.eventPartner < idCount ? slotOfId(r.eventPartner) : kNone;
                ev.partnerCounter = r.eventPartnerCounter;
                break;
            case kKindCell:
            case kKindWall:
                if (r.eventFace >= 2 * D)
                    throw std::invalid_argument("edmd::Engine: particle record with a bad face");
                ev.partner = (r.eventKind == kKindCell ? kCellBase : kWallBase) + r.eventFace;
                break;
            case kKindPredict:
                predict.push_back(s);
                continue;
            default:
                throw std::invalid_argument("edmd::Engine: particle record with an unknown event kind");
        }
        if (std::isnan(t) || t < m_now)
            throw std::invalid_argument("edmd::Engine: particle record with an event in the past");
        m_event[s] = ev;
        m_queue.set(s, t);
        if (m_domain) scheduleDomainBorder(s);
    }
    for (const std::uint32_t s : predict) m_domain ? scheduleDomain(s) : schedule(s);
    m_queue.retune();
    resetWatchdog();
}

template <int D, class Queue>
Engine<D, Queue>::Engine(const Engine& other) : m_config(other.m_config) {
    *this = other;
}

template <int D, class Queue>
Engine<D, Queue>& Engine<D, Queue>::operator=(const Engine& o) {
    if (this == &o) return *this;
    // The per-slot arrays keep the source's room: the rollback copy is refreshed at every
    // barrier, and a copy sized to the slots alone would be reallocated (fresh pages, zeroed
    // by the kernel) whenever the halo has grown since.
    const auto assign = [](auto& to, const auto& from) {
        if (to.capacity() < from.capacity()) {
            to.clear();
            to.reserve(from.capacity());
        }
        to = from;
    };
    m_config = o.m_config;
    assign(m_s, o.m_s);
    assign(m_event, o.m_event);
    assign(m_cellOf, o.m_cellOf);
    m_slot = o.m_slot;
    assign(m_id, o.m_id);
    assign(m_radius, o.m_radius);
    assign(m_mass, o.m_mass);
    m_uniformRadius = o.m_uniformRadius;
    m_uniformMass = o.m_uniformMass;
    assign(m_omega, o.m_omega);
    assign(m_lastCollision, o.m_lastCollision);
    m_head = o.m_head;
    m_queue = o.m_queue;
    m_cells = o.m_cells;
    m_window = o.m_window;
    m_windowGiven = o.m_windowGiven;
    m_forcedCells = o.m_forcedCells;
    m_stride = o.m_stride;
    m_cellEdge = o.m_cellEdge;
    m_invCellEdge = o.m_invCellEdge;
    m_regridTime = o.m_regridTime;
    m_maxRadius0 = o.m_maxRadius0;
    m_gravity = o.m_gravity;
    m_now = o.m_now;
    m_virial = o.m_virial;
    m_dissipated = o.m_dissipated;
    m_nextSort = o.m_nextSort;
    m_stats = o.m_stats;
    m_stall = o.m_stall;
    m_watch = o.m_watch;
    m_checkAt = o.m_checkAt;
    m_interrupted = o.m_interrupted;
    if (!o.m_domain) {
        m_domain.reset();
    } else {
        if (!m_domain) m_domain = std::make_unique<DomainData>();
        *m_domain = *o.m_domain;
    }
    // The queues compare ties through this engine's ids, not the source's.
    m_queue.setTieKeys(m_id.data());
    if (m_domain) m_domain->border.setTieKeys(m_id.data());
    return *this;
}

template <int D, class Queue>
std::size_t Engine<D, Queue>::domainMemoryBytes() const noexcept {
    if (!m_domain) return 0;
    const DomainData& dom = *m_domain;
    return dom.slots.memoryBytes() + dom.role.capacity() + dom.fringe.capacity() +
           dom.cellEvents.capacity() * sizeof(std::uint32_t) + dom.readTime.capacity() * sizeof(Real) +
           dom.dead.capacity() + dom.border.memoryBytes() + dom.pending.capacity() * sizeof(PendingRecord) +
           dom.changes.capacity() * sizeof(Change);
}

template <int D, class Queue>
void Engine<D, Queue>::setFromRecord(std::uint32_t s, const ParticleRecord& r) {
    State& p = m_s[s];
    for (int d = 0; d < D; ++d) {
        p.x[d] = r.x[d];
        p.v[d] = r.v[d];
    }
    p.tst = r.tst;
    p.counter = r.counter;
    if (!m_radius.empty()) m_radius[s] = r.radius0;
    if (!m_mass.empty()) m_mass[s] = r.mass;
    if (!m_omega.empty()) m_omega[s] = Vec3{{r.omega[0], r.omega[1], r.omega[2]}};
    if (!m_lastCollision.empty()) m_lastCollision[s] = r.lastCollision;
    for (int d = 0; d < D; ++d) m_cellOf[s][d] = r.cell[d];
}

template <int D, class Queue>
ParticleRecord Engine<D, Queue>::recordOf(std::uint32_t s) const {
    ParticleRecord r;
    const State& p = m_s[s];
    r.id = m_id[s];
    r.counter = p.counter;
    for (int d = 0; d < D; ++d) {
        r.cell[d] = m_cellOf[s][d];
        r.x[d] = p.x[d];
        r.v[d] = p.v[d];
    }
    r.tst = p.tst;
    r.radius0 = m_radius.empty() ? m_uniformRadius : m_radius[s];
    r.mass = massSlot(s);
    if (!m_omega.empty())
        for (int d = 0; d < 3; ++d) r.omega[d] = m_omega[s][d];
    if (!m_lastCollision.empty()) r.lastCollision = m_lastCollision[s];
    if (!realSlot(s)) return r;  // virtual copies carry no event (kind 4: predicted by the owner)
    const Event& ev = m_event[s];
    r.eventTime = m_queue.time(s);
    if (ev.partner < kMaxParticles) {
        r.eventKind = kKindParticle;
        r.eventPartner = m_id[ev.partner];
        r.eventPartnerCounter = ev.partnerCounter;
    } else if (ev.partner == kNone) {
        // No partner: +infinity is "no event"; a finite time re-predicts then (partner gone).
        r.eventKind = r.eventTime == kNoEvent ? kKindNone : kKindParticle;
        r.eventPartner = ~std::uint32_t{0};
    } else if (ev.partner >= kCellBase) {
        r.eventKind = kKindCell;
        r.eventFace = static_cast<std::uint8_t>(ev.partner - kCellBase);
    } else {
        r.eventKind = kKindWall;
        r.eventFace = static_cast<std::uint8_t>(ev.partner - kWallBase);
    }
    return r;
}

template <int D, class Queue>
std::vector<ParticleRecord> Engine<D, Queue>::records(bool realOnly) const {
    std::vector<ParticleRecord> out;
    out.reserve(m_domain ? m_domain->owned : size());
    for (std::uint32_t s = 0; s < size(); ++s) {
        if (m_domain && m_domain->dead[s]) continue;
        if (realOnly && !realSlot(s)) continue;
        out.push_back(recordOf(s));
    }
    std::sort(out.begin(), out.end(),
              [](const ParticleRecord& a, const ParticleRecord& b) { return a.id < b.id; });
    return out;
}

template <int D, class Queue>
EngineGlobals Engine<D, Queue>::globals() const {
    EngineGlobals g;
    g.now = m_now;
    g.stats = m_stats;
    g.virial = m_virial;
    g.dissipated = m_dissipated;
    g.restitution = m_config.restitution;
    g.wallRestitution = m_config.wallRestitution;
    g.tc = m_config.tc;
    g.growthRate = m_config.growthRate;
    return g;
}

template <int D, class Queue>
CellRole Engine<D, Queue>::roleOf(std::uint32_t s) const noexcept {
    return m_domain ? m_domain->role[cellIndex(m_cellOf[s])] : CellRole::Interior;
}

template <int D, class Queue>
bool Engine<D, Queue>::realSlot(std::uint32_t s) const noexcept {
    if (!m_domain) return true;
    if (m_domain->dead[s]) return false;
    const CellRole r = roleOf(s);
    return ownedRole(r);
}

template <int D, class Queue>
std::uint32_t Engine<D, Queue>::ownedCount() const noexcept {
    return m_domain ? m_domain->owned : size();
}

template <int D, class Queue>
void Engine<D, Queue>::scheduleDomainBorder(std::uint32_t s) noexcept {
    // A border event (spec 3.6): the particle is in a border cell, or its partner is in a border
    // or halo cell, or it crosses into one. Only these can change what another rank sees.
    DomainData& dom = *m_domain;
    const Event& ev = m_event[s];
    bool border = roleOf(s) == CellRole::Border;
    if (!border && ev.partner < kMaxParticles) {
        // The partner may reach a border cell before the collision (partners in a cell next to
        // this one stay within its 3^D cells): a collision in a fringe cell is announced too.
        border = dom.fringe[cellIndex(m_cellOf[s])] != 0 || roleOf(ev.partner) != CellRole::Interior;
    } else if (!border && ev.partner >= kCellBase && ev.partner != kNone) {
        const std::uint32_t face = ev.partner - kCellBase;
        const int d = static_cast<int>(face / 2);
        CellCoords c = m_cellOf[s];
        int k = c[d] + (face % 2 == 1 ? 1 : -1);
        if (k == m_cells[d]) k = 0;
        if (k < 0) k = m_cells[d] - 1;
        c[d] = static_cast<std::uint16_t>(k);
        border = dom.role[cellIndex(c)] != CellRole::Interior;  // next to an owned cell: in the window
    }
    // Most predictions are of interior particles that were not in the border queue either:
    // nothing to move there.
    if (!border && dom.border.time(s) == kNoEvent) return;
    dom.border.set(s, border ? m_queue.time(s) : kNoEvent);
}

template <int D, class Queue>
void Engine<D, Queue>::scheduleDomain(std::uint32_t s) noexcept {
    // A prediction reads the particles of the 3^D cells around (spec 3.6): in a border cell
    // the neighbours' virtual copies, in a fringe cell the border particles a neighbour's
    // collision can change.
    const std::uint32_t cell = cellIndex(m_cellOf[s]);
    if (m_domain->role[cell] == CellRole::Border || m_domain->fringe[cell]) m_domain->readTime[cell] = m_now;
    schedule(s);
    scheduleDomainBorder(s);
}

template <int D, class Queue>
Real Engine<D, Queue>::lastReadAround(const CellCoords& c) const noexcept {
    Real last = -kNoEvent;
    m_window.forEachAround<D>(c, m_config.periodic,
                              [&](std::uint32_t cell) { last = std::max(last, m_domain->readTime[cell]); });
    return last;
}

template <int D, class Queue>
bool Engine<D, Queue>::settledAround(const CellCoords& c, Real t) const noexcept {
    bool settled = true;
    m_window.forEachAround<D>(c, m_config.periodic, [&](std::uint32_t cell) {
        for (std::uint32_t p = m_head[cell]; p != kNone && settled; p = m_s[p].next)
            settled = m_s[p].tst <= t;
    });
    return settled;
}

template <int D, class Queue>
void Engine<D, Queue>::noteChange(std::uint32_t s, const CellCoords& oldCell) {
    // Both cells lie in the window (the particle's cell before and after one event).
    if (m_domain->role[cellIndex(oldCell)] == CellRole::Interior && roleOf(s) == CellRole::Interior) return;
    // Every change is sent, not only the last of a step: a neighbour applies each at its time.
    Change change{recordOf(s), {}};
    for (int d = 0; d < D; ++d) change.oldCell[d] = oldCell[d];
    m_domain->changes.push_back(change);
}

template <int D, class Queue>
void Engine<D, Queue>::drainChanges(std::vector<Change>& out) {
    out.clear();
    if (m_domain) std::swap(out, m_domain->changes);
}

template <int D, class Queue>
EventKey Engine<D, Queue>::pendingKey() const noexcept {
    if (m_domain->pending.empty()) return EventKey{};
    const ParticleRecord& r = m_domain->pending.front().record;
    return EventKey{r.tst, r.id};
}

template <int D, class Queue>
EventKey Engine<D, Queue>::nextKey() const noexcept {
    return m_domain ? std::min(topEventKey(), pendingKey()) : topEventKey();
}

template <int D, class Queue>
EventKey Engine<D, Queue>::nextBorderKey() const noexcept {
    if (!m_domain) return nextKey();
    EventKey k;
    if (size() > 0) k = {m_domain->border.topTime(), m_id[m_domain->border.top()], 1};
    // A pending update of a particle that is (or becomes) owned here: this rank predicts it at
    // the update's time, and the new event can be a border event. Updates of virtual copies
    // create no event here (events naming an old copy are annulled at their own, later time).
    for (const PendingRecord& p : m_domain->pending) {
        const ParticleRecord& r = p.record;
        const CellRole role = roleOfCell(r.cell);
        if (ownedRole(role) && EventKey{r.tst, r.id} < k) k = EventKey{r.tst, r.id};
    }
    return k;
}

template <int D, class Queue>
Real Engine<D, Queue>::causalityError() const noexcept {
    return m_domain ? m_domain->error : kNoEvent;
}

template <int D, class Queue>
void Engine<D, Queue>::countCellEvents() {
    if (m_domain) m_domain->cellEvents.assign(m_head.size(), 0);
}

template <int D, class Queue>
void Engine<D, Queue>::takeCellEvents(std::vector<std::uint64_t>& perCell) {
    if (!m_domain || m_domain->cellEvents.empty()) return;
    perCell.resize(m_domain->cellEvents.size(), 0);
    for (std::size_t c = 0; c < perCell.size(); ++c) {
        perCell[c] += m_domain->cellEvents[c];
        m_domain->cellEvents[c] = 0;
    }
}

template <int D, class Queue>
void Engine<D, Queue>::injectCausalityError(std::uint64_t events) noexcept {
    // kNever disarms it.
    if (m_domain) m_domain->injectAt = events == kNever ? kNever : m_stats.events + events;
}

template <int D, class Queue>
void Engine<D, Queue>::setCollisionLog(std::vector<EventKey>* log) noexcept {
    if (m_domain) m_domain->collisionLog = log;
}

template <int D, class Queue>
bool Engine<D, Queue>::receive(const ParticleRecord& r) {
    DomainData& dom = *m_domain;
    for (int d = 0; d < D; ++d)
        if (r.cell[d] >= m_cells[d])
            throw std::runtime_error("edmd: received a particle record outside the grid");
    if (r.id >= dom.globalParticles)
        throw std::runtime_error("edmd: received a particle record with an unknown id");
    if (m_stats.events >= dom.injectAt) {  // test hook: this record is declared late
        dom.injectAt = ~std::uint64_t{0};
        dom.error = std::min(dom.error, m_now);
        return false;
    }
    if (!(r.tst < m_now)) {
        dom.pending.push_back({r, dom.arrivals++});
        std::push_heap(dom.pending.begin(), dom.pending.end(), laterRecord<PendingRecord>);
        return true;
    }
    // Late (spec 3.8 steps 5-6). Harmless when nothing here has used the particle's old state
    // since the record's time: no particle next to its old cell or its new one was predicted
    // after it (a collision with it or an annulment check is followed by such a prediction).
    const CellRole role = roleOfCell(r.cell);
    const std::uint32_t s = dom.slots.find(r.id);
    const bool wasReal = s != kNone && realSlot(s);
    const bool owned = ownedRole(role);
    CellCoords newCell{};
    for (int d = 0; d < D; ++d) newCell[d] = r.cell[d];
    const bool unread = lastReadAround(newCell) < r.tst &&
                        (s == kNone || (m_s[s].tst <= r.tst && lastReadAround(m_cellOf[s]) < r.tst));
    if (unread && !owned && !wasReal) {  // a virtual copy: no event here
        applyRecord(r);
        return true;
    }
    if (unread && owned && settledAround(newCell, r.tst)) {
        // A particle handed over or changed here: predicted as at the record's time, from
        // neighbours that have not moved on since (so with the serial engine's arithmetic);
        // harmless when its next event is still ahead of this rank's clock.
        const Real now = m_now;
        m_now = r.tst;
        const std::uint32_t slot = applyRecord(r);
        if (slot != kNone) scheduleDomain(slot);
        m_now = now;
        if (slot != kNone && m_queue.time(slot) > now) return true;
    }
    dom.error = std::min(dom.error, r.tst);
    return false;
}

template <int D, class Queue>
std::uint32_t Engine<D, Queue>::addSlot(std::uint32_t id) {
    const auto s = size();
    if (s >= kMaxParticles - 1) throw std::runtime_error("edmd: too many particles on one rank");
    m_s.emplace_back();
    m_event.emplace_back();
    m_cellOf.emplace_back();
    m_id.push_back(id);
    if (!m_radius.empty()) m_radius.push_back(m_uniformRadius);
    if (!m_mass.empty()) m_mass.push_back(m_uniformMass);
    if (!m_omega.empty()) m_omega.emplace_back();
    if (!m_lastCollision.empty()) m_lastCollision.push_back(-kNoEvent);
    m_domain->dead.push_back(0);
    m_domain->slots.set(id, s);
    m_queue.setTieKeys(m_id.data());  // m_id may have moved; grow already compares keys
    m_domain->border.setTieKeys(m_id.data());
    m_queue.grow(s + 1);
    m_domain->border.grow(s + 1);
    return s;
}

template <int D, class Queue>
void Engine<D, Queue>::killSlot(std::uint32_t s) noexcept {
    unlinkCell(s);
    m_domain->dead[s] = 1;
    ++m_domain->deadCount;
    ++m_s[s].counter;  // events that name this slot are annulled (spec 2.6)
    m_domain->slots.erase(m_id[s]);
    m_queue.set(s, kNoEvent);
    m_domain->border.set(s, kNoEvent);
}

template <int D, class Queue>
void Engine<D, Queue>::reserveSlots(std::size_t n) {
    forEachSlotArray([n](auto& array) { array.reserve(n); });
    if (m_domain) m_domain->dead.reserve(n);
}

template <int D, class Queue>
std::uint32_t Engine<D, Queue>::reclaimDeadSlots() {
    if (!m_domain) return 0;
    DomainData& dom = *m_domain;
    const std::uint32_t n = size();
    if (dom.deadCount < 256 || 8 * std::uint64_t{dom.deadCount} < n) return 0;
    // Live slots move down in order (newSlot[s] <= s: in place, ascending). Slot numbers change
    // nothing physical: every order between particles is by id.
    std::vector<std::uint32_t> newSlot(n, kNone);
    std::uint32_t live = 0;
    for (std::uint32_t s = 0; s < n; ++s)
        if (!dom.dead[s]) newSlot[s] = live++;
    std::vector<Real> times(live), borderTimes(live);
    for (std::uint32_t s = 0; s < n; ++s) {
        const std::uint32_t t = newSlot[s];
        if (t == kNone) continue;
        times[t] = m_queue.time(s);
        borderTimes[t] = dom.border.time(s);
        forEachSlotArray([s, t](auto& array) { array[t] = array[s]; });
    }
    forEachSlotArray([live](auto& array) { array.resize(live); });
    dom.dead.assign(live, 0);
    dom.deadCount = 0;
    // Slot references: an event naming a dead slot (annulled at its time, since killSlot raised
    // that slot's counter) names no partner now, which annuls it the same way (runDomain).
    for (auto& ev : m_event)
        if (ev.partner < kMaxParticles) ev.partner = newSlot[ev.partner];
    for (auto& p : m_s)
        if (p.next != kNone) p.next = newSlot[p.next];  // cell lists hold live slots only
    for (auto& h : m_head)
        if (h != kNone) h = newSlot[h];
    dom.slots = IdSlotMap{};
    for (std::uint32_t t = 0; t < live; ++t) dom.slots.set(m_id[t], t);
    m_queue.setTieKeys(m_id.data());
    m_queue.reset(live);
    m_queue.beginBulk();
    for (std::uint32_t t = 0; t < live; ++t) m_queue.set(t, times[t]);
    m_queue.retune();
    dom.border.setTieKeys(m_id.data());
    dom.border.reset(live);
    for (std::uint32_t t = 0; t < live; ++t) dom.border.set(t, borderTimes[t]);
    return n - live;
}

template <int D, class Queue>
std::uint32_t Engine<D, Queue>::applyRecord(const ParticleRecord& r) {
    DomainData& dom = *m_domain;
    const CellRole role = roleOfCell(r.cell);
    std::uint32_t s = dom.slots.find(r.id);
    if (role == CellRole::Foreign) {  // left this rank's cells and halo
        if (s != kNone) {
            if (realSlot(s)) --dom.owned;
            killSlot(s);
        }
        return kNone;
    }
    const bool wasReal = s != kNone && realSlot(s);
    if (s == kNone) {
        s = addSlot(r.id);
    } else {
        unlinkCell(s);
    }
    // Radii and masses stored once when equal: a migrant that differs gets per-slot arrays.
    if (m_radius.empty() && r.radius0 != m_uniformRadius) m_radius.assign(size(), m_uniformRadius);
    if (m_mass.empty() && r.mass != m_uniformMass) m_mass.assign(size(), m_uniformMass);
    setFromRecord(s, r);
    linkCell(s);
    if (role == CellRole::Halo) {
        if (wasReal) --dom.owned;
        m_queue.set(s, kNoEvent);
        dom.border.set(s, kNoEvent);
        return kNone;
    }
    if (!wasReal) ++dom.owned;
    return s;
}

template <int D, class Queue>
void Engine<D, Queue>::applyPending() {
    // Every record of one instant first, then the predictions (a collision executed by a
    // neighbour sends both partners' records; the prediction must see both).
    DomainData& dom = *m_domain;
    const Real t = dom.pending.front().record.tst;
    m_now = std::max(m_now, t);
    std::vector<std::uint32_t> predict;
    while (!dom.pending.empty() && dom.pending.front().record.tst == t) {
        std::pop_heap(dom.pending.begin(), dom.pending.end(), laterRecord<PendingRecord>);
        const ParticleRecord r = dom.pending.back().record;
        dom.pending.pop_back();
        const std::uint32_t s = applyRecord(r);
        if (s != kNone) predict.push_back(s);
    }
    for (const std::uint32_t s : predict)
        if (realSlot(s)) scheduleDomain(s);
}

template <int D, class Queue>
void Engine<D, Queue>::applyReceivedUntil(Real t) {
    while (m_domain && !m_domain->pending.empty() && m_domain->pending.front().record.tst <= t)
        applyPending();
}

template <int D, class Queue>
void Engine<D, Queue>::applyPendingInOrder(EventKey limit) {
    DomainData& dom = *m_domain;
    while (!dom.pending.empty()) {
        const EventKey up = pendingKey();
        if (!(up < topEventKey()) || !(up < limit)) break;
        applyPending();
    }
}

template <int D, class Queue>
std::uint64_t Engine<D, Queue>::runDomain(EventKey limit, EventKey stopAfterBorderFrom) {
    DomainData& dom = *m_domain;
    std::uint64_t done = 0;
    bool stopNow = false;
    for (;;) {
        if (stopNow) break;  // the announced border event was the last of this step (spec 3.8)
        const std::uint32_t i = size() > 0 ? m_queue.top() : 0;
        const EventKey ev = topEventKey();
        if (!dom.pending.empty()) {
            const EventKey up = pendingKey();
            if (up < ev) {
                if (!(up < limit)) break;
                applyPending();
                continue;
            }
        }
        if (!(ev < limit) || dom.stalled) break;
        if (m_stats.events >= dom.watchAt) {  // the serial engine's watchdog (run())
            if (dom.watchAt > 0 && !(ev.time - dom.watchTime > 1e-9 * std::abs(ev.time))) {
                dom.stalled = true;
                break;
            }
            dom.watchAt = m_stats.events + watchdogWindow();
            dom.watchTime = ev.time;
        }
        const Real t = ev.time;
        GL_ASSERT(t >= m_now && realSlot(i),
                  "edmd::Engine: domain event in the past or of a virtual particle");
        m_now = t;
        ++done;
        ++m_stats.events;
        const Event e = m_event[i];
        const CellCoords oldCell = m_cellOf[i];
        stopNow = dom.border.time(i) == t && !(ev < stopAfterBorderFrom);
        if (!dom.cellEvents.empty()) ++dom.cellEvents[cellIndex(oldCell)];  // the balancing's load
        if (e.partner < kMaxParticles) {
            const std::uint32_t j = e.partner;
            if (m_s[j].counter != e.partnerCounter) {  // annulled (spec 2.6)
                ++m_stats.annulled;
                advance(i, t);
                noteChange(i, oldCell);
                scheduleDomain(i);
                continue;
            }
            const CellCoords oldCellJ = m_cellOf[j];
            collide(i, j, t);  // a virtual partner too: its owner gets the record (spec 3.8 step 5)
            if (dom.collisionLog) dom.collisionLog->push_back(ev);
            noteChange(i, oldCell);
            noteChange(j, oldCellJ);
            scheduleDomain(i);
            if (realSlot(j)) scheduleDomain(j);
        } else if (e.partner >= kCellBase && e.partner != kNone) {
            advance(i, t);
            crossCell(i, e.partner - kCellBase);
            noteChange(i, oldCell);
            if (realSlot(i)) {
                scheduleDomain(i);
            } else {  // migrated into a neighbour's cell: a virtual copy here from now on
                --dom.owned;
                m_queue.set(i, kNoEvent);
                dom.border.set(i, kNoEvent);
            }
        } else if (e.partner >= kWallBase && e.partner < kCellBase) {
            collideWall(i, e.partner - kWallBase, t);
            noteChange(i, oldCell);
            scheduleDomain(i);
        } else {
            // A collision whose partner this rank no longer held when it was rebuilt from
            // records (kind 1, partner gone): that partner has collided since (a valid partner
            // stays within the 3^D cells), so the serial engine annuls the event here.
            ++m_stats.annulled;
            advance(i, t);
            noteChange(i, oldCell);
            scheduleDomain(i);
        }
    }
    return done;
}

#define GRANULAB_EDMD_DOMAIN_MEMBERS(D, Q)                                                 \
    template Engine<D, Q>::Engine(EngineConfig, const DomainLayout&, const EngineGlobals&, \
                                  std::vector<ParticleRecord>);                            \
    template std::vector<ParticleRecord> Engine<D, Q>::records(bool) const;                \
    template Engine<D, Q>::Engine(const Engine&);                                          \
    template Engine<D, Q>& Engine<D, Q>::operator=(const Engine&);                         \
    template EngineGlobals Engine<D, Q>::globals() const;                                  \
    template EventKey Engine<D, Q>::nextKey() const noexcept;                              \
    template EventKey Engine<D, Q>::nextBorderKey() const noexcept;                        \
    template std::uint64_t Engine<D, Q>::runDomain(EventKey, EventKey);                    \
    template bool Engine<D, Q>::receive(const ParticleRecord&);                            \
    template Real Engine<D, Q>::causalityError() const noexcept;                           \
    template void Engine<D, Q>::drainChanges(std::vector<Change>&);                        \
    template std::uint32_t Engine<D, Q>::ownedCount() const noexcept;                      \
    template void Engine<D, Q>::injectCausalityError(std::uint64_t) noexcept;              \
    template void Engine<D, Q>::setCollisionLog(std::vector<EventKey>*) noexcept;          \
    template void Engine<D, Q>::applyReceivedUntil(Real);                                  \
    template void Engine<D, Q>::applyPendingInOrder(EventKey);                             \
    template void Engine<D, Q>::takeCellEvents(std::vector<std::uint64_t>&);               \
    template void Engine<D, Q>::countCellEvents();                                         \
    template bool Engine<D, Q>::realSlot(std::uint32_t) const noexcept;                    \
    template std::size_t Engine<D, Q>::domainMemoryBytes() const noexcept;                 \
    template std::uint32_t Engine<D, Q>::reclaimDeadSlots();

GRANULAB_EDMD_DOMAIN_MEMBERS(2, AddressableHeap)
GRANULAB_EDMD_DOMAIN_MEMBERS(2, TournamentTree)
GRANULAB_EDMD_DOMAIN_MEMBERS(2, CalendarQueue)
GRANULAB_EDMD_DOMAIN_MEMBERS(3, AddressableHeap)
GRANULAB_EDMD_DOMAIN_MEMBERS(3, TournamentTree)
GRANULAB_EDMD_DOMAIN_MEMBERS(3, CalendarQueue)
#undef GRANULAB_EDMD_DOMAIN_MEMBERS

}  // namespace granulab::edmd
