// SPDX-License-Identifier: MIT
// Serial event-driven engine (edmd spec sections 2.1-2.8, 2.10): event loop, event computation
// over the 3^D neighbour cells, cell crossings with periodic wrap, wall collisions, annulled
// collisions, growing spheres with re-gridding, checkpoints.
// Performance layout (spec 8, issue 5): particles live in slots sorted by cell (counting sort
// every kSortEvery N events, deterministic since it is keyed on the event count), so that a
// neighbour scan reads a few contiguous runs of memory; cell lists are singly linked through
// the 64-byte State; cell coordinates are stored per particle (no index decoding); pairs that
// cannot beat the earliest candidate are rejected before the square root.
#include "edmd/engine.hpp"

#include <algorithm>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>

#include "core/binary_io.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"

namespace granulab::edmd {

namespace {
/// Events between two polls of the interrupt flag (one load; the poll costs nothing measurable,
/// and 4096 events take well under a millisecond).
constexpr std::uint64_t kInterruptPoll = 4096;

// Checkpoint I/O of vectors with any allocator (core/binary_io's take the default one).
template <class T, class A>
void writeVector(std::ostream& os, const std::vector<T, A>& v) {
    writePod<std::uint64_t>(os, v.size());
    os.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}

template <class T, class A>
void readVector(std::istream& is, std::vector<T, A>& v) {
    const auto n = readPod<std::uint64_t>(is);
    checkElementsFit(is, n, sizeof(T));
    v.resize(n);
    is.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
    if (!is) throw std::runtime_error("checkpoint truncated");
}

Vec3 lift(const VecD<2>& a) noexcept {
    return {{a[0], a[1], 0}};
}
Vec3 lift(const VecD<3>& a) noexcept {
    return a;
}
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
    : m_config(config) {
    const auto n = static_cast<std::uint32_t>(x.size());
    if (v.size() != n || radius.size() != n || mass.size() != n)
        throw std::invalid_argument("edmd::Engine: position, velocity, radius and mass counts differ");
    if (x.size() >= 0x80000000u) throw std::invalid_argument("edmd::Engine: too many particles");
    for (int d = 0; d < D; ++d)
        if (!(m_config.box[d] > 0)) throw std::invalid_argument("edmd::Engine: box edges must be positive");
    if (m_config.growthRate != 0)
        for (int d = 0; d < D; ++d)
            if (!m_config.periodic[d])
                throw std::invalid_argument("edmd::Engine: growing spheres need a periodic box");
    m_s.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        m_s[i].x = x[i];
        m_s[i].v = v[i];
    }
    // Equal radii or masses are stored once (memory, and one load less per neighbour).
    if (n) {
        m_uniformRadius = radius[0];
        m_uniformMass = mass[0];
    }
    if (std::any_of(radius.begin(), radius.end(), [&](Real a) { return a != m_uniformRadius; }))
        m_radius = std::move(radius);
    if (std::any_of(mass.begin(), mass.end(), [&](Real m) { return m != m_uniformMass; }))
        m_mass = std::move(mass);
    m_maxRadius0 =
        m_radius.empty() ? (n ? m_uniformRadius : 0) : *std::max_element(m_radius.begin(), m_radius.end());
    for (int d = 0; d < D; ++d) m_gravity = m_gravity || m_config.gravity[d] != 0;
    if (m_config.rough()) m_omega.assign(n, Vec3{});
    if (m_config.tc > 0) m_lastCollision.assign(n, -kNoEvent);
    m_event.assign(n, Event{});
    m_slot.resize(n);
    m_id.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) m_slot[i] = m_id[i] = i;
    buildCells();
    sortParticles(false);
    rescheduleAll();
    resetWatchdog();
}

template <int D>
std::array<int, 3> chooseCellGrid(const EngineConfig& config, std::uint32_t n, Real amax) {
    constexpr int kMaxCells = 65535;
    // Default edge (spec 2.4): C/N ~ 1.5 (2D) or ~8 (3D) at low density, else the diameter.
    Real volume = 1;
    for (int d = 0; d < D; ++d) volume *= config.box[d];
    const Real cellsPerParticle =
        config.cellsPerParticle > 0 ? config.cellsPerParticle : (D == 2 ? 1.5 : 8.0);
    const Real targetEdge = n ? std::pow(volume / (cellsPerParticle * n), 1.0 / D) : 0;
    // Growing spheres: a hair above the diameter, so that a re-grid always lowers the cell count.
    const Real diameter = 2 * amax * (config.growthRate > 0 ? 1 + 1e-9 : 1);
    Real smallestPeriodicEdge = kNoEvent;
    for (int d = 0; d < D; ++d)
        if (config.periodic[d]) smallestPeriodicEdge = std::min(smallestPeriodicEdge, config.box[d]);
    const Real smallestEdge = std::max(config.cellSize, diameter);  // cells only need to exceed 2a
    const Real edge = std::max(smallestEdge, std::min(targetEdge, smallestPeriodicEdge / 3));
    std::array<int, 3> result{1, 1, 1};
    for (int d = 0; d < D; ++d) {
        const Real L = config.box[d];
        // Fewer cells than the edge allows is always correct (cells only need to exceed 2a).
        int cells = edge > 0 ? static_cast<int>(std::min<Real>(std::floor(L / edge), kMaxCells)) : 1;
        if (config.powerOfTwoCells && cells > 1) {
            // The power of two nearest to the target count (in ratio), but no more than the
            // diameter allows; Morton blocks are then boxes without padding (spec 3.1).
            const int most = smallestEdge > 0
                                 ? static_cast<int>(std::min<Real>(std::floor(L / smallestEdge), kMaxCells))
                                 : kMaxCells;
            const Real target = edge > 0 ? L / edge : 1;
            int p = 1;
            while (2 * p <= most && 2 * p <= target * std::sqrt(2.0)) p *= 2;
            cells = p;
        }
        if (config.periodic[d] && cells < 3)
            throw std::invalid_argument(
                "edmd::Engine: a periodic axis must hold at least 3 cells of one diameter "
                "(box edge " +
                std::to_string(L) + " m, diameter " + std::to_string(2 * amax) + " m)");
        result[d] = std::max(cells, 1);
    }
    return result;
}

