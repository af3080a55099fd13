// SPDX-License-Identifier: MIT
// Disk-disk and disk-polygon overlap contacts (gc2d spec section 3.1, erratum 6 of section 12).
// Both reduce the area to circular segments, r^2/2 (phi - sin phi) for an arc of angle phi [rad],
// plus (for the polygon) the shoelace area of the overlap with its arcs replaced by chords.
#include "geom/circle_contact.hpp"

#include <cmath>

namespace granulab::geom {

namespace {

/// x - sin x for x in [0, 2 pi] without cancellation: Taylor series (Horner) below 1, where the
/// truncation error is < 1e-16 relative; above, the direct form loses at most a factor 6.
Real xMinusSin(Real x) noexcept {
    if (x < 1) {
        const Real x2 = x * x;
        Real s = 1 - x2 / 342;  // terms up to x^19 / 19!
        s = 1 - x2 / 272 * s;
        s = 1 - x2 / 210 * s;
        s = 1 - x2 / 156 * s;
        s = 1 - x2 / 110 * s;
        s = 1 - x2 / 72 * s;
        s = 1 - x2 / 42 * s;
        s = 1 - x2 / 20 * s;
        return x * x2 / 6 * s;
    }
    return x - std::sin(x);
}

/// Sagitta limit (relative to r) below which capArea's series is used: no transcendental call.
constexpr Real kSeriesSagitta = 0.1;

/// Area [m^2] of the circular segment of radius r [m] and sagitta (height) k <= 0.1 r [m]:
/// k sqrt(2 r k) P(k/r), P(u) = 4/3 - u/5 - u^2/56 - u^3/288 - ... (series of
/// acos(1-u) - (1-u) sqrt(2u - u^2) in u); all terms after the first are negative, so there is no
/// cancellation, and the truncation error at u = 0.1 is below 1e-18 relative.
Real capArea(Real r, Real k) noexcept {
    const Real u = k / r;
    Real p = -4199.0 / 6710886400;
    p = p * u - 2431.0 / 1543503872;
    p = p * u - 715.0 / 176160768;
    p = p * u - 429.0 / 39845888;
    p = p * u - 33.0 / 1114112;
    p = p * u - 7.0 / 81920;
    p = p * u - 7.0 / 26624;
    p = p * u - 5.0 / 5632;
    p = p * u - 1.0 / 288;
    p = p * u - 1.0 / 56;
    p = p * u - 1.0 / 5;
    p = p * u + 4.0 / 3;
    return k * std::sqrt(2 * r * k) * p;
}

/// Segment of disk radius r with sagitta k, half chord h and centre-chord distance a = r - k.
Real segmentArea(Real r, Real k, Real h, Real a) noexcept {
    if (k <= kSeriesSagitta * r) return capArea(r, k);
    return 0.5 * r * r * xMinusSin(2 * std::atan2(h, a));
}

/// Orders c1, c2 so that c2 - c1 points along perp(n) (header convention) and fills point.
void finish(AreaContact& out) noexcept {
    if (dot(out.c2 - out.c1, perp(out.normal)) < 0) {
        const Vec2 t = out.c1;
        out.c1 = out.c2;
        out.c2 = t;
    }
    out.point = (out.c1 + out.c2) * 0.5;
    out.touching = true;
}

}  // namespace

AreaContact circleCircleContact(Vec2 ci, Real ri, Vec2 cj, Real rj) noexcept {
    AreaContact out;
    if (!(ri > 0 && rj > 0)) return out;
    const Vec2 dv = ci - cj;
    const Real d = norm(dv);  // [m] distance of the centres
    // rs = ri + rj with its rounding error e (TwoSum): delta is then exact given d.
    const Real rs = ri + rj;
    const Real rb = rs - ri;
    const Real e = (ri - (rs - rb)) + (rj - rb);
    const Real delta = (rs - d) + e;  // [m] overlap depth along the line of centres
    if (!(delta > 0)) return out;
    out.normal = d > 0 ? dv / d : Vec2{1, 0};
    if (d <= std::abs(ri - rj)) {  // one disk inside the other
        const bool iSmall = ri <= rj;
        const Real rmin = iSmall ? ri : rj;
        out.area = kPi * rmin * rmin;
        // Point of the small circle on the line of centres, away from the large centre.
        out.c1 = out.c2 = iSmall ? ci + out.normal * ri : cj - out.normal * rj;
        finish(out);
        return out;
    }
    // Heron-type factors, all > 0 here: p = d - ri + rj, q = d + ri - rj.
    const Real p = d - ri + rj, q = d + ri - rj;
    const Real hi = delta * p / (2 * d);  // [m] height of the cap of disk i beyond the chord
    const Real hj = delta * q / (2 * d);  // [m] same for disk j (hi + hj = delta)
    const Real h = std::sqrt(delta * p * q * (d + rs)) / (2 * d);  // [m] half chord
    const Real ai = ri - hi, aj = rj - hj;                         // [m] signed distances centre -> chord
    out.area = segmentArea(ri, hi, h, ai) + segmentArea(rj, hj, h, aj);
    if (!(out.area > 0)) return AreaContact{};
    const Vec2 mid = ci - out.normal * ai;  // chord midpoint
    const Vec2 t = perp(out.normal) * h;
    out.c1 = mid - t;
    out.c2 = mid + t;
    out.pull = out.normal * (2 * h);  // i's arc inside j: -dA/dci = L_c n, through ci (no twist)
    finish(out);
    return out;
}

namespace {

/// Walks the polygon boundary (corners relative to the disk centre) once, reporting in boundary
/// order every corner inside the disk, onCorner(q), and every crossing of the circle,
/// onHit(p, entering). Inside-ness of corners is decided once (|q| < r), and each edge reports
/// exactly the crossings its end states imply, so entries and exits always alternate.
template <class OnCorner, class OnHit>
void walkBoundary(Vec2 centre, Real r, const Vec2* corners, int n, OnCorner&& onCorner,
                  OnHit&& onHit) noexcept {
    const Real r2 = r * r;
    const Vec2 a0 = corners[0] - centre;
    const bool in0 = norm2(a0) < r2;
    Vec2 a = a0;
    bool ina = in0;
    for (int k = 0; k < n; ++k) {
        const Vec2 b = k + 1 < n ? corners[k + 1] - centre : a0;
        const bool inb = k + 1 < n ? norm2(b) < r2 : in0;
        if (ina) onCorner(a);
        const Vec2 d = b - a;
        const Real dd = norm2(d);
        const Real cr = cross(a, d);  // |cr| / |d| = distance of the centre from the edge line
        // Both ends outside: a chord needs the line within r and the foot inside the edge.
        const bool chord = cr * cr < r2 * dd && dot(a, d) < 0 && dot(b, d) > 0;
        if (ina != inb || (!ina && chord)) {
            const Real len = std::sqrt(dd);
            const Real dist = std::abs(cr) / len;
            const Real half = dist < r ? std::sqrt((r - dist) * (r + dist)) : 0;  // [m]
            const Real t0 = -dot(a, d) / dd, dt = half / len;                     // edge parameters
            const Vec2 u = d / len, foot = perp(d) * (-cr / dd);
            const auto at = [&](Real t, Real s) { return t <= 0 ? a : (t >= 1 ? b : foot + u * s); };
            if (ina) {
                onHit(at(t0 + dt, half), false);
            } else if (inb) {
                onHit(at(t0 - dt, -half), true);
            } else if (half > 0) {  // both ends outside: chord through the edge
                onHit(at(t0 - dt, -half), true);
                onHit(at(t0 + dt, half), false);
            }
        }
        a = b;
        ina = inb;
    }
}

}  // namespace

AreaContact circlePolygonContact(Vec2 centre, Real r, const Vec2* corners, int n) noexcept {
    AreaContact out;
    if (corners == nullptr || n < 3 || !(r > 0)) return out;
    constexpr int kMaxStored = 32;          // crossings kept for the farthest pair; more: walk again
    Real xsx[kMaxStored], xsy[kMaxStored];  // left uninitialised: no per-call zeroing
    int m = 0, nIn = 0, nv = 0;
    Vec2 first, prev;         // chord polygon: overlap boundary with arcs replaced by chords
    Real twiceChordArea = 0;  // [m^2] its shoelace sum relative to its first vertex
    Real segments = 0;        // [m^2] circular segments between the arcs and their chords
    Vec2 grad;                // [m] G = -dA/d(centre) = sum of perp(arc end - arc start)
    Vec2 lastExit, firstEntry;
    bool haveExit = false, haveFirstEntry = false;
    const auto vertex = [&](Vec2 v) {
        if (nv == 0)
            first = v;
        else if (nv >= 2)
            twiceChordArea += cross(prev - first, v - first);
        prev = v;
        ++nv;
    };
    const auto arc = [&](Vec2 x, Vec2 e) {  // overlap arc from exit x counter-clockwise to entry e
        grad += perp(e - x);
        const Real c2 = norm2(e - x), cr = cross(x, e);  // squared chord; > 0: arc below pi
        if (cr > 0 && c2 <= 4 * (1 - (1 - kSeriesSagitta) * (1 - kSeriesSagitta)) * r * r) {
            const Real q = 0.25 * c2;  // sagitta r - sqrt(r^2 - c^2/4), without cancellation
            segments += capArea(r, q / (r + std::sqrt(r * r - q)));
            return;
        }
        Real phi = std::atan2(cr, dot(x, e));
        if (phi < 0) phi += 2 * kPi;
        segments += 0.5 * r * r * xMinusSin(phi);
    };
    walkBoundary(
        centre, r, corners, n,
        [&](Vec2 q) {
            ++nIn;
            vertex(q);
        },
        [&](Vec2 p, bool entering) {
            vertex(p);
            if (m < kMaxStored) {
                xsx[m] = p.x;
                xsy[m] = p.y;
            }
            ++m;
            if (!entering) {
                lastExit = p;
                haveExit = true;
            } else if (haveExit) {
                arc(lastExit, p);
                haveExit = false;
            } else {
                firstEntry = p;
                haveFirstEntry = true;
            }
        });
    if (haveExit && haveFirstEntry) arc(lastExit, firstEntry);

    if (m == 0) {
        if (nIn == n) {  // polygon inside the disk
            Real a2 = 0, cx = 0, cy = 0;
            for (int k = 1; k + 1 < n; ++k) {
                const Vec2 u = corners[k] - corners[0], v = corners[k + 1] - corners[0];
                const Real c = cross(u, v);
                a2 += c;
                cx += (u.x + v.x) * c;
                cy += (u.y + v.y) * c;
            }
            if (!(a2 > 0)) return out;
            out.area = 0.5 * a2;
            out.c1 = out.c2 = corners[0] + Vec2{cx, cy} / (3 * a2);
            const Vec2 away = centre - out.c1;
            const Real len = norm(away);
            out.normal = len > 0 ? away / len : Vec2{1, 0};
            finish(out);
            return out;
        }
        // No crossing, no corner inside: disjoint, or the disk inside the polygon.
        for (int k = 0; k < n; ++k)
            if (cross(corners[k] - centre, corners[(k + 1) % n] - corners[k]) < 0) return out;
        Real best = 0;
        int edge = -1;
        for (int k = 0; k < n; ++k) {
            const Vec2 a = corners[k] - centre, d = corners[(k + 1) % n] - corners[k];
            const Real len = norm(d);
            if (!(len > 0)) continue;
            const Real dist = cross(a, d) / len;  // > 0: the centre is inside
            if (edge < 0 || dist < best) {
                best = dist;
                edge = k;
            }
        }
        if (edge < 0) return out;
        const Vec2 a = corners[edge], d = corners[(edge + 1) % n] - a;
        const Real t = dot(centre - a, d) / norm2(d);
        out.area = kPi * r * r;
        out.c1 = out.c2 = a + d * (t < 0 ? 0 : (t > 1 ? 1 : t));
        out.normal = -perp(d) / norm(d);
        finish(out);
        return out;
    }

    out.area = 0.5 * twiceChordArea + segments;
    if (!(out.area > 0)) return out;
    // c1, c2: the farthest pair of crossings (erratum 6); normally there are just two.
    Vec2 c1, c2;
    Real far2 = -1;
    if (m <= kMaxStored) {
        for (int i = 0; i < m; ++i)
            for (int j = i + 1; j < m; ++j) {
                const Vec2 p{xsx[i], xsy[i]}, q{xsx[j], xsy[j]};
                if (norm2(p - q) > far2) {
                    far2 = norm2(p - q);
                    c1 = p;
                    c2 = q;
                }
            }
    } else {  // many crossings (polygon and circle nearly alike): O(m^2) walk, no storage
        const auto none = [](Vec2) {};
        walkBoundary(centre, r, corners, n, none, [&](Vec2 p, bool) {
            walkBoundary(centre, r, corners, n, none, [&](Vec2 q, bool) {
                if (norm2(p - q) > far2) {
                    far2 = norm2(p - q);
                    c1 = p;
                    c2 = q;
                }
            });
        });
    }
    out.c1 = centre + c1;
    out.c2 = centre + c2;
    const Vec2 line = c2 - c1;
    const Real len2 = norm2(line);
    Vec2 towards = grad;
    if (norm2(grad) <= 1e-24 * len2) {  // symmetric overlap: dA/d(centre) = 0
        Vec2 mean;
        for (int k = 0; k < n; ++k) mean += corners[k] - centre;
        towards = -mean;
    }
    Vec2 nrm{1, 0};  // last resort: coincident crossings and no preferred side
    if (len2 > 0)
        nrm = perp(line) / std::sqrt(len2);
    else if (norm2(towards) > 0)
        nrm = towards / norm(towards);
    if (dot(nrm, towards) < 0) nrm = -nrm;
    out.normal = nrm;
    finish(out);
    // The disk's arcs carry -dA/d(centre) = G, each through the centre (radial normals).
    out.pull = grad;
    out.twist = cross(centre - out.point, grad);
    return out;
}

}  // namespace granulab::geom
