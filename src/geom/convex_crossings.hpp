// SPDX-License-Identifier: MIT
// The crossing step of the tracked convex polygon contact (gc2d spec sections 3.1 and 5.3): a
// boundary crossing at a cached pair of edges, the overlap chain between two crossings, and the
// refresh of a persistent contact whose cached crossings still hold (the common case of a settled
// bed), inlined into the pair kernel. geom/convex_contact.cpp uses the same functions for its
// search, so that both paths give the same results bit for bit.
#pragma once
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/types.hpp"
#include "geom/area_contact.hpp"
#include "geom/convex_contact.hpp"

namespace granulab::geom::crossings {

/// > 0: p lies left of the directed line e0 -> e1 (inside for a counter-clockwise edge) [m^2].
inline Real side(Vec2 p, Vec2 e0, Vec2 e1) noexcept {
    return cross(e1 - e0, p - e0);
}

/// k mod n for k in (-2n, 2n) (index differences and +-2 offsets), without an integer division.
inline int wrap(int k, int n) noexcept {
    GL_ASSERT(k > -2 * n && k < 2 * n, "index difference within two turns");
    if (k < 0) k += n;
    if (k < 0) k += n;
    if (k >= n) k -= n;
    if (k >= n) k -= n;
    return k;
}

/// A crossing where X's boundary enters Y: X-edge x (X[x] outside Y-edge y's line, X[x+1] inside
/// or on it) crosses Y-edge y (Y[y] inside or on X-edge x's line, Y[y+1] outside). For a convex
/// pair with two boundary crossings exactly one (x, y) qualifies.
struct Entry {
    Vec2 point;                 ///< [m]
    Real tx = 0;                ///< parameter of the point along X-edge x
    Real tyNum = 0, tyDen = 1;  ///< parameter along Y-edge y = tyNum / tyDen (rarely needed)
    Real ty() const noexcept { return tyNum / tyDen; }
};

/// The entry of X-edge x0 -> x1 into Y across Y-edge y0 -> y1, if these edges make one.
inline bool entryOf(Vec2 x0, Vec2 x1, Vec2 y0, Vec2 y1, Entry& e) noexcept {
    const Real sx0 = side(x0, y0, y1);
    if (!(sx0 < 0)) return false;
    const Real sx1 = side(x1, y0, y1);
    if (!(sx1 >= 0)) return false;
    const Real sy1 = side(y1, x0, x1);
    if (!(sy1 < 0)) return false;
    const Real sy0 = side(y0, x0, x1);
    if (!(sy0 >= 0)) return false;
    e.tx = sx0 / (sx0 - sx1);
    e.tyNum = sy0;
    e.tyDen = sy0 - sy1;
    e.point = x0 + (x1 - x0) * e.tx;
    return true;
}

inline bool entryAt(const PolygonFrame& X, const PolygonFrame& Y, int x, int y, Entry& e) noexcept {
    return entryOf(X.corner(x), X.corner(x + 1), Y.corner(y), Y.corner(y + 1), e);
}

/// The unit normal of a contact with crossings c1, c2: perp(c2 - c1) / |c2 - c1| pushes A away
/// from B (B's chain, A's side, lies left of c1 -> c2); along the centres where c1 = c2.
inline void chainNormal(AreaContact& c, Vec2 centreA, Vec2 centreB) noexcept {
    const Vec2 line = c.c2 - c.c1;
    const Real len = norm(line);
    if (len > 0) {
        c.normal = perp(line) / len;
    } else {
        const Vec2 d = centreA - centreB;
        const Real dn = norm(d);
        c.normal = dn > 0 ? d / dn : Vec2{1, 0};
    }
}

/// Overlap polygon from the two crossings: A-entry (a1, b1, e1) and B-entry (b2 into A at a2, e2).
/// The shoelace sum runs relative to c1 over A's corners a1+1 .. a2, c2, B's corners b2+1 .. b1.
/// kNormal = false leaves c.normal to chainNormal (the pair kernel's batched law pass computes it,
/// where the square root and divisions of independent pairs overlap).
template <bool kNormal = true>
inline AreaContact chainContact(const PolygonFrame& A, const PolygonFrame& B, int a1, int b1, const Entry& e1,
                                int a2, int b2, const Entry& e2) noexcept {
    int kA = wrap(a2 - a1, A.n);
    if (kA == 0 && !(e2.ty() > e1.tx)) kA = A.n;  // e2.ty(): parameter of the B-entry along A-edge a2
    int kB = wrap(b1 - b2, B.n);
    if (kB == 0 && !(e1.ty() > e2.tx)) kB = B.n;
    const Vec2 o = e1.point;  // shoelace relative to c1
    Real area2 = 0;
    Vec2 prev{0, 0};
    for (int k = 1; k <= kA; ++k) {
        const Vec2 p = A.corner(a1 + k) - o;
        area2 += cross(prev, p);
        prev = p;
    }
    {
        const Vec2 p = e2.point - o;
        area2 += cross(prev, p);
        prev = p;
    }
    for (int k = 1; k <= kB; ++k) {
        const Vec2 p = B.corner(b2 + k) - o;
        area2 += cross(prev, p);
        prev = p;
    }
    // closing edge back to c1 (the origin) contributes cross(prev, 0) = 0
    AreaContact c;
    c.area = 0.5 * area2;
    c.c1 = e1.point;
    c.c2 = e2.point;
    c.point = (c.c1 + c.c2) * 0.5;
    c.touching = c.area > 0;
    if constexpr (kNormal) chainNormal(c, A.centre, B.centre);
    const Vec2 line = c.c2 - c.c1;
    // A's chain c1 -> c2 carries -dA/dx_A = sum of perp(edge) = perp(c2 - c1); its moment about
    // the midpoint s telescopes to (|c2 - s|^2 - |c1 - s|^2)/2 = 0.
    c.pull = perp(line);
    return c;
}

/// True if the overlap found from two crossings may miss further crossings (erratum 6).
inline bool deepOverlap(const AreaContact& c, const PolygonFrame& A, const PolygonFrame& B) noexcept {
    const Real q = 0.25 * std::min(A.inradius, B.inradius);  // area <= q L_c, squared (no sqrt)
    return !(c.area * c.area <= q * q * norm2(c.c2 - c.c1));
}

/// The refresh of a contact whose cached crossings (a1, b1) and (b2, a2) both still hold at the
/// same edges, with a shallow overlap: what trackPolygonContact computes for such a pair (the
/// same arithmetic; the cache keeps its indices; one evaluation and two feature tests are
/// counted). Returns false, with `cache` and `stats` untouched, in every other case; the caller
/// then calls trackPolygonContact. Inlined into the pair kernel: no call, no index search.
/// kNormal = false: out.normal is left to chainNormal (see chainContact).
template <bool kNormal = true>
inline bool refreshCrossings(const PolygonFrame& A, const PolygonFrame& B, const FeatureCache& cache,
                             FeatureStats& stats, AreaContact& out) noexcept {
    if (cache.state != FeatureCache::Crossing) return false;
    const int a1 = cache.f[0], b1 = cache.f[1], a2 = cache.f[2], b2 = cache.f[3];
    if (a1 >= A.n || b1 >= B.n || a2 >= A.n || b2 >= B.n) return false;
    Entry e1, e2;
    if (!entryAt(A, B, a1, b1, e1) || !entryAt(B, A, b2, a2, e2)) return false;
    out = chainContact<kNormal>(A, B, a1, b1, e1, a2, b2, e2);
    if (deepOverlap(out, A, B)) return false;
    ++stats.evaluations;
    stats.iterations += 2;  // one entry test at each cached crossing, as findEntryNear counts them
    return true;
}

/// True if the cached closest features of an apart pair still prove it apart by a separating
/// line, without the Lin-Canny walk (no division, no square root): for an edge of one polygon and
/// a corner of the other, the corner lies strictly outside the edge's line and is the other
/// polygon's extreme point toward it (both neighbours no nearer the line: convexity makes a local
/// extreme the global one); for two corners, the line between them is separating (each corner is
/// its polygon's extreme point along it). The cache keeps its features (they remain a start near
/// the closest ones; the walk moves them when the certificate fails). Counts one evaluation and
/// one feature test. False, with `stats` untouched, in every other case (the caller then calls
/// trackPolygonContact, which walks).
inline bool stillApart(const PolygonFrame& A, const PolygonFrame& B, const FeatureCache& cache,
                       FeatureStats& stats) noexcept {
    if (cache.state != FeatureCache::Apart) return false;
    const int fa = cache.f[0], fb = cache.f[1];
    if (fa >= 2 * A.n || fb >= 2 * B.n) return false;
    const int ka = fa >> 1, kb = fb >> 1;
    bool apart;
    if (fa & 1) {
        if (fb & 1) return false;  // two edges: not stored (the walk reduces them to an edge and a corner)
        // Edge ka of A (inside on its left), corner kb of B.
        const Vec2 e0 = A.corners[ka], e1 = A.corner(ka + 1), q = B.corners[kb];
        const Real s = side(q, e0, e1);
        apart = s < 0 && side(B.corner(kb - 1), e0, e1) <= s && side(B.corner(kb + 1), e0, e1) <= s;
    } else if (fb & 1) {
        const Vec2 e0 = B.corners[kb], e1 = B.corner(kb + 1), q = A.corners[ka];
        const Real s = side(q, e0, e1);
        apart = s < 0 && side(A.corner(ka - 1), e0, e1) <= s && side(A.corner(ka + 1), e0, e1) <= s;
    } else {
        const Vec2 p = A.corners[ka], q = B.corners[kb], d = q - p;
        apart = norm2(d) > 0 && dot(A.corner(ka - 1) - p, d) <= 0 && dot(A.corner(ka + 1) - p, d) <= 0 &&
                dot(B.corner(kb - 1) - q, d) >= 0 && dot(B.corner(kb + 1) - q, d) >= 0;
    }
    if (!apart) return false;
    ++stats.evaluations;
    ++stats.iterations;
    return true;
}

}  // namespace granulab::geom::crossings
