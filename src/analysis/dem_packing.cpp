// SPDX-License-Identifier: MIT
// Local packing fraction on test areas (gc2d spec section 7 item 6, Eq. 2.44 and 2.45): exact
// grain-rectangle intersections and the convex hull of the clipped outlines.
#include "analysis/dem_packing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "analysis/convex_hull.hpp"

namespace granulab::analysis {

namespace {

/// Angle in [0, 2 pi).
Real wrapAngle(Real t) {
    t = std::fmod(t, 2 * kPi);
    return t < 0 ? t + 2 * kPi : t;
}

bool strictlyInside(Vec2 p, Vec2 lo, Vec2 hi) {
    return p.x > lo.x && p.x < hi.x && p.y > lo.y && p.y < hi.y;
}

/// One Sutherland-Hodgman pass: keep the part of `in` with s * (p[axis] - bound) >= 0.
void clipHalfPlane(const std::vector<Vec2>& in, std::vector<Vec2>& out, int axis, Real bound, Real s) {
    out.clear();
    const std::size_t n = in.size();
    const auto side = [&](Vec2 p) { return s * ((axis == 0 ? p.x : p.y) - bound); };
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 p = in[i], q = in[(i + 1) % n];
        const Real dp = side(p), dq = side(q);
        if (dp >= 0) out.push_back(p);
        if ((dp >= 0) != (dq >= 0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
    }
}

}  // namespace

Real diskInRectangle(Vec2 c, Real r, Vec2 lo, Vec2 hi, std::size_t diskCorners, std::vector<Vec2>* points) {
    const Vec2 l = lo - c, u = hi - c;  // rectangle relative to the centre
    if (l.x >= r || u.x <= -r || l.y >= r || u.y <= -r || !(r > 0)) return 0;
    thread_local std::vector<Vec2> unit;  // the corner directions, computed once per corner count
    if (unit.size() != diskCorners) {
        unit.resize(diskCorners);
        for (std::size_t m = 0; m < diskCorners; ++m) {
            const Real t = 2 * kPi * static_cast<Real>(m) / static_cast<Real>(diskCorners);
            unit[m] = {std::cos(t), std::sin(t)};
        }
    }
    const auto corner = [&](std::size_t m) { return unit[m] * r; };
    if (l.x <= -r && u.x >= r && l.y <= -r && u.y >= r) {  // disk wholly inside
        if (points)
            for (std::size_t m = 0; m < diskCorners; ++m) points->push_back(c + corner(m));
        return kPi * r * r;
    }
    // Arcs: split the circle where it crosses the four lines, keep the pieces inside (1/2 r^2 dt).
    Real cuts[8];
    std::size_t nc = 0;
    for (const Real X : {l.x, u.x})
        if (std::abs(X) < r) {
            const Real t = std::acos(X / r);
            cuts[nc++] = t;
            cuts[nc++] = wrapAngle(-t);
        }
    for (const Real Y : {l.y, u.y})
        if (std::abs(Y) < r) {
            const Real t = std::asin(Y / r);
            cuts[nc++] = wrapAngle(t);
            cuts[nc++] = wrapAngle(kPi - t);
        }
    for (std::size_t i = 1; i < nc; ++i)  // insertion sort (std::sort trips -Warray-bounds at -O3)
        for (std::size_t j = i; j > 0 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);
    Real twice = 0;  // twice the area: sum of r^2 dt over arcs plus cross(p, q) over edge pieces
    const auto inside = [&](Real t) { return strictlyInside({r * std::cos(t), r * std::sin(t)}, l, u); };
    for (std::size_t k = 0; k < nc; ++k) {
        const Real t0 = cuts[k], t1 = k + 1 < nc ? cuts[k + 1] : cuts[0] + 2 * kPi;
        if (t1 - t0 <= 0 || !inside(0.5 * (t0 + t1))) continue;
        twice += r * r * (t1 - t0);
        if (points) {
            const auto first =
                static_cast<std::size_t>(std::ceil(t0 / (2 * kPi) * static_cast<Real>(diskCorners)));
            for (std::size_t m = first;; ++m) {
                const Real t = 2 * kPi * static_cast<Real>(m) / static_cast<Real>(diskCorners);
                if (t > t1) break;
                points->push_back(c + corner(m % diskCorners));
            }
        }
    }
    // Rectangle edges, counter-clockwise, clipped to the disk: |P + s (Q - P)|^2 <= r^2.
    const Vec2 rect[4] = {{l.x, l.y}, {u.x, l.y}, {u.x, u.y}, {l.x, u.y}};
    for (int e = 0; e < 4; ++e) {
        const Vec2 P = rect[e], d = rect[(e + 1) % 4] - P;
        const Real A = norm2(d), B = dot(P, d), C = norm2(P) - r * r;
        const Real disc = B * B - A * C;
        if (disc <= 0) continue;
        const Real root = std::sqrt(disc);
        const Real s0 = std::max<Real>(0, (-B - root) / A), s1 = std::min<Real>(1, (-B + root) / A);
        if (s1 <= s0) continue;
        const Vec2 p = P + d * s0, q = P + d * s1;
        twice += cross(p, q);
        if (points) {
            points->push_back(c + p);
            points->push_back(c + q);
        }
    }
    return 0.5 * twice;
}

Real polygonInRectangle(const std::vector<Vec2>& poly, Vec2 lo, Vec2 hi, std::vector<Vec2>* points) {
    std::vector<Vec2> a = poly, b;
    clipHalfPlane(a, b, 0, lo.x, 1);
    clipHalfPlane(b, a, 0, hi.x, -1);
    clipHalfPlane(a, b, 1, lo.y, 1);
    clipHalfPlane(b, a, 1, hi.y, -1);
    Real twice = 0;
    for (std::size_t i = 0; i < a.size(); ++i) twice += cross(a[i], a[(i + 1) % a.size()]);
    if (points && twice > 0) points->insert(points->end(), a.begin(), a.end());
    return 0.5 * twice;
}

PackingGrid packingGrid(const GrainFrame& grains, const TestAreaGrid& grid, const PackingParams& params) {
    checkGrid(grid, "packingGrid");
    if (params.diskHullPoints < 4) throw std::invalid_argument("packingGrid: diskHullPoints must be >= 4");
    const std::size_t n = grains.size(), areas = grid.count();
    // Bounding boxes: polygons from their corners, disks from the radius.
    const AreaMembers members = areaMembers(grid, n, [&](std::size_t i, Vec2& lo, Vec2& hi) {
        if (grains.isPolygon(i)) {
            lo = hi = grains.corners[grains.cornerStart[i]];
            for (std::size_t c = grains.cornerStart[i]; c < grains.cornerStart[i + 1]; ++c) {
                const Vec2 p = grains.corners[c];
                lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
                hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
            }
        } else {
            const Real r = grains.radius[i];
            lo = {grains.x[i] - r, grains.y[i] - r};
            hi = {grains.x[i] + r, grains.y[i] + r};
        }
        return true;
    });
    PackingGrid out;
    out.grid = grid;
    out.covered.assign(areas, 0);
    out.simple.assign(areas, 0);
    out.hullArea.assign(areas, 0);
    out.improved.assign(areas, std::numeric_limits<Real>::quiet_NaN());
    out.grains.assign(areas, 0);
    std::vector<Vec2> points, poly;
    std::size_t empty = 0;
    for (std::size_t k = 0; k < areas; ++k) {
        const Vec2 lo{grid.left(k % grid.nx), grid.bottom(k / grid.nx)}, hi = lo + Vec2{grid.w, grid.h};
        points.clear();
        Real covered = 0;
        for (std::size_t m = members.start[k]; m < members.start[k + 1]; ++m) {
            const std::size_t i = members.items[m];
            Real a;
            if (grains.isPolygon(i)) {
                poly.assign(grains.corners.begin() + static_cast<std::ptrdiff_t>(grains.cornerStart[i]),
                            grains.corners.begin() + static_cast<std::ptrdiff_t>(grains.cornerStart[i + 1]));
                a = polygonInRectangle(poly, lo, hi, &points);
            } else {
                a = diskInRectangle({grains.x[i], grains.y[i]}, grains.radius[i], lo, hi,
                                    params.diskHullPoints, &points);
            }
            if (a > 0) {
                covered += a;
                ++out.grains[k];
            }
        }
        out.covered[k] = covered;
        out.simple[k] = covered / grid.area();  // Eq. 2.44
        out.hullArea[k] = convexHullArea(points);
        if (out.hullArea[k] > 0)
            out.improved[k] = covered / out.hullArea[k];  // Eq. 2.45
        else
            ++empty;
    }
    if (empty > 0)
        out.notes.push_back("areas without grains (rho_improved = NaN): " + std::to_string(empty) + " of " +
                            std::to_string(areas));
    return out;
}

Table packingTable(const PackingGrid& p) {
    Table t;
    t.name = "packing_fraction";
    t.notes.push_back("test area = " + std::to_string(p.grid.w) + " x " + std::to_string(p.grid.h) + " [m]");
    t.notes.push_back("step = " + std::to_string(p.grid.sx) + " x " + std::to_string(p.grid.sy) + " [m]");
    t.notes.insert(t.notes.end(), p.notes.begin(), p.notes.end());
    t.add("x", "m");
    t.add("z", "m");
    t.add("rho_simple", "1");
    t.add("rho_improved", "1");
    t.add("A_k", "m^2");
    t.add("grains", "1");
    for (std::size_t k = 0; k < p.grid.count(); ++k) {
        const Vec2 c = p.grid.centre(k);
        t.columns[0].values.push_back(c.x);
        t.columns[1].values.push_back(c.y);
        t.columns[2].values.push_back(p.simple[k]);
        t.columns[3].values.push_back(p.improved[k]);
        t.columns[4].values.push_back(p.hullArea[k]);
        t.columns[5].values.push_back(static_cast<Real>(p.grains[k]));
    }
    return t;
}

}  // namespace granulab::analysis
