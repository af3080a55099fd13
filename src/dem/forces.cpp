// SPDX-License-Identifier: MIT
// Force loops. Why this shape: the law form is dispatched once per bucket (std::visit over the
// three axis variants), the loop body is a template with the law inlined; parameters of a
// material pair are read from the LawTable with the alternative known at compile time.
// Pairs are processed in list order, so the floating-point summation order is fixed.
#include "dem/forces.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "dem/contact/kernel.hpp"
#include "dem/forces_area.hpp"
#include "geom/segment.hpp"

namespace granulab::dem {

namespace {

template <class N, class D, class T>
ResolvedLaw<N, D, T> resolve(const ContactLaw& law) noexcept {
    return {*std::get_if<N>(&law.normal), *std::get_if<D>(&law.damping), *std::get_if<T>(&law.tangential),
            law.clipAttraction, rollingSettings(law.rolling)};
}

/// Visits the form of a bucket with its concrete axis types.
template <class Fn>
void visitForm(const ContactLaw& rep, Fn&& fn) {
    std::visit(
        [&](const auto& n, const auto& d, const auto& t) {
            using N = std::decay_t<decltype(n)>;
            using D = std::decay_t<decltype(d)>;
            using T = std::decay_t<decltype(t)>;
            fn(static_cast<N*>(nullptr), static_cast<D*>(nullptr), static_cast<T*>(nullptr));
        },
        rep.normal, rep.damping, rep.tangential);
}

/// Calls fn(N*, D*, T*, begin, end) for every non-empty bucket of `list` with the concrete axis
/// types of the bucket's law form: the one dispatch per bucket.
template <class Fn>
void forEachBucket(const ContactList& list, const LawTable& laws, Fn&& fn) {
    for (std::uint32_t f = 0; f + 1 < list.bucketStart.size(); ++f) {
        const auto b = list.bucketStart[f], e = list.bucketStart[f + 1];
        if (b == e) continue;
        visitForm(laws.formRepresentative(f), [&](auto* nT, auto* dT, auto* tT) { fn(nT, dT, tT, b, e); });
    }
}

/// Disk-disk contacts of one bucket. n points from i to j; t = perp(n).
/// Tangential displacement [m] of the contact points during the step, from the drift velocities.
inline Real tangentialIncrement(const DriftVelocities& d, std::uint32_t i, std::uint32_t j, Real ri, Real rj,
                                Real nx, Real ny, Real dt) noexcept {
    const Real wsum = d.omega[i] * ri + d.omega[j] * rj;
    const Real vrx = d.vx[i] - d.vx[j] - wsum * ny;
    const Real vry = d.vy[i] - d.vy[j] + wsum * nx;
    return (-vrx * ny + vry * nx) * dt;
}

template <class N, class D, class T, bool kRolling>
void diskPairs(model::ParticleStore& s, ContactList& list, std::uint32_t begin, std::uint32_t end,
               const LawTable& laws, const DriftVelocities& drift, Real dt, Real overlapGuard, bool trialHistory,
               ForceStats& stats) noexcept {
    const std::uint32_t nm = laws.materialCount();
    const ContactLaw* table = laws.laws().data();
    const Real* __restrict x = s.x.data();
    const Real* __restrict y = s.y.data();
    const Real* __restrict vx = s.vx.data();
    const Real* __restrict vy = s.vy.data();
    const Real* __restrict om = s.omega.data();
    const Real* __restrict rad = s.radius.data();
    const Real* __restrict mass = s.mass.data();
    const std::uint32_t* __restrict mat = s.material.data();
    Real* __restrict fx = s.fx.data();
    Real* __restrict fy = s.fy.data();
    Real* __restrict tq = s.torque.data();
    const std::uint32_t* __restrict pi = list.first.data();
    const std::uint32_t* __restrict pj = list.second.data();
    // History is read and written through one pointer: the accepted springs, or (iterating
    // integrators) the trial copy that computeForces refreshed from them.
    Real* __restrict xiHist = trialHistory ? list.xiTrial.data() : list.xi.data();
    constexpr bool rolling = kRolling;  // some law has rolling resistance (a compile-time switch)
    Real* __restrict zetaHist = trialHistory ? list.zetaTrial.data() : list.zeta.data();
    std::uint64_t contacts = 0;
    Real maxRel = stats.maxRelativeOverlap;
    for (std::uint32_t p = begin; p < end; ++p) {
        const std::uint32_t i = pi[p], j = pj[p];
        const Real dx = x[j] - x[i], dy = y[j] - y[i];
        const Real ri = rad[i], rj = rad[j];
        const Real rsum = ri + rj;
        const Real r2 = dx * dx + dy * dy;
        if (r2 >= rsum * rsum) {
            xiHist[p] = 0;
            if (rolling) zetaHist[p] = 0;
            continue;
        }
        ++contacts;
        const Real r = std::sqrt(r2);
        const Real invR = r > 0 ? 1.0 / r : 0.0;
        const Real nx = r > 0 ? dx * invR : 1.0, ny = r > 0 ? dy * invR : 0.0;
        const Real overlap = rsum - r;
        if (overlapGuard > 0 && overlap > overlapGuard * (ri < rj ? ri : rj)) {  // seed's guard, off by default
            ++stats.guardSkips;  // history kept as it is; the overlap still counts for the diagnosis
            const Real rel = overlap / (ri < rj ? ri : rj);
            maxRel = rel > maxRel ? rel : maxRel;
            continue;
        }
        // Relative velocity of i's contact point w.r.t. j's: v_i - v_j + (w_i r_i + w_j r_j) perp(n).
        const Real wsum = om[i] * ri + om[j] * rj;
        const Real vrx = vx[i] - vx[j] - wsum * ny;
        const Real vry = vy[i] - vy[j] + wsum * nx;
        const Real mi = mass[i], mj = mass[j];
        ContactKinematics k;
        k.overlap = overlap;
        k.vn = vrx * nx + vry * ny;
        k.vt = -vrx * ny + vry * nx;
        k.meff = mi * mj / (mi + mj);
        // R_eff costs a division: only for laws that use it (Hertz, Mindlin, rolling).
        constexpr bool kLawUsesReff = std::is_same_v<N, HertzNormal> || std::is_same_v<T, MindlinTangential>;
        k.reff = (kLawUsesReff || rolling) ? ri * rj / rsum : 0.0;
        k.dxt = 0;
        if (!std::is_same_v<T, NoFriction> || rolling)
            if (drift.vx) k.dxt = tangentialIncrement(drift, i, j, ri, rj, nx, ny, dt);
        k.vroll = 0;
        k.dxroll = 0;
        Real zeta = 0;
        if (rolling) {  // cfddem Eq. 3.58 along t
            const Real sizeTerm = 0.5 * (rj - ri) / rsum;
            k.vroll = -k.reff * (om[i] - om[j]) - sizeTerm * k.vt;
            if (drift.vx) k.dxroll = -k.reff * (drift.omega[i] - drift.omega[j]) * dt - sizeTerm * k.dxt;
            zeta = zetaHist[p];
        }
        const auto law = resolve<N, D, T>(table[static_cast<std::size_t>(mat[i]) * nm + mat[j]]);
        const ContactForce f = evaluateContact<N, D, T, kRolling>(law, k, xiHist[p], zeta);
        if constexpr (kRolling) {
            zetaHist[p] = zeta;
            tq[i] += f.rollingTorque;
            tq[j] -= f.rollingTorque;
        }
        // Force on i: -fn n + ft t.
        const Real fxi = -f.fn * nx - f.ft * ny;
        const Real fyi = -f.fn * ny + f.ft * nx;
        fx[i] += fxi;
        fy[i] += fyi;
        fx[j] -= fxi;
        fy[j] -= fyi;
        tq[i] += ri * f.ft;  // arm r_i n, force component ft along perp(n)
        tq[j] += rj * f.ft;
        const Real rel = overlap / (ri < rj ? ri : rj);
        maxRel = rel > maxRel ? rel : maxRel;
    }
    stats.contacts += contacts;
    stats.maxRelativeOverlap = maxRel;
}

/// Disk-wall contacts of one bucket. n points from the wall to the disk centre.
template <class N, class D, class T>
void diskWalls(model::ParticleStore& s, const model::WallSet& walls, ContactList& list, std::uint32_t begin,
               std::uint32_t end, const LawTable& laws, const DriftVelocities& drift, Real dt, bool trialHistory,
               ForceStats& stats, std::vector<Vec2>& wallForce) noexcept {
    const std::uint32_t nm = laws.materialCount();
    const ContactLaw* table = laws.laws().data();
    std::uint64_t contacts = 0;
    for (std::uint32_t p = begin; p < end; ++p) {
        const std::uint32_t i = list.first[p];
        const auto& seg = walls.segments[list.second[p]];
        const Vec2 c{s.x[i], s.y[i]};
        const Real r = s.radius[i];
        const auto g = geom::diskSegmentContact(c, r, seg.a, seg.b, seg.startShared, seg.endShared,
                                                seg.prevDirection);
        Real* xiHist = trialHistory ? list.xiTrial.data() : list.xi.data();
        const bool rolling = laws.hasRolling();
        Real* zetaHist = trialHistory ? list.zetaTrial.data() : list.zeta.data();
        if (!g.touching || g.overlap <= 0) {
            xiHist[p] = 0;
            if (rolling) zetaHist[p] = 0;
            continue;
        }
        ++contacts;
        const Vec2 n = g.normal;
        const Vec2 wallVel = walls.walls[seg.wall].velocity;
        // Contact point at -r n from the centre: v_c = v - w r perp(n).
        const Real w = s.omega[i] * r;
        const Vec2 vrel{s.vx[i] + w * n.y - wallVel.x, s.vy[i] - w * n.x - wallVel.y};
        ContactKinematics k;
        k.overlap = g.overlap;
        k.vn = -dot(vrel, n);
        k.vt = dot(vrel, perp(n));
        k.meff = s.mass[i];
        k.reff = r;
        k.dxt = 0;
        if (!std::is_same_v<T, NoFriction> || rolling) {
            if (drift.vx) {
                const Real wh = drift.omega[i] * r;
                const Vec2 vh{drift.vx[i] + wh * n.y - wallVel.x, drift.vy[i] - wh * n.x - wallVel.y};
                k.dxt = dot(vh, perp(n)) * dt;
            }
        }
        k.vroll = 0;
        k.dxroll = 0;
        Real zeta = 0;
        if (rolling) {  // Eq. 3.58 with R_wall -> infinity, in the pair frame of the disk
            k.vroll = -r * s.omega[i] + 0.5 * k.vt;
            if (drift.vx) k.dxroll = -r * drift.omega[i] * dt + 0.5 * k.dxt;
            zeta = zetaHist[p];
        }
        const auto law = resolve<N, D, T>(table[static_cast<std::size_t>(s.material[i]) * nm + seg.material]);
        const ContactForce f = evaluateContact(law, k, xiHist[p], zeta);
        if (rolling) {
            zetaHist[p] = zeta;
            s.torque[i] += f.rollingTorque;
        }
        const Real fxi = f.fn * n.x - f.ft * n.y;
        const Real fyi = f.fn * n.y + f.ft * n.x;
        s.fx[i] += fxi;
        s.fy[i] += fyi;
        s.torque[i] -= r * f.ft;  // arm -r n
        wallForce[seg.wall] -= Vec2{fxi, fyi};
        stats.maxRelativeOverlap = std::max(stats.maxRelativeOverlap, g.overlap / r);
    }
    stats.wallContacts += contacts;
}

template <class D>
constexpr bool kAreaDamping = std::is_same_v<D, NoDamping> || std::is_same_v<D, AreaDamping>;
template <class T>
constexpr bool kAreaTangential = std::is_same_v<T, NoFriction> || std::is_same_v<T, AreaFriction>;
/// True for the law forms of the overlap-depth kernels (disks only).
template <class N, class D, class T>
constexpr bool kDepthForm = !std::is_same_v<N, AreaNormal> && !std::is_same_v<D, AreaDamping> &&
                            !std::is_same_v<T, AreaFriction>;
/// True for the forms of the gc2d area kernel (validation rejects mixed forms).
template <class N, class D, class T>
constexpr bool kAreaForm = std::is_same_v<N, AreaNormal> && kAreaDamping<D> && kAreaTangential<T>;

/// Contact-point velocities of slot i for lever arm r (v + omega z x r), actual and drift.
inline Vec2 pointVelocity(const Real* vx, const Real* vy, const Real* om, std::uint32_t i, Vec2 r) noexcept {
    return Vec2{vx[i], vy[i]} + perp(r) * om[i];
}

/// gc2d area contacts of one bucket of particle pairs (any shapes).
template <class D, class T>
void areaPairs(model::ParticleStore& s, ContactList& list, std::uint32_t begin, std::uint32_t end, const LawTable& laws,
               const DriftVelocities& drift, Real dt, bool trialHistory, ForceStats& stats, ShapeContext& sc) noexcept {
    const std::uint32_t nm = laws.materialCount();
    const ContactLaw* table = laws.laws().data();
    Real* xiHist = trialHistory ? list.xiTrial.data() : list.xi.data();
    Real* areaHist = trialHistory ? list.areaOldTrial.data() : list.areaOld.data();
    std::uint64_t contacts = 0;
    Real maxRel = stats.maxRelativeOverlap;
    const Real invDt = 1.0 / dt;
    // Two passes over batches of touching pairs: geometry first, then the law. The law's short,
    // independent iterations let the processor overlap their square roots and divisions; the
    // forces are still summed in pair order (bit-identical to a single pass).
    struct Pending {
        std::uint32_t p, i, j;
        geom::AreaContact g;
    };
    constexpr int kBatch = 32;
    Pending batch[kBatch];
    int pending = 0;
    const auto flush = [&] {
        for (int b = 0; b < pending; ++b) {
            const Pending& q = batch[b];
            const std::uint32_t i = q.i, j = q.j;
            area::AreaPair c;
            c.g = q.g;
            c.ri = c.g.point - Vec2{s.x[i], s.y[i]};
            c.rj = c.g.point - Vec2{s.x[j], s.y[j]};
            c.vi = pointVelocity(s.vx.data(), s.vy.data(), s.omega.data(), i, c.ri);
            c.vj = pointVelocity(s.vx.data(), s.vy.data(), s.omega.data(), j, c.rj);
            if (drift.vx) {
                c.hasDrift = true;
                c.di = pointVelocity(drift.vx, drift.vy, drift.omega, i, c.ri);
                c.dj = pointVelocity(drift.vx, drift.vy, drift.omega, j, c.rj);
            }
            c.invMi = s.invMass[i];
            c.invMj = s.invMass[j];
            c.invIi = s.invInertia[i];
            c.invIj = s.invInertia[j];
            const ContactLaw& law = table[static_cast<std::size_t>(s.material[i]) * nm + s.material[j]];
            const area::AreaForce f =
                area::areaLaw(*std::get_if<AreaNormal>(&law.normal), *std::get_if<D>(&law.damping),
                              *std::get_if<T>(&law.tangential), c, dt, invDt, xiHist[q.p], areaHist[q.p]);
            s.fx[i] += f.onI.x;
            s.fy[i] += f.onI.y;
            s.fx[j] -= f.onI.x;
            s.fy[j] -= f.onI.y;
            s.torque[i] += cross(c.ri, f.onI);
            s.torque[j] -= cross(c.rj, f.onI);
            const Real rMin = std::min(s.radius[i], s.radius[j]);
            if (f.overlapDepth > maxRel * rMin) maxRel = f.overlapDepth / rMin;  // divide only for a new maximum
        }
        pending = 0;
    };
    for (std::uint32_t p = begin; p < end; ++p) {
        const std::uint32_t i = list.first[p], j = list.second[p];
        const Real dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i], rsum = s.radius[i] + s.radius[j];
        if (dx * dx + dy * dy >= rsum * rsum) {  // bounding circles apart: no contact possible
            xiHist[p] = 0;
            areaHist[p] = 0;
            continue;
        }
        Pending& q = batch[pending];
        q.g = area::pairGeometry(s, sc, i, j, list.features[p]);
        if (!q.g.touching) {
            xiHist[p] = 0;
            areaHist[p] = 0;
            continue;
        }
        ++contacts;
        q.p = p;
        q.i = i;
        q.j = j;
        if (++pending == kBatch) flush();
    }
    flush();
    stats.contacts += contacts;
    stats.maxRelativeOverlap = maxRel;
}

/// gc2d area contacts of particles with wall segments.
template <class D, class T>
void areaWalls(model::ParticleStore& s, const model::WallSet& walls, ContactList& list, std::uint32_t begin,
               std::uint32_t end, const LawTable& laws, const DriftVelocities& drift, Real dt, bool trialHistory,
               ForceStats& stats, std::vector<Vec2>& wallForce, ShapeContext& sc) noexcept {
    const std::uint32_t nm = laws.materialCount();
    const ContactLaw* table = laws.laws().data();
    Real* xiHist = trialHistory ? list.xiTrial.data() : list.xi.data();
    Real* areaHist = trialHistory ? list.areaOldTrial.data() : list.areaOld.data();
    std::uint64_t contacts = 0;
    for (std::uint32_t p = begin; p < end; ++p) {
        const std::uint32_t i = list.first[p];
        const auto& seg = walls.segments[list.second[p]];
        const Vec2 xi{s.x[i], s.y[i]};
        area::AreaPair c;
        c.wall = true;
        c.g = area::wallGeometry(s, sc, i, seg.a, seg.b, list.features[p]);
        if (!c.g.touching) {
            xiHist[p] = 0;
            areaHist[p] = 0;
            continue;
        }
        ++contacts;
        const Vec2 wallVel = walls.walls[seg.wall].velocity;
        c.ri = c.g.point - xi;
        c.vi = pointVelocity(s.vx.data(), s.vy.data(), s.omega.data(), i, c.ri);
        c.vj = wallVel;
        if (drift.vx) {
            c.hasDrift = true;
            c.di = pointVelocity(drift.vx, drift.vy, drift.omega, i, c.ri);
            c.dj = wallVel;
        }
        c.invMi = s.invMass[i];
        c.invIi = s.invInertia[i];
        const ContactLaw& law = table[static_cast<std::size_t>(s.material[i]) * nm + seg.material];
        const area::AreaForce f = area::areaLaw(*std::get_if<AreaNormal>(&law.normal), *std::get_if<D>(&law.damping),
                                                *std::get_if<T>(&law.tangential), c, dt, 1.0 / dt, xiHist[p], areaHist[p]);
        s.fx[i] += f.onI.x;
        s.fy[i] += f.onI.y;
        s.torque[i] += cross(c.ri, f.onI);
        wallForce[seg.wall] -= f.onI;
        stats.maxRelativeOverlap = std::max(stats.maxRelativeOverlap, f.overlapDepth / s.radius[i]);
    }
    stats.wallContacts += contacts;
}

}  // namespace

