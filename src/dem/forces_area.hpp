// SPDX-License-Identifier: MIT
// Force kernel of the gc2d overlap-area contact model (gc2d spec section 3, Eq. 2.15-2.29 with
// errata 1-5 of section 12) for every shape pair: polygon-polygon (tracked crossings),
// disk-polygon, disk-disk (lens) and particle-wall (a wall segment acts as an immovable convex
// quadrilateral of thickness 2 r behind the segment, on the side away from the particle); also the
// energy-conserving area_potential law (Feng, Han & Owen 2012) through the same kernel.
// Included by dem/forces_area_pairs.hpp (the kernels of one bucket) and dem/contact_energy.cpp;
// D and T are the damping and tangential alternatives of the bucket.
#pragma once
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "dem/forces.hpp"
#include "geom/circle_contact.hpp"
#include "geom/convex_contact.hpp"
#include "geom/convex_crossings.hpp"

namespace granulab::dem::area {

/// Frame of the polygon particle i (the shape must not be kDiskShape).
inline geom::PolygonFrame frameOf(const model::ParticleStore& s, const ShapeContext& sc,
                                  std::uint32_t i) noexcept {
    const std::uint32_t k = s.shape[i];
    GL_ASSERT(k != model::kDiskShape && k < sc.pool->size() && i < sc.first.size(), "a polygon of the pool");
    geom::PolygonFrame f;
    f.corners = sc.world.data() + sc.first[i];
    f.n = static_cast<int>(sc.pool->count[k]);
    f.centre = {s.x[i], s.y[i]};
    f.inradius = sc.pool->inradius[k] * sc.scale;
    return f;
}

/// Geometry of the pair (i, j), normal pushing i away from j, written to `out` (in place: the
/// pair kernel's batch slot, so that the result is not copied through the stack). kDeferNormal:
/// a persistent polygon contact refreshed inline leaves out.normal unset and returns true; the
/// caller completes it with geom::crossings::chainNormal(out, x_i, x_j) (the same arithmetic,
/// in its batched law pass). Returns false when out is complete.
template <bool kDeferNormal = false>
inline bool pairGeometryInto(const model::ParticleStore& s, const ShapeContext& sc, std::uint32_t i,
                             std::uint32_t j, geom::FeatureCache& cache, geom::FeatureStats& features,
                             geom::AreaContact& out) noexcept {
    const bool pi = s.shape[i] != model::kDiskShape, pj = s.shape[j] != model::kDiskShape;
    const Vec2 ci{s.x[i], s.y[i]}, cj{s.x[j], s.y[j]};
    if (pi && pj) {
        const geom::PolygonFrame fi = frameOf(s, sc, i), fj = frameOf(s, sc, j);
        // A persistent contact (both cached crossings hold) is refreshed inline.
        if (geom::crossings::refreshCrossings<!kDeferNormal>(fi, fj, cache, features, out))
            return kDeferNormal;
        // A persistent near miss whose cached features still prove it apart.
        if (geom::crossings::stillApart(fi, fj, cache, features)) {
            out = geom::AreaContact{};
            return false;
        }
        out = geom::trackPolygonContact(fi, fj, cache, features);
        return false;
    }
    if (!pi && !pj) {
        out = geom::circleCircleContact(ci, s.radius[i], cj, s.radius[j]);
        return false;
    }
    if (!pi) {
        const auto f = frameOf(s, sc, j);
        out = geom::circlePolygonContact(ci, s.radius[i], f.corners, f.n);
        return false;
    }
    const auto f = frameOf(s, sc, i);
    geom::AreaContact& g = out;
    g = geom::circlePolygonContact(cj, s.radius[j], f.corners, f.n);
    g.normal = -g.normal;  // computed for the disk j
    std::swap(g.c1, g.c2);
    g.pull = -g.pull;  // the closed overlap boundary: sum of n L and its moment vanish
    g.twist = -g.twist;
    return false;
}

/// Geometry of the pair (i, j), normal pushing i away from j.
inline geom::AreaContact pairGeometry(const model::ParticleStore& s, const ShapeContext& sc, std::uint32_t i,
                                      std::uint32_t j, geom::FeatureCache& cache,
                                      geom::FeatureStats& features) noexcept {
    geom::AreaContact g;
    pairGeometryInto(s, sc, i, j, cache, features, g);
    return g;
}

/// The immovable quadrilateral standing for a wall segment behind its face seen from `from`.
struct WallQuad {
    Vec2 world[4];  ///< [m] corners, counter-clockwise
    geom::PolygonFrame frame;
};

/// Unit direction of a plate's end edge at a shared corner, into the solid side `out`: the bisector
/// of the angle between the segment (e, the unit direction from the corner along it) and its
/// neighbour (u, from the corner along the neighbouring segment; zero: no neighbour), where the
/// corner is convex seen from the grain. Two plates that meet there then divide the wedge behind
/// it along the bisector, and a grain pressing on the corner has its overlap counted once (with
/// square ends both plates held the whole wedge, and the grain felt it twice). Perpendicular (out)
/// elsewhere: without a neighbour; at a concave corner, where a mitre would lean past the segment's
/// end into space that is free on the grain's side (a polyline is solid on both sides, so the plate
/// behind a face seen from outside a corner lies where other grains may be); for a straight
/// continuation; and at a corner sharper than about 23 degrees, whose mitre would reach more than
/// 5 thicknesses along the wall.
inline Vec2 plateEnd(Vec2 e, Vec2 u, Vec2 out) noexcept {
    constexpr Real kMinSlant = 0.2;  // cosine between the end edge and `out`
    const Vec2 m = e + u;
    const Real len = norm(m);
    if ((u.x == 0 && u.y == 0) || !(len > 1e-9)) return out;
    const Vec2 unit = dot(m, out) >= 0 ? m / len : m / -len;
    if (dot(unit, e) <= 0) return out;  // leans outwards: a concave corner seen from the grain
    return dot(unit, out) >= kMinSlant ? unit : out;
}

/// The plate of thickness `thickness` behind segment [a, b], on the side away from `from`, its ends
/// mitred along the bisectors of the corners it shares (plateEnd): nextAtA / nextAtB [unit] point
/// from a / b along the neighbouring segment (zero where the end is free). Falls back to square
/// ends where the mitres would cross within the thickness (a segment shorter than the plate).
inline void wallQuad(Vec2 a, Vec2 b, Vec2 from, Real thickness, WallQuad& q, Vec2 nextAtA = {},
                     Vec2 nextAtB = {}) noexcept {
    if (cross(b - a, from - a) < 0) {  // particle on the left of a -> b
        std::swap(a, b);
        std::swap(nextAtA, nextAtB);
    }
    const Vec2 d = b - a;
    const Real len = norm(d);
    const Vec2 out = len > 0 ? Vec2{d.y, -d.x} / len : Vec2{0, -1};  // right of a -> b: the solid side
    const Vec2 e = len > 0 ? d / len : Vec2{1, 0};
    const Vec2 endA = plateEnd(e, nextAtA, out), endB = plateEnd(-e, nextAtB, out);
    Vec2 farA = a + endA * (thickness / dot(endA, out)), farB = b + endB * (thickness / dot(endB, out));
    if (!(dot(farB - farA, d) > 0)) {  // the mitres cross: square ends
        farA = a + out * thickness;
        farB = b + out * thickness;
    }
    const Vec2 w[4] = {a, farA, farB, b};  // counter-clockwise
    for (int k = 0; k < 4; ++k) q.world[k] = w[k];
    q.frame.corners = q.world;
    q.frame.n = 4;
    q.frame.centre = (w[0] + w[1] + w[2] + w[3]) * 0.25;
    Real inradius = thickness;  // about the centre: its distance to the nearest edge line
    for (int k = 0; k < 4; ++k) {
        const Vec2 edge = w[(k + 1) % 4] - w[k];
        const Real l = norm(edge);
        if (l > 0) inradius = std::min(inradius, std::abs(cross(edge, q.frame.centre - w[k])) / l);
    }
    q.frame.inradius = inradius;
}

/// Geometry of particle i (polygon or disk) against an immovable convex polygon `wall` (world
/// corners counter-clockwise), normal pushing i away from the wall; pull and twist (the area
/// gradient of i, for area_potential) as for a particle pair.
inline geom::AreaContact particleWallGeometry(const model::ParticleStore& s, const ShapeContext& sc,
                                              std::uint32_t i, const geom::PolygonFrame& wall,
                                              geom::FeatureCache& cache,
                                              geom::FeatureStats& features) noexcept {
    if (s.shape[i] != model::kDiskShape)
        return geom::trackPolygonContact(frameOf(s, sc, i), wall, cache, features);
    return geom::circlePolygonContact({s.x[i], s.y[i]}, s.radius[i], wall.corners, wall.n);
}

/// Geometry of particle i against the wall of segment `segIndex`, normal pushing i away from the
/// wall: a convex body wall is one immovable polygon (gc2d spec 3.7, one contact per grain); a
/// polyline segment acts as the plate of thickness 2 r behind it. Not touching for a wall that is
/// not solid (an outlet's lid after it opened).
inline geom::AreaContact wallGeometry(const model::ParticleStore& s, const ShapeContext& sc,
                                      const model::WallSet& walls, std::uint32_t i, std::uint32_t segIndex,
                                      geom::FeatureCache& cache, geom::FeatureStats& features) noexcept {
    const auto& seg = walls.segments[segIndex];
    const model::Wall& wall = walls.walls[seg.wall];
    if (!wall.solid) return {};
    if (wall.body) {
        geom::PolygonFrame body;
        body.corners = walls.corners.data() + wall.firstSegment;
        body.n = static_cast<int>(wall.segmentCount);
        body.centre = walls.bodyCentroid[seg.wall];
        body.inradius = walls.bodyInradius[seg.wall];
        return particleWallGeometry(s, sc, i, body, cache, features);
    }
    // The neighbours at the shared corners (a polyline's plates are mitred there).
    const Vec2 nextAtA = seg.startShared ? -seg.prevDirection : Vec2{};
    Vec2 nextAtB{};
    if (seg.endShared) {
        const std::uint32_t last = wall.firstSegment + wall.segmentCount - 1;
        const auto& next = walls.segments[segIndex == last ? wall.firstSegment : segIndex + 1];
        const Vec2 dn = next.b - next.a;
        const Real ln = norm(dn);
        if (ln > 0) nextAtB = dn / ln;
    }
    WallQuad quad;
    wallQuad(seg.a, seg.b, {s.x[i], s.y[i]}, 2 * s.radius[i], quad, nextAtA, nextAtB);
    return particleWallGeometry(s, sc, i, quad.frame, cache, features);
}

/// Everything the gc2d law needs about one contact; j may be a wall (infinite mass).
struct AreaPair {
    geom::AreaContact g;
    Vec2 ri, rj;  ///< [m] lever arms s - x_i, s - x_j (rj: from a body wall's centroid; unused for polylines)
    Vec2 vi, vj;  ///< [m/s] contact-point velocities (vj: wall surface velocity)
    Vec2 di, dj;  ///< [m/s] contact-point drift velocities for the spring increment
    bool hasDrift = false;
    Real invMi = 0, invMj = 0;  ///< [1/kg] (0 for walls)
    Real invIi = 0, invIj = 0;  ///< [1/(kg m^2)]
    /// [1/m] area_potential only: 1/l0 = (R_i + R_j)/(R_i R_j) from the bounding radii; 1/R_i at a wall
    Real invL0 = 0;
    bool wall = false;
    bool wallBody = false;  ///< a convex body wall: rj is the arm from the wall's centroid
};

struct AreaForce {
    Vec2 onI;           ///< [N] force on i at the contact point s (on j: the opposite)
    Real overlapDepth;  ///< [m] h_eff = A / l
    Real couple = 0;    ///< [N m] area_potential: torque on i about s besides r_i x onI (on j: -couple)
};

/// 1/l0 [1/m] of the energy-conserving law for bounding radii R_i, R_j [m] (l0 = R_i R_j/(R_i + R_j)).
inline Real potentialInvL0(Real boundI, Real boundJ) noexcept {
    return (boundI + boundJ) / (boundI * boundJ);
}

/// gc2d Eq. 2.20-2.29 for one contact; updates the spring xi [m] and the old area [m^2].
/// `invDt` = 1/dt [1/s]; `dt` [s]. N is AreaNormal (F_el = E A / l along n) or AreaPotentialNormal
/// (the exact force of W(A) = E A^2/(2 l0^2) - k_coh A: (dU/dA) pull at s plus the couple
/// (dU/dA) twist; damping and friction as gc2d's with l = l0 and F_el = W'(A) pull . n).
template <class N, class D, class T>
[[gnu::always_inline]] inline AreaForce areaLaw(const N& nl, const D& dl, const T& tl, const AreaPair& c,
                                                Real dt, Real invDt, Real& ioXi, Real& ioAreaOld) noexcept {
    constexpr bool kPotential = std::is_same_v<N, AreaPotentialNormal>;
    const auto& g = c.g;
    Real invL;
    if constexpr (kPotential) {
        invL = c.invL0;                  // a constant of the pair: the force is a gradient
    } else if (c.wall && !c.wallBody) {  // a polyline plate: infinitely long, l = r_i (spec 3.7)
        invL = 1.0 / norm(c.ri);
    } else {  // 1/l, l = r_i r_j/(r_i + r_j) (Eq. 2.15); a body wall's r_j = |s - x_wall| (spec 3.7)
        const Real ri = norm(c.ri), rj = norm(c.rj);
        invL = (ri + rj) / (ri * rj);
    }
    AreaForce out{{0, 0}, 0};
    if (!(invL > 0) || !std::isfinite(invL)) return out;
    const Real hEff = g.area * invL;  // effective penetration depth A / l [m]
    const Vec2 n = g.normal, t = perp(n);
    Real fel, fcoh, slope = 0;  // [N], [N], dU/dA [N/m]
    if constexpr (kPotential) {
        const Real pullN = dot(g.pull, n);  // = L_c for two crossings
        fel = nl.E * hEff * invL * pullN;   // W'(A) pull . n
        fcoh = nl.cohesion * pullN;
        slope = nl.slope(g.area, invL);
    } else {
        fel = nl.E * hEff;                                               // Eq. 2.20
        fcoh = nl.cohesion > 0 ? nl.cohesion * norm(g.c2 - g.c1) : 0.0;  // Eq. 2.28
    }
    out.overlapDepth = hEff;
    Real fn = fel, damp = 0;
    if constexpr (std::is_same_v<D, AreaDamping>) {    // Eq. 2.21/2.22, erratum 1
        const Real mperp = 1.0 / (c.invMi + c.invMj);  // reduced mass; m_i at a wall
        const Real dA = g.area - ioAreaOld;
        damp = dl.gamma * std::sqrt(nl.E * mperp) * dA * invL * invDt;
        if (dA < 0) damp = std::max(damp, -fel);  // separating: never attractive
        fn += damp;
    }
    ioAreaOld = g.area;
    Real fpar = 0;
    if constexpr (std::is_same_v<T, AreaFriction>) {  // Eq. 2.23-2.27, errata 2-4
        const Real vpar = dot(c.vi - c.vj, t);
        const Real dpar = c.hasDrift ? dot(c.di - c.dj, t) : 0.0;
        ioXi += dpar * dt;  // S = k_t xi, the spring attached at first touch
        const Real invMpar =
            c.invMi + c.invMj + norm2(c.ri) * c.invIi + (c.wall ? 0.0 : norm2(c.rj) * c.invIj);
        const Real spring = tl.kt * ioXi;
        const Real visc = tl.damped ? std::sqrt(tl.kt / invMpar) * vpar : 0.0;
        const Real trial = spring + visc;
        Real cap = tl.mu * (tl.capTotal ? std::max<Real>(fn - fcoh, 0) : fel);
        if (tl.rabinowicz) {  // mu (|v|/1 m/s)^(-1/10): unbounded at rest, the spring holds
            const Real v = std::abs(vpar);
            cap = v > 0 ? cap * std::pow(v, -0.1) : std::numeric_limits<Real>::infinity();
        }
        fpar = trial >= 0 ? std::min(trial, cap) : -std::min(-trial, cap);
        if (std::abs(spring) > cap) ioXi = (ioXi >= 0 ? cap : -cap) / tl.kt;  // the spring slides along
    }
    if constexpr (kPotential) {
        out.onI = g.pull * slope + n * damp - t * fpar;  // -dU/dx_i, damping, friction
        out.couple = slope * g.twist;                    // -dU/dtheta_i - r_i x (-dU/dx_i)
    } else {
        out.onI = n * (fn - fcoh) - t * fpar;  // Eq. 2.29
    }
    return out;
}

}  // namespace granulab::dem::area
