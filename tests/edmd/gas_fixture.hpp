// SPDX-License-Identifier: MIT
// Shared helpers of the EDMD physics validation tests (edmd spec 4.2-4.6, 5.2-5.3, 5.7): a
// periodic gas of N equal disks/spheres (m = a = 1, T0 = 1) at volume fraction nu, equilibrated
// as in spec 4.2 (lattice, Maxwell velocities, elastic pre-run, restartClock), block-averaged
// measurement windows, snapshots for the gas analyses; and the small lattice gas and the
// all-pairs overlap check that the engine unit tests share.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "analysis/point_set.hpp"
#include "core/rng.hpp"
#include "edmd/engine.hpp"
#include "edmd/initial_state.hpp"
#include "edmd/kinetic_theory.hpp"

namespace granulab::edmd::validation {

/// Smallest centre distance over all pairs divided by the contact distance (O(N^2), minimum
/// image); 1 - round-off when particles touch, below 1 if any pair overlaps.
template <class E>
Real minimumGapRatio(const E& e) {
    Real worst = 1e300;
    for (std::uint32_t i = 0; i < e.size(); ++i)
        for (std::uint32_t j = i + 1; j < e.size(); ++j) {
            const auto r = e.separation(i, j);
            worst = std::min(worst, std::sqrt(dot(r, r)) / (e.radius(i) + e.radius(j)));
        }
    return worst;
}

/// n^D particles of radius a and unit mass on a cubic lattice in a box of edge L (sites centred
/// in their cells), Gaussian velocities with zero total momentum (not rescaled).
template <int D>
GasState<D> latticeGas(int n, Real L, Real a, std::uint64_t seed) {
    GasState<D> g;
    CounterRng rng(seed, 0);
    int count = 1;
    for (int d = 0; d < D; ++d) count *= n;
    VecD<D> mean;
    for (int k = 0; k < count; ++k) {
        VecD<D> p, u;
        int rest = k;
        for (int d = 0; d < D; ++d) {
            p[d] = (rest % n + 0.5) * L / n;
            rest /= n;
            u[d] = rng.normal();
        }
        g.x.push_back(p);
        g.v.push_back(u);
        mean = mean + u;
    }
    for (auto& u : g.v) u = u - mean * (1.0 / count);
    g.radius.assign(g.x.size(), a);
    g.mass.assign(g.x.size(), 1.0);
    return g;
}

/// A periodic gas of `count` particles of radius 1 and mass 1 at temperature 1 and volume fraction
/// nu, started on the lattice (spec 4.2 steps 1-2). The engine starts elastic.
template <int D>
Engine<D> makeGas(std::uint64_t count, Real nu, std::uint64_t seed, const Restitution& rules = {},
                  Real tc = 0) {
    const Real L = unitLatticeEdge(D, count, nu);
    auto s = unitLatticeGas<D>(count, nu, seed);
    EngineConfig c;
    c.box = {L, L, L};
    c.restitution = rules;
    c.tc = tc;
    return Engine<D>(c, std::move(s.x), std::move(s.v), std::move(s.radius), std::move(s.mass));
}

/// Elastic pre-run of `collisionsPerParticle` collisions per particle (a collision involves two
/// particles, so N c/2 collision events; spec 4.2 step 3), then restartClock (step 4).
template <int D>
void equilibrate(Engine<D>& e, Real collisionsPerParticle) {
    e.runCollisions(static_cast<std::uint64_t>(collisionsPerParticle * e.size() / 2));
    e.restartClock();
}

/// Granular temperature T = 2 E/(D N) (spec 4.4; E total kinetic energy, k_B = 1).
template <int D>
Real temperature(const Engine<D>& e) {
    return 2 * e.kineticEnergy() / (D * static_cast<Real>(e.size()));
}

/// Mean and standard error of the mean of independent block values.
struct BlockMean {
    Real mean = 0, error = 0;
};
inline BlockMean blockMean(const std::vector<Real>& values) {
    BlockMean b;
    const auto n = static_cast<Real>(values.size());
    for (Real v : values) b.mean += v;
    b.mean /= n;
    Real s2 = 0;
    for (Real v : values) s2 += (v - b.mean) * (v - b.mean);
    b.error = std::sqrt(s2 / (n - 1) / n);
    return b;
}

/// Blocking analysis (Flyvbjerg and Petersen, J. Chem. Phys. 91, 461 (1989)): the standard error
/// of the mean from the blocks merged in groups of 1, 2, 3 and 5 consecutive blocks (at least 6
/// groups), the largest of them. Conservative when the blocks are not quite independent (slow
/// structural modes of dense fluids outlast a block).
inline BlockMean blockedMean(const std::vector<Real>& values) {
    BlockMean result = blockMean(values);
    for (std::size_t group : {2u, 3u, 5u}) {
        if (values.size() / group < 6) break;
        std::vector<Real> merged;
        for (std::size_t k = 0; k + group <= values.size(); k += group) {
            Real s = 0;
            for (std::size_t j = 0; j < group; ++j) s += values[k + j];
            merged.push_back(s / static_cast<Real>(group));
        }
        result.error = std::max(result.error, blockMean(merged).error);
    }
    return result;
}

/// Snapshot of the engine for the gas analyses.
template <int D>
analysis::PointSet snapshot(const Engine<D>& e) {
    analysis::PointSet p;
    p.dim = D;
    p.box = e.config().box;
    p.periodic = e.config().periodic;
    for (std::uint32_t i = 0; i < e.size(); ++i) {
        const auto x = e.positionNow(i);
        const auto v = e.velocityNow(i);
        for (int d = 0; d < D; ++d) {
            // positionNow wraps into [0, L]; keep the analyses' [0, L) contract under round-off.
            Real xd = x[d];
            if (xd >= p.box[static_cast<std::size_t>(d)]) xd -= p.box[static_cast<std::size_t>(d)];
            p.x.push_back(std::max<Real>(xd, 0));
            p.v.push_back(v[d]);
        }
        p.radius.push_back(e.radius(i));
        p.mass.push_back(e.mass(i));
    }
    return p;
}

}  // namespace granulab::edmd::validation