void ShapeContext::update(const model::ParticleStore& s) {
    if (!anyPolygon) return;
    const std::size_t n = s.size();
    first.resize(n);
    std::size_t total = 0;
    for (std::size_t i = 0; i < n; ++i) {
        first[i] = static_cast<std::uint32_t>(total);
        if (s.shape[i] != model::kDiskShape) total += pool->count[s.shape[i]];
    }
    world.resize(total);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t k = s.shape[i];
        if (k == model::kDiskShape) continue;
        const Real c = std::cos(s.angle[i]), sn = std::sin(s.angle[i]);
        const Vec2 x{s.x[i], s.y[i]};
        const Vec2* body = pool->corners.data() + pool->start[k];
        Vec2* out = world.data() + first[i];
        for (std::uint32_t m = 0; m < pool->count[k]; ++m)
            out[m] = {x.x + (c * body[m].x - sn * body[m].y), x.y + (sn * body[m].x + c * body[m].y)};
    }
}

void computeForces(model::ParticleStore& s, const model::WallSet& walls, NeighborList& list, const LawTable& laws,
                   const BodyForces& body, const DriftVelocities& drift, Real dt, bool trialHistory,
                   ForceStats& stats, std::vector<Vec2>& wallForce, ShapeContext& shapes) noexcept {
    const std::size_t n = s.size();
    for (std::size_t i = 0; i < n; ++i) {
        s.fx[i] = s.mass[i] * body.gravity.x - body.gamma * s.vx[i];
        s.fy[i] = s.mass[i] * body.gravity.y - body.gamma * s.vy[i];
        s.torque[i] = -body.gammaRotation * s.omega[i];
    }
    if (body.springs)
        for (const PullSpring& sp : *body.springs) {  // gc2d spec section 3.8
            const std::uint32_t i = sp.slot;
            const Real c = std::cos(s.angle[i]), sn = std::sin(s.angle[i]);
            const Vec2 arm{c * sp.attach.x - sn * sp.attach.y, sn * sp.attach.x + c * sp.attach.y};
            const Vec2 f = (sp.freeEnd(body.time) - (Vec2{s.x[i], s.y[i]} + arm)) * sp.stiffness;
            s.fx[i] += f.x;
            s.fy[i] += f.y;
            s.torque[i] += cross(arm, f);
        }
    stats = ForceStats{};
    for (auto& w : wallForce) w = Vec2{};
    if (trialHistory) {  // every evaluation of a step starts from the accepted history
        for (auto* l : {&list.pairs, &list.wallPairs}) {
            std::copy(l->xi.begin(), l->xi.end(), l->xiTrial.begin());
            std::copy(l->zeta.begin(), l->zeta.end(), l->zetaTrial.begin());
            std::copy(l->areaOld.begin(), l->areaOld.end(), l->areaOldTrial.begin());
        }
    }
    shapes.update(s);
    forEachBucket(list.pairs, laws, [&](auto* nT, auto* dT, auto* tT, std::uint32_t b, std::uint32_t e) {
        using N = std::remove_pointer_t<decltype(nT)>;
        using D = std::remove_pointer_t<decltype(dT)>;
        using T = std::remove_pointer_t<decltype(tT)>;
        if constexpr (kAreaForm<N, D, T>) {
            areaPairs<D, T>(s, list.pairs, b, e, laws, drift, dt, trialHistory, stats, shapes);
        } else if constexpr (kDepthForm<N, D, T>) {
            if (laws.hasRolling())
                diskPairs<N, D, T, true>(s, list.pairs, b, e, laws, drift, dt, body.overlapGuard, trialHistory, stats);
            else
                diskPairs<N, D, T, false>(s, list.pairs, b, e, laws, drift, dt, body.overlapGuard, trialHistory, stats);
        }
    });
    forEachBucket(list.wallPairs, laws, [&](auto* nT, auto* dT, auto* tT, std::uint32_t b, std::uint32_t e) {
        using N = std::remove_pointer_t<decltype(nT)>;
        using D = std::remove_pointer_t<decltype(dT)>;
        using T = std::remove_pointer_t<decltype(tT)>;
        if constexpr (kAreaForm<N, D, T>)
            areaWalls<D, T>(s, walls, list.wallPairs, b, e, laws, drift, dt, trialHistory, stats, wallForce, shapes);
        else if constexpr (kDepthForm<N, D, T>)
            diskWalls<N, D, T>(s, walls, list.wallPairs, b, e, laws, drift, dt, trialHistory, stats, wallForce);
    });
}

