// SPDX-License-Identifier: MIT
// Drop sources (gc2d spec 6.5), inlets (cfddem spec 4.2, Eq. 4.1) and outlets / sinks (cfddem
// spec 4.3): what enters and leaves at each step, with overlap-safe placement.
#include "dem/particle_flow.hpp"

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>
#include <stdexcept>

#include "core/binary_io.hpp"
#include "core/rng.hpp"
#include "dem/generate.hpp"
#include "geom/polygon.hpp"
#include "geom/segment.hpp"
#include "model/grain_shapes.hpp"

namespace granulab::dem {

namespace {

constexpr std::uint64_t kFlowStream = 0x666c6f7700000000ULL;  // "flow"

/// The random stream of insertion k of element e of a kind (0 sources, 1 inlets).
CounterRng insertionRng(std::uint64_t seed, std::uint64_t kind, std::size_t element, std::uint64_t k) {
    return CounterRng(seed, kFlowStream + (kind << 56) + (static_cast<std::uint64_t>(element) << 40) + k);
}

/// Shape, size, mass and inertia of one particle of `what`, drawn from rng; nullopt if a grain
/// could not be drawn convex.
std::optional<NewParticle> drawParticle(const InsertTemplate& what, CounterRng& rng, model::ShapePool& pool) {
    NewParticle p;
    p.material = what.material;
    p.velocity = what.velocity;
    p.omega = what.omega;
    p.angle = what.angle;
    if (!what.shape) {
        p.radius = drawRadius(what.radius, rng);
        p.mass = model::particleMass(what.massModel, what.density, p.radius);
        p.inertia = model::particleInertia(what.massModel, p.mass, p.radius);
        return p;
    }
    std::uint32_t k = what.sharedShape;
    if (what.shape->kind == "grain") {
        const model::Grain g = model::randomGrain(*what.shape, rng);
        if (!geom::checkConvexPolygon(g.corners).ok()) return std::nullopt;
        k = pool.add(g.corners);
    }
    if (k == model::kDiskShape) return std::nullopt;
    p.shape = k;
    p.angle += model::drawRotation(*what.shape, rng);
    p.radius = pool.circumradius[k];
    p.mass = what.density * pool.area[k];  // polygons are areal (gc2d Eq. 2.10-2.12)
    p.inertia = what.density * pool.secondMoment[k];
    return p;
}

/// True if a disk of radius r at c (a particle's bounding circle) is clear of every particle of
/// the store, of `fresh` and of every solid wall.
/// `above` (may be null) gets the height [m] at which the disk would clear the particle that
/// blocks it (its centre height plus both radii).
bool isClear(Vec2 c, Real r, const model::ParticleStore& s, const std::vector<NewParticle>& fresh,
             const model::WallSet& walls, Real* above = nullptr) {
    for (std::size_t j = 0; j < s.size(); ++j) {
        const Real reach = r + s.radius[j];
        const Real dx = s.x[j] - c.x, dy = s.y[j] - c.y;
        if (dx * dx + dy * dy < reach * reach) {
            if (above) *above = s.y[j] + reach * (1 + 1e-9);
            return false;
        }
    }
    for (const auto& q : fresh)
        if (norm2(q.position - c) < (r + q.radius) * (r + q.radius)) return false;
    for (const auto& w : walls.walls) {
        if (!w.solid) continue;
        if (w.body) {
            if (geom::diskConvexContact(c, r, walls.corners.data() + w.firstSegment,
                                        static_cast<int>(w.segmentCount))
                    .touching)
                return false;
            continue;
        }
        for (std::uint32_t k = 0; k < w.segmentCount; ++k) {
            const auto& seg = walls.segments[w.firstSegment + k];
            const Vec2 q = seg.a + (seg.b - seg.a) * geom::closestParameter(seg.a, seg.b, c);
            if (norm2(c - q) < r * r) return false;
        }
    }
    return true;
}

}  // namespace

ParticleFlow::ParticleFlow(FlowConfig config) : m_config(std::move(config)) {
    m_counters.sourceDrops.assign(m_config.sources.size(), 0);
    m_counters.sourceSkipped.assign(m_config.sources.size(), 0);
    m_counters.inletEmitted.assign(m_config.inlets.size(), 0);
    m_counters.inletSkipped.assign(m_config.inlets.size(), 0);
    m_counters.outletRemoved.assign(m_config.outlets.size(), 0);
    m_counters.outletMass.assign(m_config.outlets.size(), 0);
}

bool ParticleFlow::insertionDue(Real t, Real dt) const noexcept {
    for (std::size_t e = 0; e < m_config.sources.size(); ++e) {
        const DropSource& src = m_config.sources[e];
        const Real due = src.from + static_cast<Real>(m_counters.sourceDrops[e]) * src.interval;
        if (due <= t && due <= src.to) return true;
    }
    for (std::size_t e = 0; e < m_config.inlets.size(); ++e) {  // the condition of `entering`
        const Inlet& in = m_config.inlets[e];
        if (t >= in.from && t < in.to &&
            (t - in.from) * in.rate > static_cast<Real>(m_counters.inletEmitted[e]) + dt)
            return true;
    }
    return false;
}

void ParticleFlow::refreshCandidates(const model::ParticleStore& s, Real maxRadius, Real skin,
                                     std::size_t end) {
    const std::size_t n = std::min(end, s.size());
    m_near.resize(m_config.outlets.size());
    const Real* __restrict x = s.x.data();
    const Real* __restrict y = s.y.data();
    for (std::size_t o = 0; o < m_config.outlets.size(); ++o) {
        const Outlet& q = m_config.outlets[o];
        auto& near = m_near[o];
        near.clear();
        const Real pad = q.isRegion ? skin : maxRadius + skin;
        const Real bx0 = (q.isRegion ? q.xmin : std::min(q.a.x, q.b.x)) - pad;
        const Real bx1 = (q.isRegion ? q.xmax : std::max(q.a.x, q.b.x)) + pad;
        const Real by0 = (q.isRegion ? q.ymin : std::min(q.a.y, q.b.y)) - pad;
        const Real by1 = (q.isRegion ? q.ymax : std::max(q.a.y, q.b.y)) + pad;
        const bool outside = q.isRegion && !q.removeInside;  // candidates: not deep inside the region
        for (std::uint32_t i = 0; i < n; ++i) {
            const bool deepInside =
                x[i] > q.xmin + skin && x[i] < q.xmax - skin && y[i] > q.ymin + skin && y[i] < q.ymax - skin;
            const bool inBox = x[i] >= bx0 && x[i] <= bx1 && y[i] >= by0 && y[i] <= by1;
            if (outside ? !deepInside : inBox) near.push_back(i);
        }
    }
}

std::vector<std::uint32_t> ParticleFlow::leaving(const model::ParticleStore& s, Real t) {
    std::vector<std::uint32_t> out;
    for (std::size_t o = 0; o < m_config.outlets.size(); ++o) {
        const Outlet& q = m_config.outlets[o];
        if (t < q.openAt || o >= m_near.size()) continue;
        const Vec2 d = q.b - q.a;
        const Vec2 nOut = perp(d) / norm(d);  // cfddem: n_out = z x d, left of a -> b
        for (const std::uint32_t i : m_near[o]) {
            const Vec2 c{s.x[i], s.y[i]};
            bool gone;
            if (q.isRegion) {
                const bool inside = c.x >= q.xmin && c.x < q.xmax && c.y >= q.ymin && c.y < q.ymax;
                gone = inside == q.removeInside;
            } else {
                // Capture zone: centre within R of the edge (cfddem 3.11 geometry); outer side
                // (winkel1 < pi/2) and moving outward (winkel2 < pi/2, v = 0 stays).
                const Vec2 foot = q.a + d * geom::closestParameter(q.a, q.b, c);
                const Real r = s.radius[i];
                gone = norm2(c - foot) < r * r && dot(c - foot, nOut) > 0 &&
                       s.vx[i] * nOut.x + s.vy[i] * nOut.y > 0;
            }
            if (!gone || std::find(out.begin(), out.end(), i) != out.end()) continue;
            out.push_back(i);
            ++m_counters.outletRemoved[o];
            m_counters.outletMass[o] += s.mass[i];
            ++m_counters.removed;
            m_counters.massOut += s.mass[i];
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<NewParticle> ParticleFlow::entering(const model::ParticleStore& s, const model::WallSet& walls,
                                                model::ShapePool& pool, Real t, Real dt, Vec2 gravity) {
    std::vector<NewParticle> fresh;
    const std::uint64_t seed = m_config.seed;
    // Drop sources: drop k is due at from + k interval, for from + k interval <= to.
    for (std::size_t e = 0; e < m_config.sources.size(); ++e) {
        const DropSource& src = m_config.sources[e];
        for (;;) {
            const std::uint64_t k = m_counters.sourceDrops[e];
            const Real due = src.from + static_cast<Real>(k) * src.interval;
            if (due > t || due > src.to) break;
            ++m_counters.sourceDrops[e];
            const Real span = src.to - src.from;
            const Real width =
                span > 0 ? src.width + (src.widthEnd - src.width) * (due - src.from) / span : src.width;
            CounterRng rng = insertionRng(seed, 0, e, k);
            const auto drawn = drawParticle(src.what, rng, pool);
            bool placed = false;
            Real lift = -1e300;  // REL retry: just above the grain that blocked the last try
            Real x = 0;
            for (int attempt = 0; drawn && attempt < src.what.attempts && !placed; ++attempt) {
                NewParticle p = *drawn;
                if (lift > -1e300) {
                    p.position = {x, lift};
                    lift = -1e300;
                    if (isClear(p.position, p.radius, s, fresh, walls, &lift)) {
                        fresh.push_back(p);
                        placed = true;
                    }
                    continue;
                }
                x = src.position.x + (rng.uniform() - 0.5) * width;
                Real base = 0;
                if (src.relative) {  // REL: ride on the pile top under the drop point (gc2d 6.5)
                    // Grains still falling are not the pile: only those slower than a tenth of the
                    // impact speed sqrt(2 g h) count (gc2d counts all, and a fast source then
                    // climbs on its own falling grains).
                    const Real impact2 = 2 * norm(gravity) * std::abs(src.position.y);
                    const Real slow2 = impact2 > 0 ? 0.01 * impact2 : 1e300;
                    Real top = 0;
                    bool any = false;
                    for (std::size_t j = 0; j < s.size(); ++j)
                        if (std::abs(s.x[j] - x) < p.radius + s.radius[j] && (!any || s.y[j] > top) &&
                            s.vx[j] * s.vx[j] + s.vy[j] * s.vy[j] < slow2) {
                            top = s.y[j];
                            any = true;
                        }
                    base = any ? top : 0;
                }
                p.position = {x, base + src.position.y};
                if (isClear(p.position, p.radius, s, fresh, walls, src.relative ? &lift : nullptr)) {
                    fresh.push_back(p);
                    placed = true;
                }
            }
            if (!placed) {
                ++m_counters.sourceSkipped[e];
                ++m_counters.skipped;
            }
        }
    }
    // Inlets (cfddem Eq. 4.1): one particle in a step when (t - from) pps > emitted + dt.
    for (std::size_t e = 0; e < m_config.inlets.size(); ++e) {
        const Inlet& in = m_config.inlets[e];
        if (t < in.from || t >= in.to) continue;
        const std::uint64_t k = m_counters.inletEmitted[e];
        if (!((t - in.from) * in.rate > static_cast<Real>(k) + dt)) continue;
        ++m_counters.inletEmitted[e];
        CounterRng rng = insertionRng(seed, 1, e, k);
        const auto drawn = drawParticle(in.what, rng, pool);
        const Vec2 d = in.b - in.a;
        const Real length = norm(d);
        const Vec2 nIn = -perp(d) / length;
        bool placed = false;
        for (int attempt = 0; drawn && attempt < in.what.attempts && !placed; ++attempt) {
            NewParticle p = *drawn;
            const Real margin = in.inset ? std::min<Real>(p.radius / length, 0.5) : 0;
            const Real u = margin + (1 - 2 * margin) * rng.uniform();
            p.position = in.a + d * u + nIn * (in.inset ? p.radius : 0);
            if (isClear(p.position, p.radius, s, fresh, walls)) {
                fresh.push_back(p);
                placed = true;
            }
        }
        if (!placed) {
            ++m_counters.inletSkipped[e];
            ++m_counters.skipped;
        }
    }
    return fresh;
}

void ParticleFlow::bookInserted(const std::vector<NewParticle>& added) noexcept {
    for (const auto& p : added) {
        ++m_counters.inserted;
        m_counters.massIn += p.mass;
    }
}

void ParticleFlow::save(std::ostream& os) const {
    const auto& c = m_counters;
    writeVector(os, c.sourceDrops);
    writeVector(os, c.sourceSkipped);
    writeVector(os, c.inletEmitted);
    writeVector(os, c.inletSkipped);
    writeVector(os, c.outletRemoved);
    writeVector(os, c.outletMass);
    for (const std::uint64_t v : {c.inserted, c.removed, c.skipped}) writePod(os, v);
    writePod(os, c.massIn);
    writePod(os, c.massOut);
}

void ParticleFlow::load(std::istream& is) {
    FlowCounters c;
    readVector(is, c.sourceDrops);
    readVector(is, c.sourceSkipped);
    readVector(is, c.inletEmitted);
    readVector(is, c.inletSkipped);
    readVector(is, c.outletRemoved);
    readVector(is, c.outletMass);
    c.inserted = readPod<std::uint64_t>(is);
    c.removed = readPod<std::uint64_t>(is);
    c.skipped = readPod<std::uint64_t>(is);
    c.massIn = readPod<Real>(is);
    c.massOut = readPod<Real>(is);
    if (c.sourceDrops.size() != m_config.sources.size() ||
        c.sourceSkipped.size() != m_config.sources.size() ||
        c.inletEmitted.size() != m_config.inlets.size() || c.inletSkipped.size() != m_config.inlets.size() ||
        c.outletRemoved.size() != m_config.outlets.size() || c.outletMass.size() != m_config.outlets.size())
        throw std::runtime_error(
            "the checkpoint's sources, inlets and outlets differ from the scene's (add or remove them only "
            "in a "
            "fresh run)");
    m_counters = std::move(c);
}

}  // namespace granulab::dem
