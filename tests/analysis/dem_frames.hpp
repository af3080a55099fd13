// SPDX-License-Identifier: MIT
// Test helpers for the DEM pile analyses (gc2d spec section 7): hand-built grain and contact
// frames, wall segments, and a synthetic heap of disks on a square lattice with known flank angle.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "analysis/dem_frame.hpp"
#include "core/types.hpp"

namespace granulab::test {

/// Appends a disk of radius r [m] at (x, y) [m] with id `id` (mass 1 kg, at rest).
inline void addDisk(analysis::GrainFrame& g, std::int64_t id, Real x, Real y, Real r) {
    g.id.push_back(id);
    g.x.push_back(x);
    g.y.push_back(y);
    g.vx.push_back(0);
    g.vy.push_back(0);
    g.omega.push_back(0);
    g.angle.push_back(0);
    g.radius.push_back(r);
    g.speed.push_back(0);
    g.mass.push_back(1);
    g.material.push_back(0);
    g.cornerStart.push_back(g.corners.size());
}

/// Appends a contact between grain a and grain b (b = -1 with wall >= 0) at point p with unit
/// normal n (a toward b) and force f on a [N]; fn = -f.n, ft = f.perp(n).
inline void addContact(analysis::ContactFrame& c, std::int64_t a, std::int64_t b, std::int32_t wall, Vec2 p,
                       Vec2 n, Vec2 f) {
    c.a.push_back(a);
    c.b.push_back(b);
    c.wall.push_back(wall);
    c.px.push_back(p.x);
    c.py.push_back(p.y);
    c.nx.push_back(n.x);
    c.ny.push_back(n.y);
    c.fx.push_back(f.x);
    c.fy.push_back(f.y);
    c.fn.push_back(-dot(f, n));
    c.ft.push_back(dot(f, perp(n)));
    c.depth.push_back(0);
    c.area.push_back(0);
    c.length.push_back(0);
}

/// A grain-grain contact with force f on a along -n (a pure normal or arbitrary force).
inline void addPair(analysis::ContactFrame& c, std::int64_t a, std::int64_t b, Vec2 f) {
    const Real m = norm(f);
    const Vec2 n = m > 0 ? -f / m : Vec2{1, 0};
    addContact(c, a, b, -1, {0, 0}, n, f);
}

inline void addSegment(analysis::WallSegments& w, std::int32_t wall, Vec2 a, Vec2 b) {
    w.a.push_back(a);
    w.b.push_back(b);
    w.wall.push_back(wall);
}

/// Heap of disks of radius r on a square lattice of spacing 2r: columns at x = (i + 1/2) 2r for
/// i in [-apron, columns + apron), rows at y = r + j 2r; a disk is kept when its centre lies on or
/// below min(tan(angle) x, tan(angle) (L - x)), L = 2r columns, or it is in row 0 (the floor layer
/// that extends `apron` columns beyond the heap on each side).
inline analysis::GrainFrame latticeHeap(Real angleDeg, std::size_t columns, std::size_t apron, Real r) {
    analysis::GrainFrame g;
    const Real d = 2 * r, slope = std::tan(angleDeg * kPi / 180), length = d * static_cast<Real>(columns);
    std::int64_t id = 0;
    const auto first = -static_cast<std::int64_t>(apron), last = static_cast<std::int64_t>(columns + apron);
    for (std::int64_t i = first; i < last; ++i) {
        const Real x = (static_cast<Real>(i) + 0.5) * d;
        const Real top = std::min(slope * x, slope * (length - x));
        for (std::int64_t j = 0;; ++j) {
            const Real y = r + static_cast<Real>(j) * d;
            if (j > 0 && y > top) break;
            addDisk(g, id++, x, y, r);
        }
    }
    return g;
}

}  // namespace granulab::test
