// SPDX-License-Identifier: MIT
// The DEM domain decomposition (dem/parallel/domain_world.hpp; docs/physics/dem-mpi.md).
#include "dem/parallel/domain_world.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "core/timer.hpp"
#include "dem/parallel/domain_records.hpp"

namespace granulab::dem {

struct DomainWorld::Incoming {
    std::vector<ParticleRecord> owned, ghosts;
    std::vector<Real> ownedRows, ghostRows;  ///< integrator state, m_integratorColumns per record
    std::vector<IdHistory> pairs, walls;

    ByteBuffer message() const {
        MessageWriter w;
        w.put(owned);
        w.put(ownedRows);
        w.put(ghosts);
        w.put(ghostRows);
        w.put(pairs);
        w.put(walls);
        return w.take();
    }
    /// Appends `other` (this rank's share to itself, which skips the message).
    void append(Incoming&& other) {
        const auto add = [](auto& to, auto& from) { to.insert(to.end(), from.begin(), from.end()); };
        add(owned, other.owned);
        add(ownedRows, other.ownedRows);
        add(ghosts, other.ghosts);
        add(ghostRows, other.ghostRows);
        add(pairs, other.pairs);
        add(walls, other.walls);
    }
    /// Appends what `bytes` (a message()) holds.
    void append(const ByteBuffer& bytes) {
        MessageReader rd(bytes);
        rd.appendTo(owned);
        rd.appendTo(ownedRows);
        rd.appendTo(ghosts);
        rd.appendTo(ghostRows);
        rd.appendTo(pairs);
        rd.appendTo(walls);
    }
};

DomainWorld::DomainWorld(Communicator& comm, World whole, DomainConfig config, const SlabPartition* cuts)
    : m_comm(comm), m_world(std::move(whole)), m_config(config) {
    const model::ParticleStore& s = m_world.store();
    const int ranks = comm.size(), me = comm.rank();
    m_particles = s.size();
    m_world.setExternalFlow(true);
    m_world.setFieldCommunicator(&comm);  // voidage cells and all-pairs attraction gather from every rank
    if (me != 0) {  // removals are booked by the rank that removes, and summed: start from the root's
        FlowCounters& c = m_world.flowForDomain().countersForDomain();
        std::fill(c.outletRemoved.begin(), c.outletRemoved.end(), 0);
        std::fill(c.outletMass.begin(), c.outletMass.end(), 0.0);
        c.removed = 0;
        c.massOut = 0;
    }
    const StateColumns* state = m_world.integratorState();
    m_integratorColumns = state ? state->columns.size() : 0;
    m_owned = s.size();  // every particle, for the first weights
    // The extent of the particles and the walls (a scene that sources fill starts empty).
    Real lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    const auto extend = [&](Vec2 p) {
        lo[0] = std::min(lo[0], p.x);
        hi[0] = std::max(hi[0], p.x);
        lo[1] = std::min(lo[1], p.y);
        hi[1] = std::max(hi[1], p.y);
    };
    for (std::size_t k = 0; k < s.size(); ++k) extend({s.x[k], s.y[k]});
    for (const auto& seg : m_world.walls().segments) {
        extend(seg.a);
        extend(seg.b);
    }
    for (const auto& src : m_world.flow().config().sources) extend(src.position);
    if (!(hi[0] >= lo[0])) lo[0] = hi[0] = lo[1] = hi[1] = 0;  // nothing at all
    // Slabs across the longer extent.
    const int axis = cuts && cuts->ranks() == ranks ? cuts->axis : (hi[1] - lo[1] > hi[0] - lo[0] ? 1 : 0);
    if (cuts && cuts->ranks() == ranks) {
        m_partition = *cuts;
    } else if (m_config.balance && ranks > 1) {
        // Every rank holds every particle: the root's alone make the histogram.
        const std::vector<Real> weights = me == 0 ? workWeights() : std::vector<Real>{};
        const std::vector<Real>& coords = axis == 0 ? s.x : s.y;
        m_partition =
            balancedSlabs(comm, axis, std::span<const Real>(coords.data(), me == 0 ? coords.size() : 0),
                          weights, lo[axis], hi[axis]);
    } else {
        m_partition = uniformSlabs(axis, lo[axis], hi[axis], ranks);
    }
    const Real halo = haloWidth();
    const std::size_t k = m_integratorColumns;
    std::vector<Real> row(k);
    Incoming in;
    std::vector<char> kept(s.size(), 0);
    for (std::size_t i = 0; i < s.size(); ++i) {
        const Real c = axis == 0 ? s.x[i] : s.y[i];
        const int owner = m_partition.owner(c);
        bool ghost = false;
        if (owner != me) m_partition.forGhostRanks(c, halo, owner, [&](int r) { ghost = ghost || r == me; });
        if (owner != me && !ghost) continue;
        kept[i] = 1;
        if (state) state->copyRow(i, row.data());
        (owner == me ? in.owned : in.ghosts).push_back(recordOf(s, i, owner));
        auto& rows = owner == me ? in.ownedRows : in.ghostRows;
        rows.insert(rows.end(), row.begin(), row.end());
    }
    bool lowerIsFirst = true;
    for (const PairHistory& h : NeighborList::historyOf(m_world.neighbors().pairs))
        if (kept[keyFirst(h.key)] && kept[keySecond(h.key)])
            in.pairs.push_back(pairHistoryById(s, h, true, lowerIsFirst));
    for (const PairHistory& h : NeighborList::historyOf(m_world.neighbors().wallPairs))
        if (kept[keyFirst(h.key)]) in.walls.push_back(wallHistoryById(s, h));
    assemble(std::move(in), false);
    measureDomains();
    // A piston's controller reads the total force on its wall at every step; other walls' forces
    // are summed for outputs only.
    for (const auto& w : m_world.walls().walls)
        m_sumWallsEveryStep = m_sumWallsEveryStep || w.driver.kind == model::WallDriver::Kind::Piston;
}

std::vector<Real> DomainWorld::workWeights() const {
    std::vector<Real> w(m_owned, 1.0);
    const NeighborList& list = m_world.neighbors();
    for (std::size_t p = 0; p < list.pairs.size(); ++p) {
        if (list.pairs.first[p] < m_owned) w[list.pairs.first[p]] += 1;
        if (list.pairs.second[p] < m_owned) w[list.pairs.second[p]] += 1;
    }
    for (std::size_t p = 0; p < list.wallPairs.size(); ++p)
        if (list.wallPairs.first[p] < m_owned) w[list.wallPairs.first[p]] += 1;
    return w;
}

void DomainWorld::measureDomains() {
    m_weights = workWeights();
    const double mine[3] = {std::accumulate(m_weights.begin(), m_weights.end(), 0.0),
                            static_cast<double>(m_stats.owned), static_cast<double>(m_stats.ghosts)};
    const std::vector<double> all = m_comm.allGather(std::span<const double>(mine, 3));
    double most = 0, total = 0, owned = 0, ghosts = 0;
    for (std::size_t r = 0; r < all.size() / 3; ++r) {
        most = std::max(most, all[3 * r]);
        total += all[3 * r];
        owned += all[3 * r + 1];
        ghosts += all[3 * r + 2];
    }
    const double mean = total / static_cast<double>(m_comm.size());
    m_stats.imbalance = mean > 0 ? most / mean : 1.0;
    m_particles = static_cast<std::size_t>(owned);
    m_stats.haloShare = owned > 0 ? ghosts / owned : 0.0;
}

void DomainWorld::assemble(Incoming in, bool countAsBuild) {
    const int axis = m_partition.axis;
    const Real halo = haloWidth();
    const std::size_t k = m_integratorColumns;
    // Owned particles along a Z curve of halo-sized cells (compact tiles), ghosts by owner and id.
    Real lo[2] = {1e300, 1e300};
    for (const ParticleRecord& r : in.owned) {
        lo[0] = std::min(lo[0], r.x);
        lo[1] = std::min(lo[1], r.y);
    }
    std::vector<std::pair<std::uint64_t, std::uint32_t>> order(in.owned.size());
    for (std::size_t i = 0; i < in.owned.size(); ++i) {
        const auto cell = [&](Real v, Real from) {  // 16 bits: the code fits the upper half of the key
            return static_cast<std::uint32_t>(std::clamp<Real>((v - from) / halo, 0, 65535));
        };
        const std::uint64_t key = mortonCode(cell(in.owned[i].x, lo[0]), cell(in.owned[i].y, lo[1]));
        order[i] = {key << 32 | in.owned[i].id, static_cast<std::uint32_t>(i)};
    }
    std::sort(order.begin(), order.end());
    std::vector<std::uint32_t> ghostOrder(in.ghosts.size());
    std::iota(ghostOrder.begin(), ghostOrder.end(), 0u);
    std::sort(ghostOrder.begin(), ghostOrder.end(), [&](std::uint32_t p, std::uint32_t q) {
        const ParticleRecord &a = in.ghosts[p], &b = in.ghosts[q];
        return a.owner != b.owner ? a.owner < b.owner : a.id < b.id;
    });
    model::ParticleStore store = storeOfSize(in.owned.size() + in.ghosts.size());
    std::vector<Real> rows((in.owned.size() + in.ghosts.size()) * k);
    std::size_t slot = 0;
    const auto place = [&](const ParticleRecord& r, const std::vector<Real>& from, std::size_t i) {
        setRecord(store, slot, r);
        std::copy_n(from.begin() + static_cast<std::ptrdiff_t>(i * k), k,
                    rows.begin() + static_cast<std::ptrdiff_t>(slot * k));
        ++slot;
    };
    for (const auto& [key, i] : order) place(in.owned[i], in.ownedRows, i);
    const int ranks = m_comm.size();
    m_ghostBegin.assign(static_cast<std::size_t>(ranks) + 1, 0);
    for (const std::uint32_t i : ghostOrder) {
        place(in.ghosts[i], in.ghostRows, i);
        ++m_ghostBegin[static_cast<std::size_t>(in.ghosts[i].owner) + 1];
    }
    m_owned = in.owned.size();
    m_ghostBegin[0] = static_cast<std::uint32_t>(m_owned);
    for (int r = 0; r < ranks; ++r) m_ghostBegin[r + 1] += m_ghostBegin[r];
    const SlotOfId slotOfId(store);
    std::vector<PairHistory> pairs = pairHistoryInSlots(std::move(in.pairs), slotOfId);
    std::vector<PairHistory> walls = wallHistoryInSlots(in.walls, slotOfId);
    // Which ranks keep each owned particle as a ghost (the same rule the sender applied).
    m_sendSlots.assign(static_cast<std::size_t>(ranks), {});
    for (std::uint32_t i = 0; i < m_owned; ++i)
        m_partition.forGhostRanks(axis == 0 ? store.x[i] : store.y[i], halo, m_comm.rank(),
                                  [&](int r) { m_sendSlots[static_cast<std::size_t>(r)].push_back(i); });
    for (auto& slots : m_sendSlots)
        std::sort(slots.begin(), slots.end(),
                  [&](std::uint32_t p, std::uint32_t q) { return store.id[p] < store.id[q]; });
    m_stats.owned = m_owned;
    m_stats.ghosts = store.size() - m_owned;
    m_world.replaceParticles(std::move(store), rows, pairs, walls, m_owned, countAsBuild);
}

void DomainWorld::exchange(bool mayBalance) {
    exchangeWithFlow({}, {}, 0, mayBalance);
}

void DomainWorld::exchangeWithFlow(const std::vector<std::uint32_t>& leaving,
                                   const std::vector<NewParticle>& entering, ParticleId firstId,
                                   bool mayBalance) {
    const double started = wallSeconds();
    const int ranks = m_comm.size();
    const model::ParticleStore& s = m_world.store();
    // The work measured after the last exchange decides: the lists, and so the weights, are
    // those of that exchange.
    if (mayBalance && m_config.balance && ranks > 1) {
        if (m_stats.imbalance > m_config.balanceTrigger) {
            const std::vector<Real>& coords = m_partition.axis == 0 ? s.x : s.y;
            m_partition =
                balancedSlabs(m_comm, m_partition.axis, std::span<const Real>(coords.data(), m_owned),
                              m_weights, m_partition.lower(1), m_partition.upper(ranks - 2));
            ++m_stats.rebalances;
        }
    }
    const Real halo = haloWidth();
    const std::size_t k = m_integratorColumns;
    std::vector<Incoming> out(static_cast<std::size_t>(ranks));
    // Destinations of every owned particle: its new owner first, then the ranks keeping a ghost.
    std::vector<std::uint32_t> destBegin(m_owned + 1, 0);
    std::vector<int> dests;
    std::vector<Real> row(k);
    const auto send = [&](const ParticleRecord& record, std::size_t slot) {
        const Real c = m_partition.axis == 0 ? record.x : record.y;
        const int owner = m_partition.owner(c);
        ParticleRecord rec = record;
        rec.owner = owner;
        auto& mine = out[static_cast<std::size_t>(owner)];
        mine.owned.push_back(rec);
        mine.ownedRows.insert(mine.ownedRows.end(), row.begin(), row.end());
        dests.push_back(owner);
        m_partition.forGhostRanks(c, halo, owner, [&](int r) {
            auto& theirs = out[static_cast<std::size_t>(r)];
            theirs.ghosts.push_back(rec);
            theirs.ghostRows.insert(theirs.ghostRows.end(), row.begin(), row.end());
            dests.push_back(r);
        });
        if (slot < m_owned) destBegin[slot + 1] = static_cast<std::uint32_t>(dests.size());
    };
    const StateColumns* state = m_world.integratorState();
    std::size_t gone = 0;  // leaving is ascending
    for (std::size_t i = 0; i < m_owned; ++i) {
        if (gone < leaving.size() && leaving[gone] == i) {  // through an outlet: sent nowhere
            ++gone;
            destBegin[i + 1] = static_cast<std::uint32_t>(dests.size());
            continue;
        }
        if (state) state->copyRow(i, row.data());
        send(recordOf(s, i, 0), i);
    }
    // New particles: created by the rank whose slab holds them (every rank has the same list),
    // as a one-rank run inserts them: radius and inertia at the current size scale, its weight
    // as the force until the next evaluation, integrator state zero.
    std::fill(row.begin(), row.end(), 0.0);
    const Real scale = m_world.sizeScale();
    const Vec2 g = m_world.gravity();
    for (std::size_t k = 0; k < entering.size(); ++k) {
        const NewParticle& p = entering[k];
        if (m_partition.owner(m_partition.axis == 0 ? p.position.x : p.position.y) != m_comm.rank()) continue;
        const Real inertia = p.inertia * scale * scale;
        const ParticleRecord rec{p.position.x,
                                 p.position.y,
                                 p.velocity.x,
                                 p.velocity.y,
                                 p.angle,
                                 p.omega,
                                 p.mass * g.x,
                                 p.mass * g.y,
                                 0.0,
                                 p.radius * scale,
                                 p.mass,
                                 p.mass > 0 ? 1.0 / p.mass : 0.0,
                                 inertia > 0 ? 1.0 / inertia : 0.0,
                                 firstId + static_cast<ParticleId>(k),
                                 p.material,
                                 p.shape,
                                 0};
        send(rec, m_owned);  // no old slot: no history
    }
    // A pair's history goes wherever one of its owned particles goes (the receiver keeps it when
    // it holds both); a wall pair's goes with its particle to the new owner.
    std::vector<int> targets;
    bool lowerIsFirst = true;
    for (const PairHistory& h : NeighborList::historyOf(m_world.neighbors().pairs)) {
        const std::uint32_t a = keyFirst(h.key), b = keySecond(h.key);
        targets.clear();
        for (const std::uint32_t slot : {a, b})
            if (slot < m_owned)
                targets.insert(targets.end(), dests.begin() + destBegin[slot],
                               dests.begin() + destBegin[slot + 1]);
        std::sort(targets.begin(), targets.end());
        targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
        IdHistory r = pairHistoryById(s, h, false, lowerIsFirst);
        r.fromOwnerOfA = (lowerIsFirst ? a : b) < m_owned ? 1 : 0;
        for (const int t : targets) out[static_cast<std::size_t>(t)].pairs.push_back(r);
    }
    for (const PairHistory& h : NeighborList::historyOf(m_world.neighbors().wallPairs)) {
        const std::uint32_t a = keyFirst(h.key);
        if (a < m_owned)
            out[static_cast<std::size_t>(dests[destBegin[a]])].walls.push_back(wallHistoryById(s, h));
    }
    const auto me = static_cast<std::size_t>(m_comm.rank());
    std::vector<ByteBuffer> messages(static_cast<std::size_t>(ranks));
    for (std::size_t r = 0; r < messages.size(); ++r)
        if (r != me) messages[r] = out[r].message();
    const std::vector<ByteBuffer> received = m_comm.allToAll(std::move(messages));
    Incoming in;  // in rank order, this rank's own share without a message
    for (std::size_t r = 0; r < received.size(); ++r) {
        if (r == me)
            in.append(std::move(out[r]));
        else
            in.append(received[r]);
    }
    out.clear();
    assemble(std::move(in), true);
    ++m_stats.exchanges;
    // The work after the exchange, and the halo's share of all particles.
    measureDomains();
    m_stats.imbalanceSum += m_stats.imbalance;
    m_stats.exchangeSeconds += wallSeconds() - started;
}

void DomainWorld::updateHalo() {
    const int ranks = m_comm.size();
    if (ranks == 1) return;
    const double started = wallSeconds();
    const std::size_t k = m_integratorColumns, per = 6 + k;
    model::ParticleStore& s = m_world.storeForHalo();
    StateColumns* state = m_world.integratorStateForHalo();
    // Point to point, to the neighbouring slabs only: rank r keeps ghosts of this rank exactly
    // when this rank has slots to send to it (the same rule on both sides).
    std::vector<Real> values;
    for (int r = 0; r < ranks; ++r) {
        const auto& slots = m_sendSlots[static_cast<std::size_t>(r)];
        if (slots.empty()) continue;
        values.resize(slots.size() * per);
        Real* v = values.data();
        for (const std::uint32_t i : slots) {
            v[0] = s.x[i];
            v[1] = s.y[i];
            v[2] = s.vx[i];
            v[3] = s.vy[i];
            v[4] = s.angle[i];
            v[5] = s.omega[i];
            if (state) state->copyRow(i, v + 6);
            v += per;
        }
        m_comm.send(r, kHaloTag, packPod(std::span<const Real>(values)));
    }
    std::vector<Real> in;
    for (int r = 0; r < ranks; ++r) {
        const std::uint32_t begin = m_ghostBegin[static_cast<std::size_t>(r)];
        const std::uint32_t end = m_ghostBegin[static_cast<std::size_t>(r) + 1];
        if (begin == end) continue;
        in.clear();
        unpackPod(m_comm.receive(r, kHaloTag), in);
        if (in.size() != (end - begin) * per)
            throw std::logic_error("halo update: a rank sent another number of ghosts than it owns here");
        const Real* v = in.data();
        for (std::uint32_t g = begin; g < end; ++g, v += per) {
            s.x[g] = v[0];
            s.y[g] = v[1];
            s.vx[g] = v[2];
            s.vy[g] = v[3];
            s.angle[g] = v[4];
            s.omega[g] = v[5];
            if (state) state->setRow(g, v + 6);
        }
    }
    m_stats.haloSeconds += wallSeconds() - started;
}

std::uint32_t DomainWorld::step(bool stop) {
    m_stepped = true;
    std::uint32_t status = m_world.beginStep();
    updateHalo();
    double started = wallSeconds();
    // The one reduction of a step: whether any rank must rebuild, every rank's flags of this
    // step's first part and of the last step's forces (a deep overlap), and a stop request.
    double flags[6] = {m_world.neighborsStale() ? 1.0 : 0.0,
                       (status & kStepNonFinite) ? 1.0 : 0.0,
                       (status & kStepTunnelling) ? 1.0 : 0.0,
                       (status & kStepFieldFailed) ? 1.0 : 0.0,
                       stop ? 1.0 : 0.0,
                       m_deepOverlap ? 1.0 : 0.0};
    m_comm.allMax(flags);
    m_stats.reduceSeconds += wallSeconds() - started;
    m_stopRequested = flags[4] > 0;
    m_deepOverlap = false;
    status = (flags[1] > 0 ? kStepNonFinite : 0u) | (flags[2] > 0 ? kStepTunnelling : 0u) |
             (flags[3] > 0 ? kStepFieldFailed : 0u) | (flags[5] > 0 ? kStepDeepOverlap : 0u);
    if (status & (kStepFieldFailed | kStepDeepOverlap)) return status;
    if (flags[0] > 0) exchange();
    // A deep overlap is reported with the next step's reduction (or by settle()).
    m_deepOverlap = (m_world.finishStep(this) & kStepDeepOverlap) != 0;
    // Particles leave through this rank's outlets; sources and inlets place theirs against all.
    std::vector<std::uint32_t> leaving;
    std::vector<NewParticle> entering;
    const bool flow = m_world.flow().active();
    if (flow) {
        leaving = m_world.flowLeaving();
        if (m_world.flow().insertionDue(m_world.time(), m_world.config().dt))
            entering = m_world.flowEntering(everyParticle());
    }
    const bool outlets = flow && !m_world.flow().config().outlets.empty();
    if (m_sumWallsEveryStep || outlets) {  // a sum at the end of the step only when needed
        started = wallSeconds();
        std::vector<Vec2>& wallForce = m_world.wallForceForSum();
        std::vector<double> sums(2 * wallForce.size() + 1);
        for (std::size_t w = 0; w < wallForce.size(); ++w) {
            sums[2 * w] = wallForce[w].x;
            sums[2 * w + 1] = wallForce[w].y;
        }
        sums.back() = static_cast<double>(leaving.size());
        m_comm.allSum(sums);
        if (m_sumWallsEveryStep)
            for (std::size_t w = 0; w < wallForce.size(); ++w) wallForce[w] = {sums[2 * w], sums[2 * w + 1]};
        m_anyLeft = sums.back() > 0;
        m_stats.reduceSeconds += wallSeconds() - started;
    } else {
        m_anyLeft = false;
    }
    if (m_anyLeft || !entering.empty()) {
        const ParticleId firstId = m_world.admitParticles(entering);
        exchangeWithFlow(leaving, entering, firstId);
        if (m_anyLeft) {  // the smallest radius of what stays (tunnelling guard)
            double smallest = 1e300;
            const auto& r = m_world.store().radius;
            for (std::size_t i = 0; i < m_owned; ++i) smallest = std::min(smallest, r[i]);
            m_comm.allMin(std::span<double>(&smallest, 1));
            m_world.setMinRadius(smallest);
        }
    }
    return status;
}

bool DomainWorld::agree(bool acceptedHere) {
    double notAccepted = acceptedHere ? 0.0 : 1.0;
    m_comm.allMax(std::span<double>(&notAccepted, 1));
    if (notAccepted > 0) updateHalo();
    return notAccepted == 0;
}

std::uint32_t DomainWorld::settle() {
    double deep = m_deepOverlap ? 1.0 : 0.0;
    m_comm.allMax(std::span<double>(&deep, 1));
    m_deepOverlap = false;
    return deep > 0 ? kStepDeepOverlap : kStepOk;
}

model::ParticleStore DomainWorld::everyParticle() {
    struct Light {
        Real x, y, vx, vy, radius;
        ParticleId id;
    };
    const model::ParticleStore& s = m_world.store();
    std::vector<Light> mine(m_owned);
    for (std::size_t i = 0; i < m_owned; ++i)
        mine[i] = {s.x[i], s.y[i], s.vx[i], s.vy[i], s.radius[i], s.id[i]};
    std::vector<Light> all = allGatherPod(m_comm, std::span<const Light>(mine));
    std::sort(all.begin(), all.end(), [](const Light& a, const Light& b) { return a.id < b.id; });
    model::ParticleStore every;
    every.reserve(all.size());
    for (const Light& l : all) {
        every.x.push_back(l.x);
        every.y.push_back(l.y);
        every.vx.push_back(l.vx);
        every.vy.push_back(l.vy);
        every.radius.push_back(l.radius);
        every.id.push_back(l.id);
    }
    return every;  // only these columns: what placement reads
}

std::size_t DomainWorld::memoryBytes() {
    std::uint64_t bytes = m_world.memoryBytes();
    m_comm.allSum(std::span<std::uint64_t>(&bytes, 1));
    return static_cast<std::size_t>(bytes);
}

void DomainWorld::gather(World& copy) {
    const model::ParticleStore& s = m_world.store();
    const std::size_t k = m_integratorColumns;
    const StateColumns* state = m_world.integratorState();
    Incoming mine;
    std::vector<Real> row(k);
    for (std::size_t i = 0; i < m_owned; ++i) {
        mine.owned.push_back(recordOf(s, i, m_comm.rank()));
        if (state) state->copyRow(i, row.data());
        mine.ownedRows.insert(mine.ownedRows.end(), row.begin(), row.end());
    }
    bool lowerIsFirst = true;
    for (const PairHistory& h : NeighborList::historyOf(m_world.neighbors().pairs)) {
        const IdHistory r = pairHistoryById(s, h, true, lowerIsFirst);
        if ((lowerIsFirst ? keyFirst(h.key) : keySecond(h.key)) < m_owned) mine.pairs.push_back(r);  // once
    }
    for (const PairHistory& h : NeighborList::historyOf(m_world.neighbors().wallPairs))
        mine.walls.push_back(wallHistoryById(s, h));
    // Removals are booked by the rank that removed: summed (the other counters agree everywhere).
    const FlowCounters& mineCounted = m_world.flow().counters();
    std::vector<double> removed(mineCounted.outletRemoved.begin(), mineCounted.outletRemoved.end());
    removed.insert(removed.end(), mineCounted.outletMass.begin(), mineCounted.outletMass.end());
    removed.push_back(static_cast<double>(mineCounted.removed));
    removed.push_back(mineCounted.massOut);
    m_comm.allSum(removed);
    std::vector<double> wallSums;  // this rank's contacts on each wall, of the last step
    for (const Vec2& f : m_world.wallForceForSum()) {
        wallSums.push_back(f.x);
        wallSums.push_back(f.y);
    }
    if (!m_sumWallsEveryStep) m_comm.allSum(wallSums);
    // The fluid statistics of the ranks' last evaluation (their owned particles), as one process
    // reports them; the copy's output evaluation would see the state after the step instead.
    const FluidStats& fluid = m_world.fluidStats();
    double fluidSums[3] = {fluid.drag.x, fluid.drag.y, static_cast<double>(fluid.outside)};
    double fluidMax[2] = {fluid.maxReynolds, -fluid.minVoidage};
    m_comm.allSum(fluidSums);
    m_comm.allMax(fluidMax);
    const std::vector<ByteBuffer> all = m_comm.gather(mine.message());
    if (!m_comm.root()) return;
    Incoming in;
    for (const ByteBuffer& bytes : all) in.append(bytes);
    std::vector<std::uint32_t> order(in.owned.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t p, std::uint32_t q) { return in.owned[p].id < in.owned[q].id; });
    model::ParticleStore store = storeOfSize(order.size());
    std::vector<Real> rows(order.size() * k);
    for (std::size_t slot = 0; slot < order.size(); ++slot) {
        const std::uint32_t i = order[slot];
        setRecord(store, slot, in.owned[i]);
        std::copy_n(in.ownedRows.begin() + static_cast<std::ptrdiff_t>(i * k), k,
                    rows.begin() + static_cast<std::ptrdiff_t>(slot * k));
    }
    const SlotOfId slotOfId(store);
    const std::vector<PairHistory> pairs = pairHistoryInSlots(std::move(in.pairs), slotOfId);
    const std::vector<PairHistory> walls = wallHistoryInSlots(in.walls, slotOfId);
    copy.adoptClock(m_world);
    FlowCounters& counted = copy.flowForDomain().countersForDomain();
    const std::size_t outlets = counted.outletRemoved.size();
    for (std::size_t o = 0; o < outlets; ++o) {
        counted.outletRemoved[o] = static_cast<std::uint64_t>(removed[o]);
        counted.outletMass[o] = removed[outlets + o];
    }
    counted.removed = static_cast<std::uint64_t>(removed[2 * outlets]);
    counted.massOut = removed[2 * outlets + 1];
    std::vector<Vec2>& wallForce = copy.wallForceForSum();
    for (std::size_t k = 0; k < wallForce.size(); ++k) wallForce[k] = {wallSums[2 * k], wallSums[2 * k + 1]};
    const std::size_t n = store.size();
    copy.replaceParticles(std::move(store), rows, pairs, walls, n, false, true);
    copy.evaluateForOutput();
    if (copy.field() && m_stepped) {  // before the first step, the whole world's (the copy's own)
        FluidStats reduced;
        reduced.drag = {fluidSums[0], fluidSums[1]};
        reduced.outside = static_cast<std::uint64_t>(fluidSums[2]);
        reduced.maxReynolds = fluidMax[0];
        reduced.minVoidage = -fluidMax[1];
        copy.setFluidStats(reduced);
    }
}

}  // namespace granulab::dem
