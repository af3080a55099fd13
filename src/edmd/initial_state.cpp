// SPDX-License-Identifier: MIT
// Lattice and random placement, polydisperse radii, Maxwell velocities (edmd spec 4.2).
#include "edmd/initial_state.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/rng.hpp"
#include "edmd/kinetic_theory.hpp"

namespace granulab::edmd {

namespace {

template <int D>
void placeOnLattice(const InitialStateSpec& spec, GasState<D>& g) {
    // Sites per axis in proportion to the box edges, at least N sites in all; the N particles
    // take evenly spread sites (site floor(k S / N)), so a partly filled lattice has no hole.
    Real volume = 1;
    for (int d = 0; d < D; ++d) volume *= spec.box[d];
    const Real spacingGuess = std::pow(volume / static_cast<Real>(spec.count), 1.0 / D);
    std::array<std::uint64_t, 3> sites{1, 1, 1};
    std::uint64_t total = 1;
    for (int d = 0; d < D; ++d) {
        sites[d] =
            std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::floor(spec.box[d] / spacingGuess)));
        total *= sites[d];
    }
    for (int d = 0; total < spec.count; d = (d + 1) % D) {  // round up axis by axis until N fit
        total = total / sites[d] * (sites[d] + 1);
        ++sites[d];
    }
    const Real rmax = std::max(spec.radius, spec.radiusMax);
    for (int d = 0; d < D; ++d) {
        const Real spacing = spec.box[d] / static_cast<Real>(sites[d]);
        if (spacing < 2 * rmax)
            throw std::invalid_argument(
                "the lattice spacing " + std::to_string(spacing) + " m along axis " + std::to_string(d) +
                " is below the largest diameter " + std::to_string(2 * rmax) +
                " m: lower the volume fraction (a simple lattice holds at most " +
                (D == 2 ? "0.785" : "0.524") + "), or start lower and grow (edmd.growth_rate)");
    }
    for (std::uint64_t k = 0; k < spec.count; ++k) {
        std::uint64_t site = static_cast<std::uint64_t>((static_cast<long double>(k) * total) / spec.count);
        VecD<D> p;
        for (int d = 0; d < D; ++d) {
            p[d] = (static_cast<Real>(site % sites[d]) + 0.5) * spec.box[d] / static_cast<Real>(sites[d]);
            site /= sites[d];
        }
        g.x.push_back(p);
    }
}

template <int D>
void placeAtRandom(const InitialStateSpec& spec, GasState<D>& g) {
    // Random sequential addition with a cell grid of edge >= the largest diameter.
    const Real rmax = std::max(spec.radius, spec.radiusMax);
    std::array<int, 3> cells{1, 1, 1};
    std::size_t cellCount = 1;
    for (int d = 0; d < D; ++d) {
        cells[d] = std::max(1, static_cast<int>(std::min<Real>(spec.box[d] / (2 * rmax), 1 << 20)));
        cellCount *= static_cast<std::size_t>(cells[d]);
    }
    std::vector<std::vector<std::uint32_t>> members(cellCount);
    CounterRng rng(spec.seed, 0xED0D);
    const std::uint64_t maxAttempts = 2000 * spec.count + 100000;
    std::uint64_t attempts = 0;
    auto cellOf = [&](const VecD<D>& p, int c[D]) {
        for (int d = 0; d < D; ++d)
            c[d] = std::clamp(static_cast<int>(p[d] / spec.box[d] * cells[d]), 0, cells[d] - 1);
    };
    while (g.x.size() < spec.count) {
        if (++attempts > maxAttempts)
            throw std::invalid_argument(
                "random placement found room for only " + std::to_string(g.x.size()) + " of " +
                std::to_string(spec.count) + " particles (random sequential addition jams near " +
                (D == 2 ? "0.547" : "0.38") + "): use placement = \"lattice\", or grow");
        const Real r = g.radius[g.x.size()];
        VecD<D> p;
        for (int d = 0; d < D; ++d) {
            const Real margin = spec.periodic[d] ? 0 : r;
            p[d] = rng.uniform(margin, spec.box[d] - margin);
        }
        int c[D];
        cellOf(p, c);
        bool free = true;
        int offset[D] = {};
        for (int d = 0; d < D; ++d) offset[d] = -1;
        while (free) {
            std::size_t index = 0;
            bool valid = true;
            for (int d = D - 1; d >= 0; --d) {
                int k = c[d] + offset[d];
                if (k < 0 || k >= cells[d]) {
                    if (!spec.periodic[d]) valid = false;
                    k = (k + cells[d]) % cells[d];
                }
                index = index * static_cast<std::size_t>(cells[d]) + static_cast<std::size_t>(k);
            }
            if (valid)
                for (const std::uint32_t j : members[index]) {
                    Real dist2 = 0;
                    for (int d = 0; d < D; ++d) {
                        Real dx = p[d] - g.x[j][d];
                        if (spec.periodic[d]) dx -= spec.box[d] * std::round(dx / spec.box[d]);
                        dist2 += dx * dx;
                    }
                    const Real s = r + g.radius[j];
                    if (dist2 < s * s) {
                        free = false;
                        break;
                    }
                }
            int d = 0;
            while (d < D && ++offset[d] > 1) offset[d++] = -1;
            if (d == D) break;
        }
        if (!free) continue;
        std::size_t index = 0;
        for (int d = D - 1; d >= 0; --d)
            index = index * static_cast<std::size_t>(cells[d]) + static_cast<std::size_t>(c[d]);
        members[index].push_back(static_cast<std::uint32_t>(g.x.size()));
        g.x.push_back(p);
    }
}

}  // namespace

