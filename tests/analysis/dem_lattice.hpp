// SPDX-License-Identifier: MIT
// Hand-built DEM frames for the analysis tests: disk lattices and their contacts.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "analysis/dem_frame.hpp"
#include "core/types.hpp"

namespace granulab::test {

/// Appends a disk (id = current size) of radius r [m] and mass m [kg] at (x, y) at rest.
inline void addDisk(analysis::GrainFrame& f, Real x, Real y, Real r, Real m) {
    f.id.push_back(static_cast<std::int64_t>(f.size()));
    f.x.push_back(x);
    f.y.push_back(y);
    f.vx.push_back(0);
    f.vy.push_back(0);
    f.omega.push_back(0);
    f.angle.push_back(0);
    f.radius.push_back(r);
    f.speed.push_back(0);
    f.mass.push_back(m);
    f.material.push_back(0);
    f.cornerStart.push_back(f.corners.size());
}

/// Hexagonal lattice of touching disks of radius r: row j at y = y0 + j sqrt(3) r, odd rows
/// shifted by r; nx disks per row from x0, ny rows. Packing fraction pi / (2 sqrt 3).
inline analysis::GrainFrame hexLattice(std::size_t nx, std::size_t ny, Real r, Real x0 = 0, Real y0 = 0) {
    analysis::GrainFrame f;
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i)
            addDisk(f, x0 + 2 * r * static_cast<Real>(i) + (j % 2 ? r : 0),
                    y0 + std::sqrt(3.0) * r * static_cast<Real>(j), r, 1);
    return f;
}

/// Appends a contact: force F on a at point p, normal n from a to b (b = -1 and wall >= 0 at a wall).
inline void addContact(analysis::ContactFrame& c, std::int64_t a, std::int64_t b, std::int32_t wall, Vec2 p,
                       Vec2 n, Vec2 F) {
    c.a.push_back(a);
    c.b.push_back(b);
    c.wall.push_back(wall);
    c.px.push_back(p.x);
    c.py.push_back(p.y);
    c.nx.push_back(n.x);
    c.ny.push_back(n.y);
    c.fx.push_back(F.x);
    c.fy.push_back(F.y);
    c.fn.push_back(-dot(F, n));
    c.ft.push_back(dot(F, perp(n)));
    c.depth.push_back(0);
    c.area.push_back(0);
    c.length.push_back(0);
}

}  // namespace granulab::test
