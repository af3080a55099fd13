// SPDX-License-Identifier: MIT
// Serial event-driven engine (edmd spec sections 2.1-2.8): event loop, event computation over
// the 3^D neighbour cells, cell crossings with periodic wrap, annulled collisions.
#include "edmd/engine.hpp"

#include <algorithm>
#include <stdexcept>

namespace granulab::edmd {

template <int D, class Queue>
Engine<D, Queue>::Engine(EngineConfig config, std::vector<V> x, std::vector<V> v, std::vector<Real> radius,
                         std::vector<Real> mass)
    : m_config(config), m_mass(std::move(mass)) {
    const auto n = static_cast<std::uint32_t>(x.size());
    if (v.size() != n || radius.size() != n || m_mass.size() != n)
        throw std::invalid_argument("edmd::Engine: position, velocity, radius and mass counts differ");
    m_s.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) m_s[i] = {x[i], v[i], 0.0, radius[i]};
    const Real rmax = n ? *std::max_element(radius.begin(), radius.end()) : 0;
    const Real edge = std::max(m_config.cellSize, 2 * rmax);
    m_cells = edge > 0 ? static_cast<int>(std::floor(m_config.box / edge)) : 3;
    if (m_cells < 3) throw std::invalid_argument("edmd::Engine: the box must hold at least 3 cells of one diameter");
    m_cellEdge = m_config.box / m_cells;
    std::size_t cellCount = 1;
    for (int d = 0; d < D; ++d) cellCount *= static_cast<std::size_t>(m_cells);
    m_head.assign(cellCount, 0xFFFFFFFFu);
    m_counter.assign(n, 0);
    m_lastCollision.assign(n, -kNoEvent);
    m_cell.assign(n, 0);
    m_next.assign(n, 0xFFFFFFFFu);
    m_prev.assign(n, 0xFFFFFFFFu);
    m_event.assign(n, Event{});
    for (std::uint32_t i = 0; i < n; ++i) {
        int c[D];
        for (int d = 0; d < D; ++d)
            c[d] = std::clamp(static_cast<int>(std::floor(m_s[i].x[d] / m_cellEdge)), 0, m_cells - 1);
        insertIntoCell(i, cellIndex(c));
    }
    m_queue.reset(n);
    for (std::uint32_t i = 0; i < n; ++i) schedule(i);
}

template <int D, class Queue>
std::uint32_t Engine<D, Queue>::cellIndex(const int c[D]) const noexcept {
    std::uint32_t k = 0;
    for (int d = D - 1; d >= 0; --d) k = k * static_cast<std::uint32_t>(m_cells) + static_cast<std::uint32_t>(c[d]);
    return k;
}

template <int D, class Queue>
void Engine<D, Queue>::cellCoords(std::uint32_t i, int c[D]) const noexcept {
    std::uint32_t k = m_cell[i];
    for (int d = 0; d < D; ++d) {
        c[d] = static_cast<int>(k % static_cast<std::uint32_t>(m_cells));
        k /= static_cast<std::uint32_t>(m_cells);
    }
}

template <int D, class Queue>
void Engine<D, Queue>::insertIntoCell(std::uint32_t i, std::uint32_t cell) noexcept {
    m_cell[i] = cell;
    m_prev[i] = 0xFFFFFFFFu;
    m_next[i] = m_head[cell];
    if (m_head[cell] != 0xFFFFFFFFu) m_prev[m_head[cell]] = i;
    m_head[cell] = i;
}

