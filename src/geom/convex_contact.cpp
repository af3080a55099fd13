// SPDX-License-Identifier: MIT
// Tracked convex polygon contact: crossings, the local overlap chain, 2D Lin-Canny, cold start
// (gc2d spec sections 3.1 and 5.3).
#include "geom/convex_contact.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "geom/convex_crossings.hpp"
#include "geom/polygon.hpp"

namespace granulab::geom {

namespace {

using crossings::chainContact;
using crossings::deepOverlap;
using crossings::Entry;
using crossings::entryAt;
using crossings::side;
using crossings::wrap;

/// Index offsets tried around a cached crossing: single-edge moves first (the usual case as a
/// contact rolls or slides), then both edges, then two edges away.
constexpr int kOffsets[][2] = {{1, 0},  {-1, 0}, {0, 1},  {0, -1}, {1, 1}, {-1, -1}, {1, -1},  {-1, 1},
                               {2, 0},  {-2, 0}, {0, 2},  {0, -2}, {2, 1}, {1, 2},   {-2, -1}, {-1, -2},
                               {2, -1}, {-1, 2}, {-2, 1}, {1, -2}, {2, 2}, {-2, -2}, {2, -2},  {-2, 2}};

inline void storeCrossings(FeatureCache& cache, int a1, int b1, int a2, int b2) noexcept {
    cache.state = FeatureCache::Crossing;
    cache.f[0] = static_cast<std::uint16_t>(a1);
    cache.f[1] = static_cast<std::uint16_t>(b1);
    cache.f[2] = static_cast<std::uint16_t>(a2);
    cache.f[3] = static_cast<std::uint16_t>(b2);
}

/// Searches the entry at and around the cached (x, y).
bool findEntryNear(const PolygonFrame& X, const PolygonFrame& Y, int& x, int& y, Entry& e,
                   std::uint64_t& iterations) noexcept {
    ++iterations;
    if (entryAt(X, Y, x, y, e)) return true;
    for (const auto& o : kOffsets) {
        ++iterations;
        const int cx = wrap(x + o[0], X.n), cy = wrap(y + o[1], Y.n);
        if (entryAt(X, Y, cx, cy, e)) {
            x = cx;
            y = cy;
            return true;
        }
    }
    return false;
}

/// Full clipping (rare: deep overlaps, containment, several crossings, collinear edges), with
/// per-thread buffers so that it does not allocate once warm.
AreaContact clipContact(const PolygonFrame& A, const PolygonFrame& B) {
    thread_local ClipScratch scratch;
    const PolygonOverlap o = convexOverlap(A.corners, A.n, B.corners, B.n, scratch);
    AreaContact c;
    c.touching = o.overlapping;
    if (!o.overlapping) return c;
    c.area = o.area;
    c.c1 = o.c1;
    c.c2 = o.c2;
    c.point = o.point;
    c.normal = o.normal;
    c.pull = o.pull;
    c.twist = o.twist;
    return c;
}

// ------------------------------------------------------------------ 2D Lin-Canny
enum class Walk { Apart, Suspect };

inline Vec2 closestOnSegment(Vec2 a, Vec2 b, Vec2 p) noexcept {
    const Vec2 d = b - a;
    const Real l2 = norm2(d);
    Real t = l2 > 0 ? dot(p - a, d) / l2 : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    return a + d * t;
}

/// Tests q against the Voronoi region of feature f of P; moves f to the neighbour across a
/// violated boundary. Returns 0: inside, 1: moved, 2: q lies on the inner side of the edge.
inline int voronoiStep(const PolygonFrame& P, int& f, Vec2 q) noexcept {
    const int k = f >> 1;
    if ((f & 1) == 0) {  // corner k
        const Vec2 c = P.corner(k);
        if (dot(q - c, P.corner(k + 1) - c) > 0) {
            f = 2 * k + 1;
            return 1;
        }
        if (dot(q - c, c - P.corner(k - 1)) < 0) {
            f = 2 * wrap(k - 1, P.n) + 1;
            return 1;
        }
        return 0;
    }
    const Vec2 a = P.corner(k), b = P.corner(k + 1), d = b - a;
    if (dot(q - a, d) < 0) {
        f = 2 * k;
        return 1;
    }
    if (dot(q - b, d) > 0) {
        f = 2 * wrap(k + 1, P.n);
        return 1;
    }
    return cross(d, q - a) > 0 ? 2 : 0;
}

/// Closest points of feature fa of A and fb of B; an edge-edge pair is reduced to the
/// corner-edge pair that realises it (returns false if the two edges intersect).
bool featurePoints(const PolygonFrame& A, const PolygonFrame& B, int& fa, int& fb, Vec2& pa,
                   Vec2& pb) noexcept {
    const int ka = fa >> 1, kb = fb >> 1;
    const bool ea = fa & 1, eb = fb & 1;
    if (!ea && !eb) {
        pa = A.corner(ka);
        pb = B.corner(kb);
    } else if (!ea) {
        pa = A.corner(ka);
        pb = closestOnSegment(B.corner(kb), B.corner(kb + 1), pa);
    } else if (!eb) {
        pb = B.corner(kb);
        pa = closestOnSegment(A.corner(ka), A.corner(ka + 1), pb);
    } else {
        const Vec2 a0 = A.corner(ka), a1 = A.corner(ka + 1), b0 = B.corner(kb), b1 = B.corner(kb + 1);
        const Real s0 = side(b0, a0, a1), s1 = side(b1, a0, a1), t0 = side(a0, b0, b1), t1 = side(a1, b0, b1);
        if (((s0 <= 0 && s1 >= 0) || (s0 >= 0 && s1 <= 0)) && ((t0 <= 0 && t1 >= 0) || (t0 >= 0 && t1 <= 0)))
            return false;
        // Non-intersecting segments: the distance is realised at an endpoint.
        const Vec2 q[4] = {closestOnSegment(b0, b1, a0), closestOnSegment(b0, b1, a1),
                           closestOnSegment(a0, a1, b0), closestOnSegment(a0, a1, b1)};
        const Real d[4] = {norm2(q[0] - a0), norm2(q[1] - a1), norm2(q[2] - b0), norm2(q[3] - b1)};
        const int best = static_cast<int>(std::min_element(d, d + 4) - d);
        if (best < 2) {
            fa = 2 * wrap(ka + best, A.n);
            pa = best == 0 ? a0 : a1;
            pb = q[best];
        } else {
            fb = 2 * wrap(kb + best - 2, B.n);
            pb = best == 2 ? b0 : b1;
            pa = q[best];
        }
    }
    return true;
}

/// Walks (fa, fb) to the closest features. Apart: the distance is positive and the features are
/// certified by the Voronoi regions. Suspect: the polygons may overlap (features intersect or a
/// closest point lies on the inner side of an edge); fa, fb are then near the contact.
Walk linCanny(const PolygonFrame& A, const PolygonFrame& B, int& fa, int& fb,
              std::uint64_t& iterations) noexcept {
    const int limit = 2 * (A.n + B.n) + 8;
    for (int it = 0; it < limit; ++it) {
        ++iterations;
        Vec2 pa, pb;
        if (!featurePoints(A, B, fa, fb, pa, pb)) return Walk::Suspect;
        const int ra = voronoiStep(A, fa, pb);
        if (ra == 1) continue;
        const int rb = voronoiStep(B, fb, pa);
        if (rb == 1) continue;
        if (ra == 2 || rb == 2) return Walk::Suspect;
        // Certify with a strict separating line: an edge feature must have the other closest
        // point strictly outside its line. (The Euclidean distance to the projected point can be
        // a round-off 1e-19 when that point lies on the line: aligned faces overlapping.)
        if (fa & 1)
            return side(pb, A.corner(fa >> 1), A.corner((fa >> 1) + 1)) < 0 ? Walk::Apart : Walk::Suspect;
        if (fb & 1)
            return side(pa, B.corner(fb >> 1), B.corner((fb >> 1) + 1)) < 0 ? Walk::Apart : Walk::Suspect;
        return norm2(pa - pb) > 0 ? Walk::Apart : Walk::Suspect;
    }
    return Walk::Suspect;
}

/// O(n m) search of both crossings; 0: none, 1: exactly one of each, 2: several.
int allEntries(const PolygonFrame& A, const PolygonFrame& B, int& a1, int& b1, Entry& e1, int& a2, int& b2,
               Entry& e2) noexcept {
    int nAB = 0, nBA = 0;
    Entry e;
    for (int a = 0; a < A.n; ++a)
        for (int b = 0; b < B.n; ++b) {
            if (entryAt(A, B, a, b, e)) {
                if (nAB++ == 0) {
                    a1 = a;
                    b1 = b;
                    e1 = e;
                }
            }
            if (entryAt(B, A, b, a, e)) {
                if (nBA++ == 0) {
                    b2 = b;
                    a2 = a;
                    e2 = e;
                }
            }
        }
    if (nAB == 0 && nBA == 0) return 0;
    return (nAB == 1 && nBA == 1) ? 1 : 2;
}

bool inside(const PolygonFrame& P, Vec2 q) noexcept {
    for (int k = 0; k < P.n; ++k)
        if (side(q, P.corner(k), P.corner(k + 1)) < 0) return false;
    return true;
}

AreaContact coldStart(const PolygonFrame& A, const PolygonFrame& B, FeatureCache& cache,
                      FeatureStats& stats) noexcept {
    ++stats.coldStarts;
    stats.iterations += static_cast<std::uint64_t>(A.n) * static_cast<std::uint64_t>(B.n);
    int a1 = 0, b1 = 0, a2 = 0, b2 = 0;
    Entry e1, e2;
    const int found = allEntries(A, B, a1, b1, e1, a2, b2, e2);
    if (found == 1) {
        AreaContact c = chainContact(A, B, a1, b1, e1, a2, b2, e2);
        if (!deepOverlap(c, A, B)) {
            storeCrossings(cache, a1, b1, a2, b2);
            return c;
        }
    }
    if (found != 0 || inside(B, A.corner(0)) || inside(A, B.corner(0))) {
        ++stats.fullClips;
        cache.state = FeatureCache::Cold;
        return clipContact(A, B);
    }
    // Apart: start the walk from the closest pair of corners.
    int fa = 0, fb = 0;
    Real best = -1;
    for (int a = 0; a < A.n; ++a)
        for (int b = 0; b < B.n; ++b) {
            const Real d = norm2(A.corner(a) - B.corner(b));
            if (best < 0 || d < best) {
                best = d;
                fa = 2 * a;
                fb = 2 * b;
            }
        }
    if (linCanny(A, B, fa, fb, stats.iterations) == Walk::Apart) {
        cache.state = FeatureCache::Apart;
        cache.f[0] = static_cast<std::uint16_t>(fa);
        cache.f[1] = static_cast<std::uint16_t>(fb);
        return {};
    }
    // Touching without a strict crossing: collinear edges (aligned squares face to face) put
    // the crossings exactly on corners. Clipping handles these; the next step starts cold again.
    ++stats.fullClips;
    cache.state = FeatureCache::Cold;
    return clipContact(A, B);
}

/// Both crossings near (a1, b1) and (a2, b2); false if either is not found locally.
bool trackCrossings(const PolygonFrame& A, const PolygonFrame& B, int& a1, int& b1, int& a2, int& b2,
                    AreaContact& out, FeatureStats& stats) noexcept {
    Entry e1, e2;
    if (!findEntryNear(A, B, a1, b1, e1, stats.iterations)) return false;
    if (!findEntryNear(B, A, b2, a2, e2, stats.iterations)) return false;
    out = chainContact(A, B, a1, b1, e1, a2, b2, e2);
    return !deepOverlap(out, A, B);
}

}  // namespace

AreaContact trackPolygonContact(const PolygonFrame& A, const PolygonFrame& B, FeatureCache& cache,
                                FeatureStats& stats) noexcept {
    GL_ASSERT(A.corners && B.corners && A.n >= 3 && B.n >= 3, "two polygons");
    GL_ASSERT(2 * A.n <= 0xFFFF && 2 * B.n <= 0xFFFF, "feature indices fit the cache");
    ++stats.evaluations;
    if (cache.state == FeatureCache::Crossing) {
        // The cache of this pair always holds valid indices (asserted); the guard only keeps a
        // foreign cache from reading out of range.
        GL_ASSERT(cache.f[0] < A.n && cache.f[1] < B.n && cache.f[2] < A.n && cache.f[3] < B.n,
                  "crossing cache of this pair");
        const auto idx = [](std::uint16_t f, int n) { return f < n ? static_cast<int>(f) : 0; };
        int a1 = idx(cache.f[0], A.n), b1 = idx(cache.f[1], B.n), a2 = idx(cache.f[2], A.n),
            b2 = idx(cache.f[3], B.n);
        AreaContact c;
        if (trackCrossings(A, B, a1, b1, a2, b2, c, stats)) {
            storeCrossings(cache, a1, b1, a2, b2);
            return c;
        }
        // Probably separated: walk from the edges of the last crossing.
        int fa = 2 * a1 + 1,
            fb = 2 * b1 + 1;  // a1, b1 as cached (the search leaves them unchanged on failure)
        if (linCanny(A, B, fa, fb, stats.iterations) == Walk::Apart) {
            cache.state = FeatureCache::Apart;
            cache.f[0] = static_cast<std::uint16_t>(fa);
            cache.f[1] = static_cast<std::uint16_t>(fb);
            return {};
        }
        return coldStart(A, B, cache, stats);
    }
    if (cache.state == FeatureCache::Apart) {
        GL_ASSERT(cache.f[0] < 2 * A.n && cache.f[1] < 2 * B.n, "closest-feature cache of this pair");
        int fa = cache.f[0] < 2 * A.n ? cache.f[0] : 0, fb = cache.f[1] < 2 * B.n ? cache.f[1] : 0;
        if (linCanny(A, B, fa, fb, stats.iterations) == Walk::Apart) {
            cache.f[0] = static_cast<std::uint16_t>(fa);
            cache.f[1] = static_cast<std::uint16_t>(fb);
            return {};
        }
        // First touch: the crossings lie next to the closest features.
        int a1 = fa >> 1, b1 = fb >> 1, a2 = fa >> 1, b2 = fb >> 1;
        AreaContact c;
        if (trackCrossings(A, B, a1, b1, a2, b2, c, stats)) {
            storeCrossings(cache, a1, b1, a2, b2);
            return c;
        }
    }
    return coldStart(A, B, cache, stats);
}

AreaContact polygonContact(const PolygonFrame& a, const PolygonFrame& b) noexcept {
    FeatureCache cache;
    FeatureStats stats;
    return coldStart(a, b, cache, stats);
}

}  // namespace granulab::geom
