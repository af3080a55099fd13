// SPDX-License-Identifier: MIT
// Serial event-driven engine (edmd spec sections 2.1-2.8, 2.10): event loop, event computation
// over the 3^D neighbour cells, cell crossings with periodic wrap, wall collisions, annulled
// collisions, growing spheres with re-gridding, checkpoints.
#include "edmd/engine.hpp"

#include <algorithm>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>

#include "core/binary_io.hpp"

namespace granulab::edmd {

namespace {
constexpr std::uint32_t kNone = 0xFFFFFFFFu;

Vec3 lift(const VecD<2>& a) noexcept { return {{a[0], a[1], 0}}; }
Vec3 lift(const VecD<3>& a) noexcept { return a; }
template <int D>
VecD<D> lower(const Vec3& a) noexcept {
    VecD<D> r;
    for (int d = 0; d < D; ++d) r[d] = a[d];
    return r;
}
}  // namespace

template <int D, class Queue>
Engine<D, Queue>::Engine(EngineConfig config, std::vector<V> x, std::vector<V> v, std::vector<Real> radius,
                         std::vector<Real> mass)
    : m_config(config), m_mass(std::move(mass)) {
    const auto n = static_cast<std::uint32_t>(x.size());
    if (v.size() != n || radius.size() != n || m_mass.size() != n)
        throw std::invalid_argument("edmd::Engine: position, velocity, radius and mass counts differ");
    for (int d = 0; d < D; ++d)
        if (!(m_config.box[d] > 0)) throw std::invalid_argument("edmd::Engine: box edges must be positive");
    if (m_config.growthRate != 0)
        for (int d = 0; d < D; ++d)
            if (!m_config.periodic[d]) throw std::invalid_argument("edmd::Engine: growing spheres need a periodic box");
    m_s.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) m_s[i] = {x[i], v[i], 0.0, radius[i]};
    m_maxRadius0 = n ? *std::max_element(radius.begin(), radius.end()) : 0;
    for (int d = 0; d < D; ++d) m_gravity = m_gravity || m_config.gravity[d] != 0;
    if (m_config.rough()) m_omega.assign(n, Vec3{});
    m_counter.assign(n, 0);
    if (m_config.tc > 0) m_lastCollision.assign(n, -kNoEvent);
    m_event.assign(n, Event{});
    buildCells();
    rescheduleAll();
}

template <int D, class Queue>
void Engine<D, Queue>::buildCells() {
    const auto n = size();
    const Real amax = m_maxRadius0 + std::max<Real>(0, m_config.growthRate * m_now);
    // Default edge (spec 2.4): C/N ~ 1.5 (2D) or ~8 (3D) at low density, else the diameter.
    Real volume = 1;
    for (int d = 0; d < D; ++d) volume *= m_config.box[d];
    const Real cellsPerParticle = D == 2 ? 1.5 : 8.0;
    const Real lowDensityEdge = n ? std::pow(volume / (cellsPerParticle * n), 1.0 / D) : 0;
    // Growing spheres: a hair above the diameter, so that a re-grid always lowers the cell count.
    const Real diameter = 2 * amax * (m_config.growthRate > 0 ? 1 + 1e-9 : 1);
    Real smallestPeriodicEdge = kNoEvent;
    for (int d = 0; d < D; ++d)
        if (m_config.periodic[d]) smallestPeriodicEdge = std::min(smallestPeriodicEdge, m_config.box[d]);
    const Real edge = std::max({m_config.cellSize, diameter, std::min(lowDensityEdge, smallestPeriodicEdge / 3)});
    std::size_t cellCount = 1;
    for (int d = 0; d < D; ++d) {
        const Real L = m_config.box[d];
        int cells = edge > 0 ? static_cast<int>(std::min<Real>(std::floor(L / edge), 1 << 20)) : 1;
        if (m_config.periodic[d] && cells < 3)
            throw std::invalid_argument("edmd::Engine: a periodic axis must hold at least 3 cells of one diameter "
                                        "(box edge " + std::to_string(L) + " m, diameter " + std::to_string(2 * amax) + " m)");
        cells = std::max(cells, 1);
        m_cells[d] = cells;
        m_cellEdge[d] = L / cells;
        m_invCellEdge[d] = cells / L;
        cellCount *= static_cast<std::size_t>(cells);
    }
    if (cellCount >= kNone) throw std::invalid_argument("edmd::Engine: too many cells; raise edmd.cell_size");
    // Growing spheres outgrow the cells when 2 a_max(t) exceeds the smallest edge.
    m_regridTime = kNoEvent;
    if (m_config.growthRate > 0) {
        Real minEdge = kNoEvent;
        for (int d = 0; d < D; ++d) minEdge = std::min(minEdge, m_cellEdge[d]);
        m_regridTime = (0.5 * minEdge - m_maxRadius0) / m_config.growthRate;
    }
    m_head.assign(cellCount, kNone);
    m_cell.assign(n, 0);
    m_next.assign(n, kNone);
    m_prev.assign(n, kNone);
    for (std::uint32_t i = 0; i < n; ++i) {
        int c[D];
        for (int d = 0; d < D; ++d)
            c[d] = std::clamp(static_cast<int>(std::floor(m_s[i].x[d] * m_invCellEdge[d])), 0, m_cells[d] - 1);
        insertIntoCell(i, cellIndex(c));
    }
}