template <int D, class Queue>
void Engine<D, Queue>::removeFromCell(std::uint32_t i) noexcept {
    if (m_prev[i] != 0xFFFFFFFFu) m_next[m_prev[i]] = m_next[i];
    else m_head[m_cell[i]] = m_next[i];
    if (m_next[i] != 0xFFFFFFFFu) m_prev[m_next[i]] = m_prev[i];
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::minimumImage(V d) const noexcept {
    const Real L = m_config.box;
    for (int k = 0; k < D; ++k) {
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
void Engine<D, Queue>::advance(std::uint32_t i, Real t) noexcept {  // free flight (Eq. 2.2-2.4, g = 0)
    State& p = m_s[i];
    p.x = p.x + p.v * (t - p.tst);
    p.tst = t;
}

template <int D, class Queue>
void Engine<D, Queue>::schedule(std::uint32_t i) noexcept {  // spec 2.8: keep only the earliest
    int c[D];
    cellCoords(i, c);
    const V xi = m_s[i].x + m_s[i].v * (m_now - m_s[i].tst);
    // The next cell crossing (per dimension: the wall the velocity points at).
    Real best = kNoEvent;
    Event ev;
    for (int d = 0; d < D; ++d) {
        const Real v = m_s[i].v[d];
        if (v == 0) continue;
        const Real lo = c[d] * m_cellEdge, hi = lo + m_cellEdge;
        const Real dt = std::max<Real>(0, v > 0 ? (hi - xi[d]) / v : (lo - xi[d]) / v);
        if (dt < best) {
            best = dt;
            ev = {Kind::Cell, static_cast<std::uint32_t>(2 * d + (v > 0 ? 1 : 0)), 0};
        }
    }
    // Collisions with the particles of the 3^D neighbour cells.
    int lo[D], hi[D];  // neighbour coordinates per dimension, wrapped without a division
    for (int d = 0; d < D; ++d) {
        lo[d] = c[d] == 0 ? m_cells - 1 : c[d] - 1;
        hi[d] = c[d] == m_cells - 1 ? 0 : c[d] + 1;
    }
    int offset[D];
    for (int d = 0; d < D; ++d) offset[d] = 0;
    const V vi = m_s[i].v;
    const Real ri = m_s[i].radius;
    for (;;) {
        int nc[D];
        for (int d = 0; d < D; ++d) nc[d] = offset[d] == 0 ? lo[d] : (offset[d] == 1 ? c[d] : hi[d]);
        for (std::uint32_t j = m_head[cellIndex(nc)]; j != 0xFFFFFFFFu; j = m_next[j]) {
            if (j == i) continue;
            const State& q = m_s[j];
            const V xj = q.x + q.v * (m_now - q.tst);
            const Real dt = pairCollisionTime(minimumImage(xi - xj), vi - q.v, ri + q.radius);
            if (dt < best || (dt == best && ev.kind == Kind::Collision && j < ev.partner)) {
                best = dt;
                ev = {Kind::Collision, j, m_counter[j]};
            }
        }
        int d = 0;
        while (d < D && ++offset[d] > 2) offset[d++] = 0;
        if (d == D) break;
    }
    m_event[i] = ev;
    m_queue.set(i, ev.kind == Kind::None ? kNoEvent : m_now + best);
}

template <int D, class Queue>
std::uint64_t Engine<D, Queue>::runUntil(Real tEnd) {
    std::uint64_t done = 0;
    while (size() > 0 && m_queue.topTime() <= tEnd) {
        const std::uint32_t i = m_queue.top();
        const Real t = m_queue.topTime();
        m_now = t;
        const Event ev = m_event[i];
        ++done;
        ++m_stats.events;
        advance(i, t);
        if (ev.kind == Kind::Collision) {
            const std::uint32_t j = ev.partner;
            if (m_counter[j] != ev.partnerCounter) {  // annulled (spec 2.6): free flight, new events
                ++m_stats.annulled;
                schedule(i);
                continue;
            }
            advance(j, t);
            V k = minimumImage(m_s[i].x - m_s[j].x);
            k = k * (1 / std::sqrt(dot(k, k)));
            const bool recent = m_config.tc > 0 && (t - m_lastCollision[i] < m_config.tc || t - m_lastCollision[j] < m_config.tc);
            smoothCollision(m_s[i].v, m_s[j].v, m_mass[i], m_mass[j], k, recent ? 1.0 : m_config.restitution);
            m_lastCollision[i] = m_lastCollision[j] = t;
            ++m_counter[i];
            ++m_counter[j];
            ++m_stats.collisions;
            schedule(i);
            schedule(j);
        } else if (ev.kind == Kind::Cell) {  // spec 2.7, periodic wrap
            ++m_stats.cellCrossings;
            const int d = static_cast<int>(ev.partner / 2);
            const bool up = ev.partner % 2 == 1;
            int c[D];
            cellCoords(i, c);
            c[d] += up ? 1 : -1;
            if (c[d] == m_cells) {
                c[d] = 0;
                m_s[i].x[d] -= m_config.box;
            } else if (c[d] < 0) {
                c[d] = m_cells - 1;
                m_s[i].x[d] += m_config.box;
            }
            removeFromCell(i);
            insertIntoCell(i, cellIndex(c));
            schedule(i);
        } else {
            schedule(i);
        }
    }
    m_now = std::max(m_now, tEnd);
    return done;
}

template <int D, class Queue>
Real Engine<D, Queue>::kineticEnergy() const noexcept {
    Real e = 0;
    for (std::uint32_t i = 0; i < size(); ++i) e += 0.5 * m_mass[i] * dot(m_s[i].v, m_s[i].v);
    return e;
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::momentum() const noexcept {
    V p;
    for (std::uint32_t i = 0; i < size(); ++i) p = p + m_s[i].v * m_mass[i];
    return p;
}

template class Engine<2, AddressableHeap>;
template class Engine<2, TournamentTree>;
template class Engine<2, CalendarQueue>;
template class Engine<3, AddressableHeap>;
template class Engine<3, TournamentTree>;
template class Engine<3, CalendarQueue>;

}  // namespace granulab::edmd