namespace {
/// Energy of the area contacts of one bucket: F_n h_eff / 2 + k_t xi^2 / 2.
template <class T>
Real areaEnergy(const model::ParticleStore& s, const model::WallSet& walls, const ContactList& cl, std::uint32_t b,
                std::uint32_t e, const LawTable& laws, bool wall, ShapeContext& sc) {
    Real energy = 0;
    const std::uint32_t nm = laws.materialCount();
    for (std::uint32_t p = b; p < e; ++p) {
        const std::uint32_t i = cl.first[p];
        geom::FeatureCache cache = cl.features[p];  // a copy: energies do not disturb the tracking
        geom::AreaContact g;
        std::uint32_t otherMat;
        Real l;
        if (wall) {
            const auto& seg = walls.segments[cl.second[p]];
            g = area::wallGeometry(s, sc, i, seg.a, seg.b, cache);
            otherMat = seg.material;
            l = norm(g.point - Vec2{s.x[i], s.y[i]});
        } else {
            const std::uint32_t j = cl.second[p];
            g = area::pairGeometry(s, sc, i, j, cache);
            otherMat = s.material[j];
            const Real ri = norm(g.point - Vec2{s.x[i], s.y[i]}), rj = norm(g.point - Vec2{s.x[j], s.y[j]});
            l = ri + rj > 0 ? ri * rj / (ri + rj) : 0;
        }
        if (!g.touching || !(l > 0)) continue;
        const ContactLaw& law = laws.laws()[static_cast<std::size_t>(s.material[i]) * nm + otherMat];
        const AreaNormal& nl = *std::get_if<AreaNormal>(&law.normal);
        const Real h = g.area / l;
        energy += 0.5 * nl.E * h * h;
        if constexpr (std::is_same_v<T, AreaFriction>) {
            const Real kt = std::get_if<AreaFriction>(&law.tangential)->kt;
            energy += 0.5 * kt * cl.xi[p] * cl.xi[p];
        }
    }
    return energy;
}
}  // namespace

