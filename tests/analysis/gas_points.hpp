// SPDX-License-Identifier: MIT
// Test helpers for the gas analyses (edmd spec 5.2): random and lattice PointSets with a fixed
// counter-based seed, and the brute-force minimum image used by the O(N^2) references.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "analysis/point_set.hpp"
#include "core/rng.hpp"

namespace granulab::test {

/// N uniform random centres in `box` (dim 2 or 3), radii uniform in [radiusMin, radiusMax] [m].
inline analysis::PointSet randomPoints(int dim, std::size_t n, std::array<Real, 3> box, Real radiusMin,
                                       Real radiusMax, std::uint64_t seed) {
    analysis::PointSet p;
    p.dim = dim;
    p.box = box;
    CounterRng rng(seed, 0);
    p.x.resize(n * static_cast<std::size_t>(dim));
    p.radius.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int d = 0; d < dim; ++d)
            p.x[i * static_cast<std::size_t>(dim) + static_cast<std::size_t>(d)] =
                rng.uniform(0, box[static_cast<std::size_t>(d)]);
        p.radius[i] = rng.uniform(radiusMin, radiusMax);
    }
    return p;
}

/// Simple square (2D) / cubic (3D) lattice of `perAxis`^dim sites at (i + 1/2) spacing, in a
/// periodic box of edge perAxis * spacing; all radii `radius`.
inline analysis::PointSet latticePoints(int dim, std::size_t perAxis, Real spacing, Real radius) {
    analysis::PointSet p;
    p.dim = dim;
    const Real edge = static_cast<Real>(perAxis) * spacing;
    p.box = {edge, edge, edge};
    const std::size_t nz = dim == 3 ? perAxis : 1;
    for (std::size_t k = 0; k < nz; ++k)
        for (std::size_t j = 0; j < perAxis; ++j)
            for (std::size_t i = 0; i < perAxis; ++i) {
                p.x.push_back((static_cast<Real>(i) + 0.5) * spacing);
                p.x.push_back((static_cast<Real>(j) + 0.5) * spacing);
                if (dim == 3) p.x.push_back((static_cast<Real>(k) + 0.5) * spacing);
                p.radius.push_back(radius);
            }
    return p;
}

/// Squared minimum-image distance [m^2] of particles i and j, written independently of the
/// library (round instead of the one-fold correction).
inline Real bruteDistance2(const analysis::PointSet& p, std::size_t i, std::size_t j) {
    const auto dim = static_cast<std::size_t>(p.dim);
    Real r2 = 0;
    for (std::size_t d = 0; d < dim; ++d) {
        Real dx = p.x[j * dim + d] - p.x[i * dim + d];
        if (p.periodic[d]) dx -= p.box[d] * std::round(dx / p.box[d]);
        r2 += dx * dx;
    }
    return r2;
}

}  // namespace granulab::test
