// SPDX-License-Identifier: MIT
// Convex polygons: shoelace mass properties, shape checks, and the overlap polygon by
// Sutherland-Hodgman clipping of i by the edges of j, keeping track of which corners of the
// result are crossings of the two boundaries (created where an edge of i is cut).
#include "geom/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granulab::geom {

Real inradiusAbout(const std::vector<Vec2>& ccw, Vec2 centre) noexcept {
    Real rIn = std::numeric_limits<Real>::infinity();
    const std::size_t n = ccw.size();
    for (std::size_t e = 0; e < n; ++e) {
        const Vec2 a = ccw[e] - centre, b = ccw[(e + 1) % n] - centre;
        const Real len = norm(b - a);
        if (len > 0) rIn = std::min(rIn, cross(b - a, -a) / len);
    }
    return rIn;
}

PolygonMass polygonMass(const std::vector<Vec2>& p) noexcept {
    PolygonMass m;
    const std::size_t n = p.size();
    if (n < 3) return m;
    // Relative to the first corner: far from the origin the shoelace sums would cancel.
    const Vec2 o = p[0];
    Real a2 = 0, cx = 0, cy = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const Vec2 u = p[k] - o, v = p[(k + 1) % n] - o;
        const Real c = cross(u, v);
        a2 += c;
        cx += (u.x + v.x) * c;
        cy += (u.y + v.y) * c;
    }
    m.area = 0.5 * a2;
    if (a2 == 0) return m;
    m.centroid = o + Vec2{cx / (3 * a2), cy / (3 * a2)};
    Real j = 0;  // polar second moment about the centroid (Eq. 2.12, closed form)
    for (std::size_t k = 0; k < n; ++k) {
        const Vec2 u = p[k] - m.centroid, v = p[(k + 1) % n] - m.centroid;
        const Real c = cross(u, v);
        j += c * (u.x * u.x + u.x * v.x + v.x * v.x + u.y * u.y + u.y * v.y + v.y * v.y);
    }
    m.secondMoment = j / 12.0;
    return m;
}

ShapeProblem checkConvexPolygon(const std::vector<Vec2>& p) noexcept {
    const int n = static_cast<int>(p.size());
    if (n < 3) return {"fewer than 3 corners", n - 1};
    Real scale = 0;
    for (const auto& q : p) scale = std::max(scale, std::max(std::abs(q.x), std::abs(q.y)));
    const Real eps = 1e-12 * std::max(scale * scale, 1e-300);
    for (int k = 0; k < n; ++k)
        if (norm2(p[(k + 1) % n] - p[k]) <= eps) return {"duplicate", (k + 1) % n};
    Real area2 = 0;
    for (int k = 0; k < n; ++k) area2 += cross(p[k], p[(k + 1) % n]);
    if (area2 < 0) return {"clockwise", 0};
    Real turning = 0;
    for (int k = 0; k < n; ++k) {
        const Vec2 a = p[(k + n - 1) % n], b = p[k], c = p[(k + 1) % n];
        const Real turn = cross(b - a, c - b);
        if (std::abs(turn) <= eps) return {"collinear", k};
        if (turn < 0) return {"non-convex", k};
        turning += std::atan2(turn, dot(b - a, c - b));
    }
    if (turning > 2 * kPi + 1e-6) return {"self-intersecting", 0};  // winds more than once
    return {};
}