Real contactEnergy(const model::ParticleStore& s, const model::WallSet& walls, const NeighborList& list,
                   const LawTable& laws, const model::ShapePool& shapes) {
    Real energy = 0;
    const std::uint32_t nm = laws.materialCount();
    ShapeContext sc;  // own world corners and statistics: energies do not disturb the step
    sc.pool = &shapes;
    sc.anyPolygon = shapes.size() > 0;
    sc.update(s);
    const auto eval = [&](const ContactList& cl, bool wall) {
        forEachBucket(cl, laws, [&](auto* nT, auto* dT, auto* tT, std::uint32_t b, std::uint32_t e) {
            using N = std::remove_pointer_t<decltype(nT)>;
            using D = std::remove_pointer_t<decltype(dT)>;
            using T = std::remove_pointer_t<decltype(tT)>;
            if constexpr (kAreaForm<N, D, T>) {
                energy += areaEnergy<T>(s, walls, cl, b, e, laws, wall, sc);
            } else if constexpr (kDepthForm<N, D, T>) {
                for (std::uint32_t p = b; p < e; ++p) {
                    const std::uint32_t i = cl.first[p];
                    Real overlap, reff;
                    std::uint32_t otherMat;
                    if (wall) {
                        const auto& seg = walls.segments[cl.second[p]];
                        const auto g = geom::diskSegmentContact({s.x[i], s.y[i]}, s.radius[i], seg.a, seg.b,
                                                                seg.startShared, seg.endShared, seg.prevDirection);
                        overlap = g.touching ? g.overlap : 0;
                        reff = s.radius[i];
                        otherMat = seg.material;
                    } else {
                        const std::uint32_t j = cl.second[p];
                        const Real dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i];
                        overlap = s.radius[i] + s.radius[j] - std::sqrt(dx * dx + dy * dy);
                        reff = s.radius[i] * s.radius[j] / (s.radius[i] + s.radius[j]);
                        otherMat = s.material[j];
                    }
                    if (overlap <= 0) continue;
                    const auto law = resolve<N, D, T>(laws.laws()[static_cast<std::size_t>(s.material[i]) * nm + otherMat]);
                    energy += dem::contactEnergy(law, overlap, reff, cl.xi[p], cl.zeta.empty() ? 0.0 : cl.zeta[p]);
                }
            }
        });
    };
    eval(list.pairs, false);
    eval(list.wallPairs, true);
    return energy;
}

}  // namespace granulab::dem
