// SPDX-License-Identifier: MIT
// Slabs of the DEM domain decomposition (dem/parallel/slab_partition.hpp).
#include "dem/parallel/slab_partition.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granulab::dem {

Real SlabPartition::lower(int r) const noexcept {
    return r <= 0 ? -std::numeric_limits<Real>::infinity() : cuts[static_cast<std::size_t>(r - 1)];
}

Real SlabPartition::upper(int r) const noexcept {
    return r >= ranks() - 1 ? std::numeric_limits<Real>::infinity() : cuts[static_cast<std::size_t>(r)];
}

int SlabPartition::owner(Real c) const noexcept {
    return static_cast<int>(std::upper_bound(cuts.begin(), cuts.end(), c) - cuts.begin());
}

SlabPartition uniformSlabs(int axis, Real lo, Real hi, int ranks) {
    SlabPartition p;
    p.axis = axis;
    for (int r = 1; r < ranks; ++r) p.cuts.push_back(lo + (hi - lo) * r / ranks);
    return p;
}

SlabPartition balancedSlabs(Communicator& comm, int axis, std::span<const Real> coords,
                            std::span<const Real> weights, Real emptyLo, Real emptyHi) {
    const int ranks = comm.size();
    double range[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    for (const Real c : coords) {  // [min, -max] in one reduction
        range[0] = std::min(range[0], c);
        range[1] = std::min(range[1], -c);
    }
    comm.allMin(range);
    const Real lo = range[0], hi = -range[1];
    if (!(hi > lo)) return uniformSlabs(axis, emptyLo, emptyHi, ranks);
    const std::size_t bins = 256 * static_cast<std::size_t>(ranks);
    const Real width = (hi - lo) / static_cast<Real>(bins);
    std::vector<double> histogram(bins, 0.0);
    for (std::size_t k = 0; k < coords.size(); ++k) {
        const auto b = static_cast<std::size_t>(std::clamp<Real>((coords[k] - lo) / width, 0, bins - 1));
        histogram[b] += weights[k];
    }
    comm.allSum(histogram);
    double total = 0;
    for (const double h : histogram) total += h;
    if (!(total > 0)) return uniformSlabs(axis, emptyLo, emptyHi, ranks);
    SlabPartition p;
    p.axis = axis;
    double below = 0;  // weight in bins [0, b)
    std::size_t b = 0;
    for (int r = 1; r < ranks; ++r) {
        const double target = total * r / ranks;
        while (b < bins && below + histogram[b] < target) below += histogram[b++];
        const double inBin = b < bins && histogram[b] > 0 ? (target - below) / histogram[b] : 0.0;
        p.cuts.push_back(lo + width * (static_cast<Real>(b) + inBin));
    }
    return p;
}

}  // namespace granulab::dem
