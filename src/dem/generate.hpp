// SPDX-License-Identifier: MIT
// Expands explicit particles, generated blocks (lattices, random placement, size
// distributions, thermal velocities) and heaps into one list of initial particles, deterministically
// from the scene seed (core/rng.hpp).
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "model/gc2d_generators.hpp"
#include "model/mass_model.hpp"
#include "model/scene_def.hpp"
#include "model/shape_pool.hpp"

namespace granulab::dem {

struct InitialParticle {
    Vec2 position, velocity;
    Real angle = 0, omega = 0;
    Real radius = 0;                          ///< [m] disk radius, or the polygon's circumradius
    std::uint32_t shape = model::kDiskShape;  ///< index into InitialParticles::shapes
    std::uint32_t material = 0;
    std::uint32_t origin = 0;  ///< index into InitialParticles::origins (where it was defined)
};

struct InitialParticles {
    std::vector<InitialParticle> particles;  ///< id = index
    std::vector<SourceLoc> origins;          ///< explicit particles and blocks, by origin index
    model::ShapePool shapes;                 ///< polygon shapes of the particles
};

/// Mass [kg] of initial particle p with the density rho of its material (model::grainMass).
inline Real initialMass(const InitialParticles& init, const InitialParticle& p, model::MassModel massModel,
                        Real rho) noexcept {
    return model::grainMass(massModel, rho, p.radius,
                            p.shape == model::kDiskShape ? Real(-1) : init.shapes.area[p.shape]);
}

/// One radius [m] drawn from a size distribution (truncated Gaussian by rejection).
inline Real drawRadius(const model::SizeDistDef& d, CounterRng& rng) {
    switch (d.kind) {
        case model::SizeDistDef::Kind::Constant:
            return d.value;
        case model::SizeDistDef::Kind::Uniform:
            return rng.uniform(d.min, d.max);
        case model::SizeDistDef::Kind::Gaussian:
            for (int attempt = 0; attempt < 1000000; ++attempt) {
                const Real r = d.mean + d.sigma * rng.normal();
                if (r >= d.min && r <= d.max) return r;
            }
            return std::clamp(d.mean, d.min, d.max);
    }
    return d.value;
}

/// Particles a lattice block will create, estimated before generation from its region and
/// spacing (an upper estimate: region grown by one spacing, 0.8 of the square-lattice density
/// bound); 0 for an invalid lattice, which validation reports.
inline double latticeSiteEstimate(const model::BlockDef& b) noexcept {
    if (b.lattice == model::BlockDef::Lattice::Rect || b.lattice == model::BlockDef::Lattice::Fcc) {
        // gc2d lattices: at most (W/dx + 1) sites in each of at most (H/dy + 1) rows.
        const Real dx = b.grid.x, dy = b.grid.y;
        if (!(dx > 0 && dy > 0 && b.xmax > b.xmin && b.ymax > b.ymin)) return 0;
        return (b.xmax - b.xmin + dx) * (b.ymax - b.ymin + dy) / (dx * dy);
    }
    if (!(b.spacing > 0 && b.xmax > b.xmin && b.ymax > b.ymin)) return 0;
    return (b.xmax - b.xmin + b.spacing) * (b.ymax - b.ymin + b.spacing) / (0.8 * b.spacing * b.spacing);
}

/// Sites of heap `h` made of grains `g` (gc2d heap.pm, spec section 6.5; docs/scene-format.md
/// "[[heap]]"): rows from the bottom (centres at base + height/2 + k rows-pitch), left to right,
/// symmetric about the middle of x_range; a site is filled when its centre lies under both slope
/// lines (y - base <= tan(slope) (distance to the nearer end), within 1e-9 of a pitch) and, in
/// hexagonal stacks, both grains below it are filled (rectangular: the grain below). Empty for
/// an invalid heap.
std::vector<Vec2> heapSites(const model::HeapDef& h, const model::HeapGrain& g);

/// Appends the grains of every [[heap]] to `out` (after the blocks), with the heap's material
/// (index in `materialNames`); a heap that places no grain or far too many goes to `diags`.
void generateHeaps(const model::SceneDef& scene, const std::vector<std::string>& materialNames,
                   InitialParticles& out, Diagnostics& diags);

/// Generates all particles; a particle's material id is the index of its material in
/// `materialNames` (model::materialNames).
/// Problems (a block that cannot place its particles) go to `diags`.
InitialParticles generateParticles(const model::SceneDef& scene,
                                   const std::vector<std::string>& materialNames, Diagnostics& diags);

}  // namespace granulab::dem