template <int D>
GasState<D> makeInitialState(const InitialStateSpec& spec) {
    if (spec.count == 0) throw std::invalid_argument("no particles requested");
    GasState<D> g;
    CounterRng sizes(spec.seed, 0xED01);
    g.radius.resize(spec.count);
    g.mass.resize(spec.count);
    for (std::uint64_t i = 0; i < spec.count; ++i) {
        const Real r =
            spec.radiusMax > spec.radius ? sizes.uniform(spec.radius, spec.radiusMax) : spec.radius;
        g.radius[i] = r;
        g.mass[i] = spec.mass * std::pow(r / spec.radius, D);
    }
    g.x.reserve(spec.count);
    if (spec.placement == Placement::Lattice)
        placeOnLattice(spec, g);
    else
        placeAtRandom(spec, g);
    // Maxwell velocities: each component N(0, T0/m_i), then zero momentum, then rescaled so
    // that T = 2 E / (D N) is exactly T0 (edmd spec 4.2 step 2).
    CounterRng velocities(spec.seed, 0xED02);
    g.v.resize(spec.count);
    VecD<D> momentum;
    Real totalMass = 0;
    for (std::uint64_t i = 0; i < spec.count; ++i) {
        for (int d = 0; d < D; ++d) g.v[i][d] = velocities.normal() * std::sqrt(spec.temperature / g.mass[i]);
        momentum = momentum + g.v[i] * g.mass[i];
        totalMass += g.mass[i];
    }
    const VecD<D> drift = momentum * (1 / totalMass);
    Real energy = 0;
    for (std::uint64_t i = 0; i < spec.count; ++i) {
        g.v[i] = g.v[i] - drift;
        energy += 0.5 * g.mass[i] * dot(g.v[i], g.v[i]);
    }
    const Real temperature = 2 * energy / (D * static_cast<Real>(spec.count));
    const Real scale = temperature > 0 ? std::sqrt(spec.temperature / temperature) : 0;
    for (auto& v : g.v) v = v * scale;
    return g;
}

template GasState<2> makeInitialState<2>(const InitialStateSpec&);
template GasState<3> makeInitialState<3>(const InitialStateSpec&);

Real unitLatticeEdge(int dim, std::uint64_t count, Real nu) {
    return boxLengthFor(dim, static_cast<Real>(count), nu, 1.0);
}

template <int D>
GasState<D> unitLatticeGas(std::uint64_t count, Real nu, std::uint64_t seed) {
    const Real L = unitLatticeEdge(D, count, nu);
    InitialStateSpec spec;
    spec.box = {L, L, L};
    spec.count = count;
    spec.radius = 1;
    spec.mass = 1;
    spec.placement = Placement::Lattice;
    spec.temperature = 1;
    spec.seed = seed;
    return makeInitialState<D>(spec);
}

template GasState<2> unitLatticeGas<2>(std::uint64_t, Real, std::uint64_t);
template GasState<3> unitLatticeGas<3>(std::uint64_t, Real, std::uint64_t);

}  // namespace granulab::edmd