template <int D, class Queue>
void Engine<D, Queue>::rescheduleAll() noexcept {
    m_queue.reset(size());
    for (std::uint32_t i = 0; i < size(); ++i) schedule(i);
}

template <int D, class Queue>
void Engine<D, Queue>::regrid() {
    for (std::uint32_t i = 0; i < size(); ++i) advance(i, m_now);
    buildCells();
    rescheduleAll();
    ++m_stats.regrids;
}

template <int D, class Queue>
std::uint32_t Engine<D, Queue>::cellIndex(const int c[D]) const noexcept {
    std::uint32_t k = 0;
    for (int d = D - 1; d >= 0; --d) k = k * static_cast<std::uint32_t>(m_cells[d]) + static_cast<std::uint32_t>(c[d]);
    return k;
}

template <int D, class Queue>
void Engine<D, Queue>::cellCoords(std::uint32_t i, int c[D]) const noexcept {
    std::uint32_t k = m_cell[i];
    for (int d = 0; d < D; ++d) {
        c[d] = static_cast<int>(k % static_cast<std::uint32_t>(m_cells[d]));
        k /= static_cast<std::uint32_t>(m_cells[d]);
    }
}

template <int D, class Queue>
void Engine<D, Queue>::insertIntoCell(std::uint32_t i, std::uint32_t cell) noexcept {
    m_cell[i] = cell;
    m_prev[i] = kNone;
    m_next[i] = m_head[cell];
    if (m_head[cell] != kNone) m_prev[m_head[cell]] = i;
    m_head[cell] = i;
}

