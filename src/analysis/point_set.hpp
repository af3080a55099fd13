// SPDX-License-Identifier: MIT
// A snapshot of hard disks (D = 2) or spheres (D = 3) as the gas analyses read it (edmd spec
// section 5.2): positions, radii and velocities in flat arrays, and the box. Pure data; filled
// by the edmd engine's observers or by a reader of snapshot files.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "core/types.hpp"

namespace granulab::analysis {

struct PointSet {
    int dim = 3;                       ///< 2 (disks) or 3 (spheres)
    std::array<Real, 3> box{1, 1, 1};  ///< [m] box edge per axis (origin at 0); unused axes ignored
    std::array<bool, 3> periodic{true, true, true};  ///< periodic axes use the minimum image
    std::vector<Real> x;       ///< [m] positions, dim values per particle, inside [0, box)
    std::vector<Real> v;       ///< [m/s] velocities, dim values per particle (may be empty)
    std::vector<Real> radius;  ///< [m] one per particle
    std::vector<Real> mass;    ///< [kg] one per particle (may be empty: unit masses)

    std::size_t size() const noexcept { return radius.size(); }
    /// Volume (2D: area) of the box [m^D].
    Real volume() const noexcept {
        Real V = 1;
        for (int d = 0; d < dim; ++d) V *= box[static_cast<std::size_t>(d)];
        return V;
    }
};

}  // namespace granulab::analysis
