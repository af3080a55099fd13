// SPDX-License-Identifier: MIT
// Hand-built DEM frames for the analysis tests: disk lattices and their contacts.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "analysis/dem_frame.hpp"
#include "core/types.hpp"
#include "dem_frames.hpp"

namespace granulab::test {

/// Appends a disk (id = current size) of radius r [m] and mass m [kg] at (x, y) at rest.
inline void appendDisk(analysis::GrainFrame& f, Real x, Real y, Real r, Real m) {
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
            appendDisk(f, x0 + 2 * r * static_cast<Real>(i) + (j % 2 ? r : 0),
                       y0 + std::sqrt(3.0) * r * static_cast<Real>(j), r, 1);
    return f;
}

}  // namespace granulab::test