PolygonOverlap convexOverlap(const Vec2* pi, int ni, const Vec2* pj, int nj, ClipScratch& sc) {
    using V = ClipScratch::Vertex;
    PolygonOverlap out;
    auto& poly = sc.poly;
    auto& next = sc.next;
    poly.clear();
    for (int k = 0; k < ni; ++k) poly.push_back({pi[k], false, true});
    for (int e = 0; e < nj && !poly.empty(); ++e) {
        const Vec2 a = pj[e], b = pj[(e + 1) % nj];
        const Vec2 d = b - a;
        const auto side = [&](Vec2 q) { return cross(d, q - a); };  // > 0: inside (left of the edge)
        next.clear();
        for (std::size_t k = 0; k < poly.size(); ++k) {
            const V& P = poly[k];
            const V& Q = poly[(k + 1) % poly.size()];
            const Real sp = side(P.p), sq = side(Q.p);
            const bool pin = sp >= 0, qin = sq >= 0;
            if (pin != qin) {
                const Real t = sp / (sp - sq);
                const Vec2 x = P.p + (Q.p - P.p) * t;
                // Cutting an edge of i at j's edge is a crossing of the two boundaries.
                if (pin)
                    next.push_back({x, P.edgeOnI, false});  // leaving: continue along j's edge
                else
                    next.push_back({x, P.edgeOnI, P.edgeOnI});  // entering: continue along P's edge
            }
            if (qin) next.push_back(Q);
        }
        poly.swap(next);
    }
    if (poly.size() < 3) return out;
    auto& corners = sc.corners;
    corners.clear();
    for (const auto& v : poly) corners.push_back(v.p);
    const PolygonMass m = polygonMass(corners);
    if (!(m.area > 0)) return out;
    out.overlapping = true;
    out.area = m.area;
    auto& xs = sc.crossings;
    xs.clear();
    Vec2 chainI, chainJ;  // mean corners of the i-boundary chain and the j-boundary chain
    int nI = 0, nJ = 0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        if (poly[k].crossing) {
            xs.push_back(poly[k].p);
            continue;
        }
        // A non-crossing corner is a corner of i (inside j) or of j (inside i).
        const bool ofI = poly[k].edgeOnI && poly[(k + poly.size() - 1) % poly.size()].edgeOnI;
        (ofI ? chainI : chainJ) += poly[k].p;
        ++(ofI ? nI : nJ);
    }
    out.crossings = static_cast<int>(xs.size());
    if (xs.size() >= 2) {  // erratum 6: with more than two crossings use the farthest pair
        Real best = -1;
        for (std::size_t a = 0; a < xs.size(); ++a)
            for (std::size_t b = a + 1; b < xs.size(); ++b)
                if (norm2(xs[a] - xs[b]) > best) {
                    best = norm2(xs[a] - xs[b]);
                    out.c1 = xs[a];
                    out.c2 = xs[b];
                }
    } else {  // containment or degenerate touching: contact line through the overlap centroid
        out.c1 = out.c2 = m.centroid;
    }
    out.point = (out.c1 + out.c2) * 0.5;
    // Exact area gradient of i (Feng, Han & Owen 2012): the edges on i's boundary, each -n L =
    // perp(q - p), with moment (m - s) . (q - p) = (|q - s|^2 - |p - s|^2)/2 about s.
    for (std::size_t k = 0; k < poly.size(); ++k) {
        if (!poly[k].edgeOnI) continue;
        const Vec2 p = poly[k].p, q = poly[(k + 1) % poly.size()].p;
        out.pull += perp(q - p);
        out.twist += 0.5 * (norm2(q - out.point) - norm2(p - out.point));
    }
    const Vec2 line = out.c2 - out.c1;
    const Real len = norm(line);
    // The part of i's boundary inside j lies on j's side of the contact line, the part of j's
    // boundary inside i on i's side: n points from the first towards the second, robust for
    // long rods touching end to end where the centroid line is useless.
    Vec2 towardsI = (nJ ? chainJ / nJ : Vec2{}) - (nI ? chainI / nI : Vec2{});
    if (nI == 0 || nJ == 0) {
        Vec2 ci, cj;
        for (int k = 0; k < ni; ++k) ci += pi[k];
        for (int k = 0; k < nj; ++k) cj += pj[k];
        towardsI = ci / ni - cj / nj;  // corner means: inside the polygons, enough for a direction
    }
    Vec2 n = len > 0 ? perp(line) / len : towardsI / std::max(norm(towardsI), 1e-300);
    if (dot(n, towardsI) < 0) n = -n;
    out.normal = n;
    return out;
}

PolygonOverlap convexOverlap(const std::vector<Vec2>& pi, const std::vector<Vec2>& pj) {
    ClipScratch sc;
    PolygonOverlap out =
        convexOverlap(pi.data(), static_cast<int>(pi.size()), pj.data(), static_cast<int>(pj.size()), sc);
    if (out.overlapping) out.polygon = sc.corners;
    return out;
}

}  // namespace granulab::geom