template std::array<int, 3> chooseCellGrid<2>(const EngineConfig&, std::uint32_t, Real);
template std::array<int, 3> chooseCellGrid<3>(const EngineConfig&, std::uint32_t, Real);

template <int D, class Queue>
void Engine<D, Queue>::buildCells() {
    const auto n = size();
    const Real amax = m_maxRadius0 + std::max<Real>(0, m_config.growthRate * m_now);
    // A parallel run's global grid comes with its records (domain layout); else it is chosen.
    const std::array<int, 3> grid =
        m_forcedCells[0] > 0 ? m_forcedCells : chooseCellGrid<D>(m_config, n, amax);
    std::size_t cellCount = 1;
    for (int d = 0; d < D; ++d) {
        const Real L = m_config.box[d];
        const int cells = grid[d];
        m_cells[d] = cells;
        m_cellEdge[d] = L / cells;
        m_invCellEdge[d] = cells / L;
        cellCount *= static_cast<std::size_t>(cells);
    }
    if (cellCount >= kNone) throw std::invalid_argument("edmd::Engine: too many cells; raise edmd.cell_size");
    // Tables for the window's cells only (a domain engine's own cells and halo, spec 3.6).
    if (!m_windowGiven) m_window = CellWindow::whole(m_cells);
    std::size_t windowStride = 1;
    for (int d = 0; d < D; ++d) {
        m_stride[d] = static_cast<std::uint32_t>(windowStride);
        windowStride *= static_cast<std::size_t>(m_window.extent[d]);
    }
    // Growing spheres outgrow the cells when 2 a_max(t) exceeds the smallest edge.
    m_regridTime = kNoEvent;
    if (m_config.growthRate > 0) {
        Real minEdge = kNoEvent;
        for (int d = 0; d < D; ++d) minEdge = std::min(minEdge, m_cellEdge[d]);
        m_regridTime = (0.5 * minEdge - m_maxRadius0) / m_config.growthRate;
    }
    m_head.assign(m_window.count(), kNone);
    m_head.shrink_to_fit();
    m_cellOf.resize(n);
    for (std::uint32_t s = 0; s < n; ++s)
        for (int d = 0; d < D; ++d)
            m_cellOf[s][d] =
                cellCoordinate(m_s[s].x[d], m_s[s].v[d], m_invCellEdge[d], m_cellEdge[d], m_cells[d]);
}

template <int D, class Queue>
void Engine<D, Queue>::sortParticles(bool requeue) {
    const auto n = size();
    m_nextSort = m_stats.events + kSortEvery * std::max<std::uint64_t>(n, 1);
    m_checkAt = 0;  // housekeeping recomputes its next event
    if (n == 0) return;
    // Counting sort by cell index (stable): newSlot[s] is the slot s moves to. m_head serves as
    // the bucket counter; the lists are rebuilt below.
    std::vector<std::uint32_t> newSlot(n);
    std::fill(m_head.begin(), m_head.end(), 0u);
    for (std::uint32_t s = 0; s < n; ++s) ++m_head[cellIndex(m_cellOf[s])];
    std::uint32_t sum = 0;
    for (auto& h : m_head) {
        const std::uint32_t c = h;
        h = sum;
        sum += c;
    }
    for (std::uint32_t s = 0; s < n; ++s) newSlot[s] = m_head[cellIndex(m_cellOf[s])]++;
    // Slot references: collision partners, the id map and the queue times.
    for (auto& ev : m_event)
        if (ev.partner < kMaxParticles) ev.partner = newSlot[ev.partner];
    for (auto& s : m_slot) s = newSlot[s];
    std::vector<Real> times;
    if (requeue) {
        times.resize(n);
        for (std::uint32_t s = 0; s < n; ++s) times[newSlot[s]] = m_queue.time(s);
    }
    // Permute every per-slot array in place along the cycles of newSlot (no second copy of
    // the states).
    for (std::uint32_t s = 0; s < n; ++s)
        while (newSlot[s] != s) {
            const std::uint32_t d = newSlot[s];
            forEachSlotArray([s, d](auto& array) { std::swap(array[s], array[d]); });
            std::swap(newSlot[s], newSlot[d]);
        }
    // Cell lists in ascending slot order (memory-forward traversal).
    std::fill(m_head.begin(), m_head.end(), kNone);
    for (std::uint32_t s = n; s-- > 0;) {
        const std::uint32_t c = cellIndex(m_cellOf[s]);
        m_s[s].next = m_head[c];
        m_head[c] = s;
    }
    if (requeue) {
        m_queue.setTieKeys(m_id.data());
        m_queue.reset(n);
        m_queue.beginBulk();
        for (std::uint32_t s = 0; s < n; ++s) m_queue.set(s, times[s]);
        m_queue.retune();
    }
}