template <int D, class Queue>
void Engine<D, Queue>::removeFromCell(std::uint32_t i) noexcept {
    if (m_prev[i] != kNone) m_next[m_prev[i]] = m_next[i];
    else m_head[m_cell[i]] = m_next[i];
    if (m_next[i] != kNone) m_prev[m_next[i]] = m_prev[i];
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::minimumImage(V d) const noexcept {
    for (int k = 0; k < D; ++k) {
        if (!m_config.periodic[k]) continue;
        const Real L = m_config.box[k];
        if (d[k] > 0.5 * L) d[k] -= L;
        else if (d[k] < -0.5 * L) d[k] += L;
    }
    return d;
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::separation(std::uint32_t i, std::uint32_t j) const noexcept {
    return minimumImage(positionNow(i) - positionNow(j));
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::positionNow(std::uint32_t i) const noexcept {
    const State& p = m_s[i];
    const Real dt = m_now - p.tst;
    V x = p.x + p.v * dt;
    for (int d = 0; d < D; ++d) {
        x[d] += 0.5 * m_config.gravity[d] * dt * dt;
        if (m_config.periodic[d]) {
            if (x[d] < 0) x[d] += m_config.box[d];
            else if (x[d] >= m_config.box[d]) x[d] -= m_config.box[d];
        }
    }
    return x;
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::velocityNow(std::uint32_t i) const noexcept {
    V v = m_s[i].v;
    if (m_gravity)
        for (int d = 0; d < D; ++d) v[d] += m_config.gravity[d] * (m_now - m_s[i].tst);
    return v;
}

template <int D, class Queue>
void Engine<D, Queue>::advance(std::uint32_t i, Real t) noexcept {  // free flight, edmd Eq. 2.2-2.4
    State& p = m_s[i];
    const Real dt = t - p.tst;
    p.x = p.x + p.v * dt;
    if (m_gravity)
        for (int d = 0; d < D; ++d) {
            p.x[d] += 0.5 * m_config.gravity[d] * dt * dt;
            p.v[d] += m_config.gravity[d] * dt;
        }
    p.tst = t;
}

template <int D, class Queue>
void Engine<D, Queue>::schedule(std::uint32_t i) noexcept {
    const bool growing = m_config.growthRate != 0;
    if (m_gravity) growing ? scheduleImpl<true, true>(i) : scheduleImpl<true, false>(i);
    else growing ? scheduleImpl<false, true>(i) : scheduleImpl<false, false>(i);
}

template <int D, class Queue>
template <bool Gravity, bool Growing>
void Engine<D, Queue>::scheduleImpl(std::uint32_t i) noexcept {  // spec 2.8: keep only the earliest
    int c[D];
    cellCoords(i, c);
    const State& p = m_s[i];
    const Real dt0 = m_now - p.tst;
    V xi = p.x + p.v * dt0;
    V vi = p.v;
    if constexpr (Gravity)
        for (int d = 0; d < D; ++d) {
            xi[d] += 0.5 * m_config.gravity[d] * dt0 * dt0;
            vi[d] += m_config.gravity[d] * dt0;
        }
    const Real growth = m_config.growthRate;
    const Real ri = Growing ? p.radius + growth * m_now : p.radius;
    Real best = kNoEvent;
    Event ev;
    // Cell faces and walls, per axis (edmd Eq. 2.22-2.25).
    for (int d = 0; d < D; ++d) {
        const Real g = Gravity ? m_config.gravity[d] : 0;
        const bool periodic = m_config.periodic[d];
        const Real lo = c[d] * m_cellEdge[d];
        const Real hi = c[d] + 1 == m_cells[d] ? m_config.box[d] : (c[d] + 1) * m_cellEdge[d];
        if (periodic || c[d] + 1 < m_cells[d]) {
            const Real dt = closingTime(hi - xi[d], vi[d], g);
            if (dt < best) {
                best = dt;
                ev = {static_cast<std::uint32_t>(2 * d + 1), 0, Kind::Cell};
            }
        } else {  // upper wall: contact when the centre is a below it
            const Real dt = closingTime(m_config.box[d] - ri - xi[d], vi[d], g);
            if (dt < best) {
                best = dt;
                ev = {static_cast<std::uint32_t>(2 * d + 1), 0, Kind::Wall};
            }
        }
        if (periodic || c[d] > 0) {
            const Real dt = closingTime(xi[d] - lo, -vi[d], -g);
            if (dt < best) {
                best = dt;
                ev = {static_cast<std::uint32_t>(2 * d), 0, Kind::Cell};
            }
        } else {
            const Real dt = closingTime(xi[d] - ri, -vi[d], -g);
            if (dt < best) {
                best = dt;
                ev = {static_cast<std::uint32_t>(2 * d), 0, Kind::Wall};
            }
        }
    }
    // Collisions with the particles of the (up to) 3^D neighbour cells. A neighbour cell across
    // a periodic boundary is seen through its image: shift[d] is added to its particles'
    // positions (applied to x_i instead), so the pair that will collide through the boundary is
    // found even while its minimum image is still the other one (spec 2.4 [I], image shifts).
    int neighbour[D][3], count[D];
    Real shift[D][3];
    for (int d = 0; d < D; ++d) {
        int k = 0;
        if (c[d] > 0) {
            neighbour[d][k] = c[d] - 1;
            shift[d][k++] = 0;
        } else if (m_config.periodic[d]) {
            neighbour[d][k] = m_cells[d] - 1;
            shift[d][k++] = -m_config.box[d];
        }
        neighbour[d][k] = c[d];
        shift[d][k++] = 0;
        if (c[d] + 1 < m_cells[d]) {
            neighbour[d][k] = c[d] + 1;
            shift[d][k++] = 0;
        } else if (m_config.periodic[d]) {
            neighbour[d][k] = 0;
            shift[d][k++] = m_config.box[d];
        }
        count[d] = k;
    }
    int offset[D] = {};
    const Real sumGrowth = 2 * growth;
    for (;;) {
        int nc[D];
        V xiImage = xi;
        for (int d = 0; d < D; ++d) {
            nc[d] = neighbour[d][offset[d]];
            xiImage[d] -= shift[d][offset[d]];
        }
        for (std::uint32_t j = m_head[cellIndex(nc)]; j != kNone; j = m_next[j]) {
            if (j == i) continue;
            const State& q = m_s[j];
            const Real dtj = m_now - q.tst;
            V xj = q.x + q.v * dtj;
            V vj = q.v;
            if constexpr (Gravity)
                for (int d = 0; d < D; ++d) {
                    xj[d] += 0.5 * m_config.gravity[d] * dtj * dtj;
                    vj[d] += m_config.gravity[d] * dtj;
                }
            Real dt;
            if constexpr (Growing)
                dt = growingPairCollisionTime(xiImage - xj, vi - vj, ri + q.radius + growth * m_now, sumGrowth);
            else
                dt = pairCollisionTime(xiImage - xj, vi - vj, ri + q.radius);
            if (dt < best || (dt == best && ev.kind == Kind::Collision && j < ev.partner)) {
                best = dt;
                ev = {j, m_counter[j], Kind::Collision};
            }
        }
        int d = 0;
        while (d < D && ++offset[d] >= count[d]) offset[d++] = 0;
        if (d == D) break;
    }
    m_event[i] = ev;
    m_queue.set(i, ev.kind == Kind::None ? kNoEvent : m_now + best);
}

template <int D, class Queue>
bool Engine<D, Queue>::elasticByTc(std::uint32_t i, std::uint32_t j, Real t) const noexcept {
    if (m_lastCollision.empty()) return false;
    return t - m_lastCollision[i] < m_config.tc || (j != kNone && t - m_lastCollision[j] < m_config.tc);
}

template <int D, class Queue>
void Engine<D, Queue>::collide(std::uint32_t i, std::uint32_t j, Real t) noexcept {
    advance(i, t);
    advance(j, t);
    State& a = m_s[i];
    State& b = m_s[j];
    const V r = minimumImage(a.x - b.x);
    const Real distance = std::sqrt(dot(r, r));
    const V k = r * (1 / distance);  // from j to i (erratum 1)
    const Real mi = m_mass[i], mj = m_mass[j];
    // Approach speed of the surfaces: normal relative speed plus the growth of both radii.
    const Real approach = -dot(a.v - b.v, k) + 2 * m_config.growthRate;
    const bool tcElastic = elasticByTc(i, j, t);
    const Real eps = tcElastic ? 1 : m_config.restitution(std::abs(approach));
    const Real normalImpulse = std::max<Real>(0, (1 + eps) * approach) * (mi * mj / (mi + mj));  // on i along k
    const Real before = 0.5 * (mi * dot(a.v, a.v) + mj * dot(b.v, b.v));
    Real after;
    if (m_omega.empty()) {
        a.v = a.v + k * (normalImpulse / mi);
        b.v = b.v - k * (normalImpulse / mj);
        after = 0.5 * (mi * dot(a.v, a.v) + mj * dot(b.v, b.v));
    } else {
        const Real z = m_config.inertiaFactor;
        const Real ai = radius(i), aj = radius(j);
        Vec3 vi = lift(a.v), vj = lift(b.v);
        Vec3& wi = m_omega[i];
        Vec3& wj = m_omega[j];
        const Real spinBefore = 0.5 * z * (mi * ai * ai * dot(wi, wi) + mj * aj * aj * dot(wj, wj));
        roughCollisionGeneral(vi, vj, wi, wj, lift(k), ai, aj, mi, mj, z, normalImpulse,
                              tcElastic ? -1.0 : m_config.tangentialRestitution);
        a.v = lower<D>(vi);
        b.v = lower<D>(vj);
        after = 0.5 * (mi * dot(a.v, a.v) + mj * dot(b.v, b.v)) +
                0.5 * z * (mi * ai * ai * dot(wi, wi) + mj * aj * aj * dot(wj, wj)) - spinBefore;
    }
    m_dissipated += before - after;
    m_virial += distance * normalImpulse;  // r_ij . J_i (edmd spec 7 item 27)
    if (!m_lastCollision.empty()) m_lastCollision[i] = m_lastCollision[j] = t;
    ++m_counter[i];
    ++m_counter[j];
    ++m_stats.collisions;
    if (tcElastic) ++m_stats.tcElastic;
}

template <int D, class Queue>
void Engine<D, Queue>::collideWall(std::uint32_t i, std::uint32_t wall, Real t) noexcept {
    advance(i, t);
    State& p = m_s[i];
    const int d = static_cast<int>(wall / 2);
    const bool upper = wall % 2 == 1;
    const Real vn = upper ? p.v[d] : -p.v[d];  // towards the wall
    if (vn > 0) {  // a round-off touch while leaving changes nothing
        const bool tcElastic = elasticByTc(i, kNone, t);
        const Real eps = tcElastic ? 1 : m_config.wallRestitution;
        m_dissipated += 0.5 * m_mass[i] * (1 - eps * eps) * vn * vn;
        p.v[d] = -eps * p.v[d];
        if (tcElastic) ++m_stats.tcElastic;
    }
    if (!m_lastCollision.empty()) m_lastCollision[i] = t;
    ++m_counter[i];
    ++m_stats.wallCollisions;
}

template <int D, class Queue>
void Engine<D, Queue>::crossCell(std::uint32_t i, std::uint32_t face) noexcept {  // spec 2.7
    const int d = static_cast<int>(face / 2);
    const bool up = face % 2 == 1;
    int c[D];
    cellCoords(i, c);
    c[d] += up ? 1 : -1;
    if (c[d] == m_cells[d]) {
        c[d] = 0;
        m_s[i].x[d] -= m_config.box[d];
    } else if (c[d] < 0) {
        c[d] = m_cells[d] - 1;
        m_s[i].x[d] += m_config.box[d];
    }
    removeFromCell(i);
    insertIntoCell(i, cellIndex(c));
    ++m_stats.cellCrossings;
}

template <int D, class Queue>
std::uint64_t Engine<D, Queue>::runUntil(Real tEnd) {
    const std::uint64_t done = run(tEnd, ~std::uint64_t{0});
    m_now = std::max(m_now, tEnd);
    return done;
}

template <int D, class Queue>
std::uint64_t Engine<D, Queue>::runCollisions(std::uint64_t collisions, Real tEnd) {
    return run(tEnd, m_stats.collisions + collisions);
}

template <int D, class Queue>
std::uint64_t Engine<D, Queue>::run(Real tEnd, std::uint64_t collisionLimit) {
    std::uint64_t done = 0;
    while (size() > 0 && m_stats.collisions < collisionLimit) {
        const Real t = m_queue.topTime();
        if (!(t <= tEnd)) break;
        if (t > m_regridTime) {  // growing spheres reached the cell edge: rebuild, then go on
            m_now = m_regridTime;
            regrid();
            continue;
        }
        const std::uint32_t i = m_queue.top();
        m_now = t;
        const Event ev = m_event[i];
        ++done;
        ++m_stats.events;
        switch (ev.kind) {
            case Kind::Collision: {
                const std::uint32_t j = ev.partner;
                if (m_counter[j] != ev.partnerCounter) {  // annulled (spec 2.6): free flight, new event
                    ++m_stats.annulled;
                    advance(i, t);
                    schedule(i);
                    break;
                }
                collide(i, j, t);
                schedule(i);
                schedule(j);
                break;
            }
            case Kind::Cell:
                advance(i, t);
                crossCell(i, ev.partner);
                schedule(i);
                break;
            case Kind::Wall:
                collideWall(i, ev.partner, t);
                schedule(i);
                break;
            case Kind::None: schedule(i); break;
        }
    }
    return done;
}

template <int D, class Queue>
void Engine<D, Queue>::restartClock() {
    for (std::uint32_t i = 0; i < size(); ++i) {
        advance(i, m_now);
        m_s[i].tst = 0;
        m_s[i].radius += m_config.growthRate * m_now;
    }
    m_maxRadius0 += m_config.growthRate * m_now;
    m_now = 0;
    std::fill(m_counter.begin(), m_counter.end(), 0u);
    std::fill(m_lastCollision.begin(), m_lastCollision.end(), -kNoEvent);
    m_stats = {};
    m_virial = 0;
    m_dissipated = 0;
    buildCells();
    rescheduleAll();
}

template <int D, class Queue>
void Engine<D, Queue>::setCollisionRules(const Restitution& restitution, Real wallRestitution, Real tc) {
    m_config.restitution = restitution;
    m_config.wallRestitution = wallRestitution;
    m_config.tc = tc;
    if (tc > 0 && m_lastCollision.empty()) m_lastCollision.assign(size(), -kNoEvent);
}

template <int D, class Queue>
Real Engine<D, Queue>::kineticEnergy() const noexcept {
    Real e = 0;
    for (std::uint32_t i = 0; i < size(); ++i) {
        const V v = velocityNow(i);
        e += 0.5 * m_mass[i] * dot(v, v);
    }
    return e;
}

template <int D, class Queue>
Real Engine<D, Queue>::rotationalEnergy() const noexcept {
    Real e = 0;
    for (std::uint32_t i = 0; i < m_omega.size(); ++i) {
        const Real a = radius(i);
        e += 0.5 * m_config.inertiaFactor * m_mass[i] * a * a * dot(m_omega[i], m_omega[i]);
    }
    return e;
}

template <int D, class Queue>
Real Engine<D, Queue>::potentialEnergy() const noexcept {
    if (!m_gravity) return 0;
    Real e = 0;
    for (std::uint32_t i = 0; i < size(); ++i) {
        const V x = positionNow(i);
        for (int d = 0; d < D; ++d) e -= m_mass[i] * m_config.gravity[d] * x[d];
    }
    return e;
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::momentum() const noexcept {
    V p;
    for (std::uint32_t i = 0; i < size(); ++i) p = p + velocityNow(i) * m_mass[i];
    return p;
}

template <int D, class Queue>
std::size_t Engine<D, Queue>::memoryBytes() const noexcept {
    return m_s.capacity() * sizeof(State) + m_mass.capacity() * sizeof(Real) + m_omega.capacity() * sizeof(Vec3) +
           m_counter.capacity() * 4 + m_lastCollision.capacity() * sizeof(Real) +
           (m_cell.capacity() + m_next.capacity() + m_prev.capacity() + m_head.capacity()) * 4 +
           m_event.capacity() * sizeof(Event) + m_queue.memoryBytes();
}

template <int D, class Queue>
void Engine<D, Queue>::saveState(std::ostream& os) const {
    writePod<std::uint32_t>(os, static_cast<std::uint32_t>(D));
    writePod(os, m_now);
    writePod(os, m_stats);
    writePod(os, m_virial);
    writePod(os, m_dissipated);
    writePod(os, m_maxRadius0);
    writePod(os, m_config.restitution);
    writePod(os, m_config.wallRestitution);
    writePod(os, m_config.tc);
    writeVector(os, m_s);
    writeVector(os, m_mass);
    writeVector(os, m_omega);
    writeVector(os, m_counter);
    writeVector(os, m_lastCollision);
    writeVector(os, m_cell);
    writeVector(os, m_next);
    writeVector(os, m_prev);
    writeVector(os, m_head);
    writeVector(os, m_event);
    writePod(os, m_cells);
    writePod(os, m_cellEdge);
    writePod(os, m_invCellEdge);
    writePod(os, m_regridTime);
    std::vector<Real> times(size());
    for (std::uint32_t i = 0; i < size(); ++i) times[i] = m_queue.time(i);
    writeVector(os, times);
}

template <int D, class Queue>
void Engine<D, Queue>::loadState(std::istream& is) {
    if (readPod<std::uint32_t>(is) != static_cast<std::uint32_t>(D))
        throw std::runtime_error("checkpoint belongs to a run of another dimension");
    m_now = readPod<Real>(is);
    m_stats = readPod<EngineStats>(is);
    m_virial = readPod<Real>(is);
    m_dissipated = readPod<Real>(is);
    m_maxRadius0 = readPod<Real>(is);
    m_config.restitution = readPod<Restitution>(is);
    m_config.wallRestitution = readPod<Real>(is);
    m_config.tc = readPod<Real>(is);
    const auto n = size();
    readVector(is, m_s);
    readVector(is, m_mass);
    readVector(is, m_omega);
    readVector(is, m_counter);
    readVector(is, m_lastCollision);
    readVector(is, m_cell);
    readVector(is, m_next);
    readVector(is, m_prev);
    readVector(is, m_head);
    readVector(is, m_event);
    m_cells = readPod<std::array<int, 3>>(is);
    m_cellEdge = readPod<std::array<Real, 3>>(is);
    m_invCellEdge = readPod<std::array<Real, 3>>(is);
    m_regridTime = readPod<Real>(is);
    std::vector<Real> times;
    readVector(is, times);
    if (m_s.size() != n || times.size() != n || m_event.size() != n)
        throw std::runtime_error("checkpoint holds another number of particles");
    m_queue.reset(n);
    for (std::uint32_t i = 0; i < n; ++i) m_queue.set(i, times[i]);
}

template class Engine<2, AddressableHeap>;
template class Engine<2, TournamentTree>;
template class Engine<2, CalendarQueue>;
template class Engine<3, AddressableHeap>;
template class Engine<3, TournamentTree>;
template class Engine<3, CalendarQueue>;

}  // namespace granulab::edmd