template <int D, class Queue>
void Engine<D, Queue>::rescheduleAll() noexcept {
    m_queue.setTieKeys(m_id.data());  // before reset, which already compares keys
    m_queue.reset(size());
    m_queue.beginBulk();
    for (std::uint32_t s = 0; s < size(); ++s) schedule(s);
    m_queue.retune();
}

template <int D, class Queue>
void Engine<D, Queue>::regrid() {
    for (std::uint32_t s = 0; s < size(); ++s) advance(s, m_now);
    buildCells();
    sortParticles(false);
    rescheduleAll();
    ++m_stats.regrids;
}

template <int D, class Queue>
std::uint32_t Engine<D, Queue>::cellIndex(const CellCoords& c) const noexcept {
    std::uint32_t k = 0;
    for (int d = 0; d < D; ++d) k += m_stride[d] * static_cast<std::uint32_t>(windowCoordinate(d, c[d]));
    GL_ASSERT(k < m_head.size(), "edmd::Engine: cell index out of range");
    return k;
}

template <int D, class Queue>
void Engine<D, Queue>::linkCell(std::uint32_t s) noexcept {
    std::uint32_t& head = m_head[cellIndex(m_cellOf[s])];
    m_s[s].next = head;
    head = s;
}

template <int D, class Queue>
void Engine<D, Queue>::unlinkCell(std::uint32_t s) noexcept {
    // Singly linked: walk the (short) list of the cell to the predecessor.
    std::uint32_t* link = &m_head[cellIndex(m_cellOf[s])];
    while (*link != s) {
        GL_ASSERT(*link != kNone, "edmd::Engine: particle missing from its cell list");
        link = &m_s[*link].next;
    }
    *link = m_s[s].next;
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::minimumImage(V d) const noexcept {
    for (int k = 0; k < D; ++k) {
        if (!m_config.periodic[k]) continue;
        const Real L = m_config.box[k];
        if (d[k] > 0.5 * L)
            d[k] -= L;
        else if (d[k] < -0.5 * L)
            d[k] += L;
    }
    return d;
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::contactVector(const V& xi, const V& xj) const noexcept {
    V r;
    for (int k = 0; k < D; ++k) {
        r[k] = xi[k] - xj[k];
        if (!m_config.periodic[k]) continue;
        const Real L = m_config.box[k];
        if (r[k] > 0.5 * L)
            r[k] = (xi[k] - L) - xj[k];
        else if (r[k] < -0.5 * L)
            r[k] = (xi[k] + L) - xj[k];
    }
    return r;
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::separation(std::uint32_t i, std::uint32_t j) const noexcept {
    return minimumImage(positionNow(i) - positionNow(j));
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::positionNow(std::uint32_t i) const noexcept {
    GL_ASSERT(!m_domain, "edmd::Engine: per-particle queries are for serial engines");
    return positionSlot(m_slot[i]);
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::velocityNow(std::uint32_t i) const noexcept {
    return velocitySlot(m_slot[i]);
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::positionSlot(std::uint32_t s) const noexcept {
    const State& p = m_s[s];
    const Real dt = m_now - p.tst;
    V x;
    for (int d = 0; d < D; ++d) {
        // The parabola also for g = 0 (it adds +0).
        x[d] = flightPosition(p.x[d], p.v[d], m_config.gravity[d], dt);
        if (m_config.periodic[d]) {
            if (x[d] < 0)
                x[d] += m_config.box[d];
            else if (x[d] >= m_config.box[d])
                x[d] -= m_config.box[d];
        }
    }
    return x;
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::velocitySlot(std::uint32_t s) const noexcept {
    V v = m_s[s].v;
    if (m_gravity)
        for (int d = 0; d < D; ++d) v[d] = flightVelocity(v[d], m_config.gravity[d], m_now - m_s[s].tst);
    return v;
}

template <int D, class Queue>
void Engine<D, Queue>::advance(std::uint32_t s, Real t) noexcept {  // free flight, edmd Eq. 2.2-2.4
    GL_ASSERT(s < size(), "edmd::Engine::advance: slot out of range");
    State& p = m_s[s];
    const Real dt = t - p.tst;
    if (m_gravity)
        freeFlight<true>(p.x, p.v, gravityVector(), dt);
    else
        freeFlight<false>(p.x, p.v, gravityVector(), dt);
    p.tst = t;
}

template <int D, class Queue>
void Engine<D, Queue>::schedule(std::uint32_t s) noexcept {
    GL_ASSERT(s < size(), "edmd::Engine::schedule: slot out of range");
    const bool growing = m_config.growthRate != 0;
    const bool uniform = m_radius.empty();
    if (!m_gravity && !growing)
        uniform ? scheduleImpl<false, false, true>(s) : scheduleImpl<false, false, false>(s);
    else if (m_gravity)
        growing ? scheduleImpl<true, true, false>(s) : scheduleImpl<true, false, false>(s);
    else
        scheduleImpl<false, true, false>(s);
}

// Event prediction of one particle (spec 2.8: keep only the earliest). The parts below are
// forced inline: scheduleImpl is the hot path, and every neighbour test must stay in one loop.

template <int D, class Queue>
template <bool Gravity, bool Growing, bool Uniform>
void Engine<D, Queue>::scheduleImpl(std::uint32_t i) noexcept {
    const State& s = m_s[i];
    Subject p{i, s.x, s.v, Uniform ? m_uniformRadius : radiusSlot(i)};
    freeFlight<Gravity>(p.x, p.v, gravityVector(), m_now - s.tst);
    const CellCoords c = m_cellOf[i];
    Prediction next;
    predictFaces<Gravity>(p, c, next);
    predictPairs<Gravity, Growing, Uniform>(p, neighbourhood(c), next);
    push(i, next);
}

template <int D, class Queue>
template <bool Gravity>
[[gnu::always_inline]] inline void Engine<D, Queue>::predictFaces(const Subject& p, const CellCoords& c,
                                                                  Prediction& next) const noexcept {
    const auto keepEarlier = [&next](Real dt, std::uint32_t partner) {
        if (dt < next.dt) {
            next.dt = dt;
            next.ev = {partner, 0};
        }
    };
    for (int d = 0; d < D; ++d) {
        const Real g = Gravity ? m_config.gravity[d] : 0;
        const bool periodic = m_config.periodic[d];
        const int cd = c[d];
        const Real lo = cd * m_cellEdge[d];
        const Real hi = cd + 1 == m_cells[d] ? m_config.box[d] : (cd + 1) * m_cellEdge[d];
        const auto up = static_cast<std::uint32_t>(2 * d + 1), down = static_cast<std::uint32_t>(2 * d);
        if (periodic || cd + 1 < m_cells[d])
            keepEarlier(closingTime(hi - p.x[d], p.v[d], g), kCellBase + up);
        else  // upper wall: contact when the centre is a below it
            keepEarlier(closingTime(m_config.box[d] - p.radius - p.x[d], p.v[d], g), kWallBase + up);
        if (periodic || cd > 0)
            keepEarlier(closingTime(p.x[d] - lo, -p.v[d], -g), kCellBase + down);
        else
            keepEarlier(closingTime(p.x[d] - p.radius, -p.v[d], -g), kWallBase + down);
    }
}

template <int D, class Queue>
[[gnu::always_inline]] inline typename Engine<D, Queue>::Neighbourhood Engine<D, Queue>::neighbourhood(
    const CellCoords& c) const noexcept {
    // Window coordinates: a cell at the window's edge has its neighbours inside only when the
    // window is the whole (periodic) axis, and only a domain engine's halo cells (never
    // predicted) sit at the edge of a partial window.
    Neighbourhood nb;
    for (int d = 0; d < D; ++d) {
        const int cd = c[d];
        GL_ASSERT(cd < m_cells[d], "edmd::Engine: cell coordinate out of range");
        const int l = windowCoordinate(d, cd), extent = m_window.extent[d];
        const bool lower = cd > 0 || m_config.periodic[d],
                   upper = cd + 1 < m_cells[d] || m_config.periodic[d];
        GL_ASSERT(extent == m_cells[d] || ((l > 0 || !lower) && (l + 1 < extent || !upper)),
                  "edmd::Engine: predicting a particle at the edge of the window");
        int k = 0;
        if (lower) {
            nb.offset[d][k] = m_stride[d] * static_cast<std::uint32_t>(l > 0 ? l - 1 : extent - 1);
            nb.shift[d][k++] = cd > 0 ? 0 : -m_config.box[d];
        }
        nb.offset[d][k] = m_stride[d] * static_cast<std::uint32_t>(l);
        nb.shift[d][k++] = 0;
        if (upper) {
            nb.offset[d][k] = m_stride[d] * static_cast<std::uint32_t>(l + 1 < extent ? l + 1 : 0);
            nb.shift[d][k++] = cd + 1 < m_cells[d] ? 0 : m_config.box[d];
        }
        nb.count[d] = k;
    }
    return nb;
}

template <int D, class Queue>
template <bool Gravity, bool Growing, bool Uniform>
[[gnu::always_inline]] inline void Engine<D, Queue>::predictPairs(const Subject& p, const Neighbourhood& nb,
                                                                  Prediction& next) const noexcept {
    // A neighbour cell across a periodic boundary is seen through its image: its shift is
    // added to its particles' positions (applied to x_i instead), so the pair that will collide
    // through the boundary is found even while its minimum image is still the other one.
    const State* const st = m_s.data();
    const std::uint32_t* const head = m_head.data();
    const V g = gravityVector();
    const Real now = m_now;
    constexpr Real kSafe = 1 + 1e-12;
    Real bound = 2 * next.dt * kSafe;
    // First pass: the heads of all neighbour cells, and a prefetch of their first particles,
    // so that the (mostly L2-missing) neighbour lines load in parallel, not one after another.
    std::uint32_t first[27];
    {
        int n = 0;
        for (int kz = 0; kz < nb.count[2]; ++kz)
            for (int ky = 0; ky < nb.count[1]; ++ky)
                for (int kx = 0; kx < nb.count[0]; ++kx) {
                    const std::uint32_t j = head[nb.offset[0][kx] + nb.offset[1][ky] + nb.offset[2][kz]];
                    first[n++] = j;
                    if (j != kNone) __builtin_prefetch(&st[j]);
                }
    }
    int cellNo = 0;
    for (int kz = 0; kz < nb.count[2]; ++kz)
        for (int ky = 0; ky < nb.count[1]; ++ky)
            for (int kx = 0; kx < nb.count[0]; ++kx) {
                V xiImage = p.x;
                xiImage[0] -= nb.shift[0][kx];
                xiImage[1] -= nb.shift[1][ky];
                if constexpr (D == 3) xiImage[2] -= nb.shift[2][kz];
                for (std::uint32_t j = first[cellNo++]; j != kNone; j = st[j].next) {
                    const State& q = st[j];
                    V xj = q.x, vj = q.v;
                    freeFlight<Gravity>(xj, vj, g, now - q.tst);
                    Real dt;
                    if (!pairTime<Growing, Uniform>(p, j, xiImage - xj, p.v - vj, bound, dt)) continue;
                    if (dt < next.dt || (dt == next.dt && next.ev.partner < kMaxParticles &&
                                         m_id[j] < m_id[next.ev.partner])) {
                        next.dt = dt;
                        bound = 2 * next.dt * kSafe;
                        next.ev = {j, q.counter};
                    }
                }
            }
}

template <int D, class Queue>
template <bool Growing, bool Uniform>
[[gnu::always_inline]] inline bool Engine<D, Queue>::pairTime(const Subject& p, std::uint32_t j, const V& r,
                                                              const V& w, Real bound,
                                                              Real& dt) const noexcept {
    if constexpr (Growing) {
        if (j == p.slot) return false;
        const Real growth = m_config.growthRate;
        dt = growingPairCollisionTime(
            r, w, p.radius + (m_radius.empty() ? m_uniformRadius : m_radius[j]) + growth * m_now, 2 * growth);
        return true;
    } else {
        // One branch on a cheap test first: only approaching pairs (b < 0) whose root can beat
        // `bound` (twice the earliest time so far) need the square root and the division (slow
        // on this hardware). The root c/(-b + sqrt(disc)) is at least c/(-2b) since disc <= b^2;
        // the caller's bound keeps round-off on the safe side, so only pairs that would lose
        // anyway are skipped. The subject itself needs no test: r = w = 0 exactly, so b = 0.
        const Real b = dot(r, w);
        const Real sum = p.radius + (Uniform            ? m_uniformRadius
                                     : m_radius.empty() ? m_uniformRadius
                                                        : m_radius[j]);
        const Real cc = dot(r, r) - sum * sum;
        if (!((b < 0) & (cc <= -b * bound))) return false;
        const Real ww = dot(w, w);
        const Real disc = b * b - ww * cc;
        if (!(disc >= 0)) return false;  // misses
        if (cc > 0) {
            dt = cc / (-b + std::sqrt(disc));  // as pairCollisionTime
            return true;
        }
        // In contact, an approach below round-off of |r||w| is a grazing touch, not a collision:
        // a collision that leaves the normal speed at zero (eps = 0) would else be found again
        // at the same instant, forever (issue 11, case 2). Only this rare branch pays for it.
        dt = 0;
        return b * b > kGrazing * kGrazing * dot(r, r) * ww;
    }
}

template <int D, class Queue>
[[gnu::always_inline]] inline void Engine<D, Queue>::push(std::uint32_t s, const Prediction& next) noexcept {
    GL_ASSERT(!(next.dt < 0), "edmd::Engine: event predicted in the past");
    m_event[s] = next.ev;
    m_queue.set(s, next.ev.partner == kNone ? kNoEvent : m_now + next.dt);
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
    const V r = contactVector(a.x, b.x);
    const Real distance = std::sqrt(dot(r, r));
    const V k = r * (1 / distance);  // from j to i (erratum 1)
    const Real mi = massSlot(i), mj = massSlot(j);
    // Approach speed of the surfaces: normal relative speed plus the growth of both radii. From
    // r itself (not k), so that its sign is the prediction's: -dot(r, w) = -b (pairTime).
    const Real approach = -dot(a.v - b.v, r) / distance + 2 * m_config.growthRate;
    const bool tcElastic = elasticByTc(i, j, t);
    const Real eps = tcElastic ? 1 : m_config.restitution(std::abs(approach));
    const Real normalImpulse =
        std::max<Real>(0, (1 + eps) * approach) * (mi * mj / (mi + mj));  // on i along k
    const Real before = 0.5 * (mi * dot(a.v, a.v) + mj * dot(b.v, b.v));
    Real after;
    if (m_omega.empty()) {
        a.v = a.v + k * (normalImpulse / mi);
        b.v = b.v - k * (normalImpulse / mj);
        after = 0.5 * (mi * dot(a.v, a.v) + mj * dot(b.v, b.v));
    } else {
        const Real z = m_config.inertiaFactor;
        const Real ai = radiusSlot(i), aj = radiusSlot(j);
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
    ++a.counter;
    ++b.counter;
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
    if (vn > 0) {                              // a round-off touch while leaving changes nothing
        const bool tcElastic = elasticByTc(i, kNone, t);
        const Real eps = tcElastic ? 1 : m_config.wallRestitution;
        m_dissipated += 0.5 * massSlot(i) * (1 - eps * eps) * vn * vn;
        p.v[d] = -eps * p.v[d];
        if (tcElastic) ++m_stats.tcElastic;
    }
    if (!m_lastCollision.empty()) m_lastCollision[i] = t;
    ++p.counter;
    ++m_stats.wallCollisions;
}

template <int D, class Queue>
void Engine<D, Queue>::crossCell(std::uint32_t i, std::uint32_t face) noexcept {  // spec 2.7
    const int d = static_cast<int>(face / 2);
    const bool up = face % 2 == 1;
    unlinkCell(i);
    int c = m_cellOf[i][d] + (up ? 1 : -1);
    GL_ASSERT(m_config.periodic[d] || (c >= 0 && c < m_cells[d]),
              "edmd::Engine: cell crossing through a wall");
    if (c == m_cells[d]) {
        c = 0;
        m_s[i].x[d] -= m_config.box[d];
    } else if (c < 0) {
        c = m_cells[d] - 1;
        m_s[i].x[d] += m_config.box[d];
    }
    m_cellOf[i][d] = static_cast<std::uint16_t>(c);
    linkCell(i);
    ++m_stats.cellCrossings;
}

template <int D, class Queue>
std::uint64_t Engine<D, Queue>::runUntil(Real tEnd) {
    const std::uint64_t done = run(tEnd, ~std::uint64_t{0});
    if (m_stall == Stall::None && !m_interrupted) m_now = std::max(m_now, tEnd);
    return done;
}

template <int D, class Queue>
std::uint64_t Engine<D, Queue>::runCollisions(std::uint64_t collisions, Real tEnd) {
    return run(tEnd, m_stats.collisions + collisions);
}

template <int D, class Queue>
std::uint64_t Engine<D, Queue>::run(Real tEnd, std::uint64_t collisionLimit) {
    std::uint64_t done = 0;
    m_interrupted = false;
    m_stall = Stall::None;
    // Progress watchdog (issue 11): within every window of events the clock must move by more
    // than round-off (an inelastic collapse or jammed growing spheres collide forever at one
    // instant); a collision-count run must also collide within 64 windows (a pre-run of
    // particles that never meet). The window state lives in the engine, so a stall spread over
    // many short calls (frequent output stops) is seen as well.
    const bool byCollisions = collisionLimit != ~std::uint64_t{0};
    auto& w = m_watch;
    while (size() > 0 && m_stats.collisions < collisionLimit) {
        const Real t = m_queue.topTime();
        if (!(t <= tEnd)) break;
        if (t > m_regridTime) {  // growing spheres reached the cell edge: rebuild, then go on
            m_now = m_regridTime;
            regrid();
            continue;
        }
        // Housekeeping behind one comparison per event (the hot loop pays nothing more): the
        // interrupt poll every kInterruptPoll events, the watchdog window, the spatial sort.
        if (m_stats.events >= m_checkAt) {
            if (interruptRequested()) {  // between whole events
                m_interrupted = true;
                break;
            }
            if (m_stats.events >= w.events) {
                // A window holds at least 16 events per particle; a real run moves the clock by
                // far more than 1e-9 of itself in it (that would take 1e10 collisions per particle
                // so far). A Zeno sequence creeps by round-off (~1e-16 per event), below it.
                if (!(m_now - w.time > 1e-9 * std::abs(m_now))) {
                    m_stall = Stall::Clock;
                    break;
                }
                w.quietWindows = m_stats.collisions == w.collisions ? w.quietWindows + 1 : 0;
                if (byCollisions && w.quietWindows >= 64) {
                    m_stall = Stall::NoCollision;
                    break;
                }
                w = {m_stats.events + watchdogWindow(), m_now, m_stats.collisions, w.quietWindows};
            }
            if (m_stats.events >= m_nextSort) sortParticles(true);  // keyed on the event count: deterministic
            m_checkAt = std::min({m_nextSort, w.events, m_stats.events + kInterruptPoll});
            continue;  // a sort re-keys the queue
        }
        const std::uint32_t i = m_queue.top();
        GL_ASSERT(i < size() && t >= m_now, "edmd::Engine: event slot out of range or event in the past");
        m_now = t;
        const Event ev = m_event[i];
        ++done;
        ++m_stats.events;
        if (ev.partner < kMaxParticles) {
            const std::uint32_t j = ev.partner;
            GL_ASSERT(j < size() && j != i, "edmd::Engine: collision partner out of range");
            if (m_s[j].counter != ev.partnerCounter) {  // annulled (spec 2.6): free flight, new event
                ++m_stats.annulled;
                advance(i, t);
                schedule(i);
                continue;
            }
            collide(i, j, t);
            schedule(i);
            schedule(j);
        } else if (ev.partner >= kCellBase && ev.partner != kNone) {
            advance(i, t);
            crossCell(i, ev.partner - kCellBase);
            schedule(i);
        } else if (ev.partner >= kWallBase && ev.partner < kCellBase) {
            collideWall(i, ev.partner - kWallBase, t);
            schedule(i);
        } else {
            schedule(i);
        }
    }
    return done;
}

template <int D, class Queue>
void Engine<D, Queue>::restartClock() {
    for (std::uint32_t s = 0; s < size(); ++s) {
        advance(s, m_now);
        m_s[s].tst = 0;
        m_s[s].counter = 0;
    }
    m_uniformRadius += m_config.growthRate * m_now;
    for (auto& a : m_radius) a += m_config.growthRate * m_now;
    m_maxRadius0 += m_config.growthRate * m_now;
    m_now = 0;
    std::fill(m_lastCollision.begin(), m_lastCollision.end(), -kNoEvent);
    m_stats = {};
    m_virial = 0;
    m_dissipated = 0;
    buildCells();
    sortParticles(false);
    rescheduleAll();
    resetWatchdog();
}

template <int D, class Queue>
void Engine<D, Queue>::setGrowthRate(Real u) {
    if (u == m_config.growthRate) return;  // nothing to rebuild
    if (u != 0)
        for (int d = 0; d < D; ++d)
            if (!m_config.periodic[d])
                throw std::invalid_argument("edmd::Engine: growing spheres need a periodic box");
    for (std::uint32_t s = 0; s < size(); ++s) advance(s, m_now);
    // Rebase the time-0 radii so that a(t) = a0 + u t keeps its value now.
    const Real shift = (m_config.growthRate - u) * m_now;
    m_uniformRadius += shift;
    for (auto& a : m_radius) a += shift;
    m_maxRadius0 += shift;
    m_config.growthRate = u;
    buildCells();
    sortParticles(false);
    rescheduleAll();
    resetWatchdog();
}

template <int D, class Queue>
void Engine<D, Queue>::resetWatchdog() noexcept {
    m_watch = {m_stats.events + watchdogWindow(), m_now, m_stats.collisions, 0};
    m_checkAt = 0;
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
    Real e = 0;  // summed in the caller's particle order (independent of the internal slots)
    for (std::uint32_t i = 0; i < size(); ++i) {
        const V v = velocityNow(i);
        e += 0.5 * mass(i) * dot(v, v);
    }
    return e;
}

template <int D, class Queue>
Real Engine<D, Queue>::rotationalEnergy() const noexcept {
    Real e = 0;
    if (m_omega.empty()) return e;
    for (std::uint32_t i = 0; i < size(); ++i) {
        const Real a = radius(i);
        const Vec3& w = m_omega[m_slot[i]];
        e += 0.5 * m_config.inertiaFactor * mass(i) * a * a * dot(w, w);
    }
    return e;
}

template <int D, class Queue>
Real Engine<D, Queue>::potentialEnergy() const noexcept {
    if (!m_gravity) return 0;
    Real e = 0;
    for (std::uint32_t i = 0; i < size(); ++i) {
        const V x = positionNow(i);
        for (int d = 0; d < D; ++d) e -= mass(i) * m_config.gravity[d] * x[d];
    }
    return e;
}

template <int D, class Queue>
typename Engine<D, Queue>::V Engine<D, Queue>::momentum() const noexcept {
    V p;
    for (std::uint32_t i = 0; i < size(); ++i) p = p + velocityNow(i) * mass(i);
    return p;
}

template <int D, class Queue>
std::size_t Engine<D, Queue>::memoryBytes() const noexcept {
    return m_s.capacity() * sizeof(State) + m_event.capacity() * sizeof(Event) +
           m_cellOf.capacity() * sizeof(CellCoords) +
           (m_slot.capacity() + m_id.capacity() + m_head.capacity()) * 4 +
           (m_radius.capacity() + m_mass.capacity() + m_lastCollision.capacity()) * sizeof(Real) +
           m_omega.capacity() * sizeof(Vec3) + m_queue.memoryBytes() + domainMemoryBytes();
}

template <int D, class Queue>
void Engine<D, Queue>::saveState(std::ostream& os) const {
    writePod<std::uint32_t>(os, static_cast<std::uint32_t>(D));
    writePod(os, m_now);
    writePod(os, m_stats);
    writePod(os, m_virial);
    writePod(os, m_dissipated);
    writePod(os, m_maxRadius0);
    writePod(os, m_uniformRadius);
    writePod(os, m_nextSort);
    writePod(os, m_config.restitution);
    writePod(os, m_config.wallRestitution);
    writePod(os, m_config.tc);
    writePod(os, m_config.growthRate);
    writeVector(os, m_s);
    writeVector(os, m_event);
    writeVector(os, m_cellOf);
    writeVector(os, m_id);  // particle id of each slot (the inverse of m_slot)
    writeVector(os, m_radius);
    writeVector(os, m_mass);
    writeVector(os, m_omega);
    writeVector(os, m_lastCollision);
    writeVector(os, m_head);
    writePod(os, m_cells);
    writePod(os, m_stride);
    writePod(os, m_cellEdge);
    writePod(os, m_invCellEdge);
    writePod(os, m_regridTime);
    std::vector<Real> times(size());
    for (std::uint32_t s = 0; s < size(); ++s) times[s] = m_queue.time(s);
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
    m_uniformRadius = readPod<Real>(is);
    m_nextSort = readPod<std::uint64_t>(is);
    m_config.restitution = readPod<Restitution>(is);
    m_config.wallRestitution = readPod<Real>(is);
    m_config.tc = readPod<Real>(is);
    m_config.growthRate = readPod<Real>(is);
    const auto n = size();
    readVector(is, m_s);
    readVector(is, m_event);
    readVector(is, m_cellOf);
    std::vector<std::uint32_t> id;
    readVector(is, id);
    readVector(is, m_radius);
    readVector(is, m_mass);
    readVector(is, m_omega);
    readVector(is, m_lastCollision);
    readVector(is, m_head);
    m_cells = readPod<std::array<int, 3>>(is);
    m_window = CellWindow::whole(m_cells);  // checkpoints are serial
    m_windowGiven = false;
    m_stride = readPod<std::array<std::uint32_t, 3>>(is);
    m_cellEdge = readPod<std::array<Real, 3>>(is);
    m_invCellEdge = readPod<std::array<Real, 3>>(is);
    m_regridTime = readPod<Real>(is);
    std::vector<Real> times;
    readVector(is, times);
    if (m_s.size() != n || times.size() != n || m_event.size() != n || id.size() != n || m_cellOf.size() != n)
        throw std::runtime_error("checkpoint holds another number of particles");
    // Indices that the event loop follows without checks must point inside their arrays.
    std::size_t cellCount = 1;
    bool gridFine = true;
    for (int d = 0; d < D; ++d) {
        gridFine = gridFine && m_cells[d] > 0 && m_cells[d] <= kMaxCellsPerAxis && m_stride[d] == cellCount &&
                   std::isfinite(m_cellEdge[d]) && m_cellEdge[d] > 0 && std::isfinite(m_invCellEdge[d]);
        cellCount *= m_cells[d] > 0 ? static_cast<std::size_t>(m_cells[d]) : 0;
    }
    if (!std::isfinite(m_now) || !gridFine || cellCount == 0 || m_head.size() != cellCount)
        throw std::runtime_error("checkpoint corrupt (clock or cell grid)");
    for (std::uint32_t s = 0; s < n; ++s) {
        bool fine = std::isfinite(m_s[s].tst) && (m_s[s].next == kNone || m_s[s].next < n) &&
                    (m_event[s].partner < n || m_event[s].partner == kNone ||
                     (m_event[s].partner >= kWallBase && m_event[s].partner - kWallBase < 2 * D) ||
                     (m_event[s].partner >= kCellBase && m_event[s].partner - kCellBase < 2 * D));
        for (int d = 0; d < D; ++d)
            fine = fine && std::isfinite(m_s[s].x[d]) && std::isfinite(m_s[s].v[d]) &&
                   m_cellOf[s][d] < m_cells[d];
        if (!fine) throw std::runtime_error("checkpoint corrupt (particle state)");
    }
    if (!std::all_of(m_head.begin(), m_head.end(), [n](std::uint32_t h) { return h == kNone || h < n; }))
        throw std::runtime_error("checkpoint corrupt (cell lists)");
    const auto positiveFinite = [](Real v) { return std::isfinite(v) && v > 0; };
    if (!std::all_of(m_radius.begin(), m_radius.end(), positiveFinite) ||
        !std::all_of(m_mass.begin(), m_mass.end(), positiveFinite) ||
        std::any_of(times.begin(), times.end(), [](Real t) { return std::isnan(t); }))
        throw std::runtime_error("checkpoint corrupt (radii, masses or event times)");
    m_slot.assign(n, kNone);
    for (std::uint32_t s = 0; s < n; ++s) {
        if (id[s] >= n || m_slot[id[s]] != kNone)
            throw std::runtime_error("checkpoint corrupt (particle id)");
        m_slot[id[s]] = s;
    }
    m_id.assign(id.begin(), id.end());
    m_queue.setTieKeys(m_id.data());
    m_queue.reset(n);
    m_queue.beginBulk();
    for (std::uint32_t s = 0; s < n; ++s) m_queue.set(s, times[s]);
    m_queue.retune();
    resetWatchdog();
}

template class Engine<2, AddressableHeap>;
template class Engine<2, TournamentTree>;
template class Engine<2, CalendarQueue>;
template class Engine<3, AddressableHeap>;
template class Engine<3, TournamentTree>;
template class Engine<3, CalendarQueue>;

}  // namespace granulab::edmd
