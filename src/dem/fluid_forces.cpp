// SPDX-License-Identifier: MIT
// Fluid forces and mutual attraction (dem/fluid_forces.hpp; cfddem spec 5.2-5.7).
#include "dem/fluid_forces.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace granulab::dem {

namespace {

constexpr Real kMinVoidage = 0.1;  ///< floor of the voidage (Di Felice's factor diverges at 0)

/// Voidage at each particle from the particle volume per square cell of edge h in a slab of
/// thickness `depth`: eps = 1 - V_solid / (h^2 depth), at least kMinVoidage.
void voidages(const model::ParticleStore& s, Real h, Real depth, VoidageScratch& scratch,
              std::vector<Real>& out) {
    scratch.bins.build(s, h);
    const Real cellVolume = h * h * depth;
    for (std::size_t c = 0; c < scratch.bins.cellCount(); ++c) {
        const auto [begin, end] = scratch.bins.members(c);
        Real solid = 0;
        for (const std::uint32_t* i = begin; i != end; ++i)
            solid += 4.0 / 3.0 * kPi * std::pow(s.radius[*i], 3);
        for (const std::uint32_t* i = begin; i != end; ++i)
            out[*i] = std::max(kMinVoidage, 1 - solid / cellVolume);
    }
}

template <class Drag, class Method>
void fluidLoop(model::ParticleStore& s, const Drag& drag, const Method& method,
               const fluid::FieldSeries& field, const FluidForceConfig& c, Vec2 g,
               const std::vector<Real>* voidage, fluid::LocalPatch* patches, FluidStats& stats) noexcept {
    const fluid::FieldInterpolator* second = field.second();
    const Real w = field.weight();
    Real maxReynoldsArg2 = 0;  ///< [m^4/s^2] largest (|v_r| eps R)^2
    for (std::size_t i = 0; i < s.size(); ++i) {
        const Vec2 pos{s.x[i], s.y[i]};
        fluid::FluidSample f;
        if constexpr (std::is_same_v<Method, fluid::CellMesh> ||
                      std::is_same_v<Method, fluid::BilinearGrid>) {
            if (patches[i].interior(pos))
                f.u = patches[i].velocity(pos);  // still in its cell: no field memory touched
            else
                method.sample(pos, f, patches[i]);
        } else {
            method.sample(pos, f);
        }
        if (second) {
            const fluid::FluidSample f2 = second->sample(pos);
            f.u = f.u * (1 - w) + f2.u * w;
            f.inside = f.inside && f2.inside;
        }
        if (!f.inside) ++stats.outside;
        const Real r = s.radius[i];
        const Real volume = 4.0 / 3.0 * kPi * r * r * r;  // [m^3] sphere
        const Vec2 vr = Vec2{s.vx[i], s.vy[i]} - f.u;     // relative velocity (cfddem 5.3 [I])
        const Real eps = voidage ? (*voidage)[i] : 1.0;
        Vec2 force = drag.force(vr, r, c.fluid, eps);
        stats.drag += force;
        if constexpr (!std::is_same_v<Drag, fluid::NoDrag>)  // Re ~ |v_r| eps r: its square, no sqrt here
            maxReynoldsArg2 = std::max(maxReynoldsArg2, norm2(vr) * eps * eps * r * r);
        if (c.buoyancy) force -= g * (c.fluid.density * volume);  // cfddem Eq. 3.63
        if (c.pressureGradient) force -= field.pressureGradient(pos) * (volume * c.pressureToPascal);
        s.fx[i] += force.x;
        s.fy[i] += force.y;
    }
    stats.maxReynolds = fluid::reynolds(c.fluid, std::sqrt(maxReynoldsArg2), 1.0);
}

}  // namespace

void addFluidForces(model::ParticleStore& s, const fluid::FieldSeries& field, const FluidForceConfig& c,
                    Vec2 g, FluidStats& stats, VoidageScratch& scratch) noexcept {
    stats = FluidStats{};
    if (s.size() == 0) return;
    std::vector<Real>& eps = scratch.eps;
    const std::vector<Real>* voidage = nullptr;
    if (fluid::needsVoidage(c.drag)) {
        Real rmax = 0;
        for (const Real r : s.radius) rmax = std::max(rmax, r);
        const Real depth = c.depth > 0 ? c.depth : 2 * rmax;
        const Real h = c.voidageCell > 0 ? c.voidageCell : std::max(field.first().spacing(), 8 * rmax);
        eps.resize(s.size());
        voidages(s, h, depth, scratch, eps);
        voidage = &eps;
        stats.minVoidage = *std::min_element(eps.begin(), eps.end());
    }
    // A patch is the interpolant of a cell, valid for whichever particle is inside it: slots
    // renumbered by re-sorting, insertion or removal keep theirs; a new field invalidates all.
    if (scratch.patchesGeneration != field.generation()) {
        scratch.patches.assign(s.size(), fluid::LocalPatch{});
        scratch.patchesGeneration = field.generation();
    } else if (scratch.patches.size() != s.size()) {
        scratch.patches.resize(s.size());
    }
    fluid::LocalPatch* patches = scratch.patches.data();
    std::visit(
        [&](const auto& drag) {
            field.first().visit([&](const auto& method) {
                fluidLoop(s, drag, method, field, c, g, voidage, patches, stats);
            });
        },
        c.drag);
}

void addAttraction(model::ParticleStore& s, Real constant, Real cutoff, CellBins& bins) noexcept {
    const std::size_t n = s.size();
    const auto pair = [&](std::size_t i, std::size_t j) {
        const Real dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i];
        const Real d2 = dx * dx + dy * dy;
        if (d2 == 0 || (cutoff > 0 && d2 > cutoff * cutoff)) return;
        const Real d = std::sqrt(d2);
        const Real f = constant * s.mass[i] * s.mass[j] / d2;  // cfddem Eq. 3.72, attractive
        const Real fx = f * dx / d, fy = f * dy / d;
        s.fx[i] += fx;
        s.fy[i] += fy;
        s.fx[j] -= fx;
        s.fy[j] -= fy;
    };
    if (cutoff <= 0) {
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) pair(i, j);
        return;
    }
    if (n < 2) return;
    // Cells of edge `cutoff`: pairs in the same cell and in the 4 forward neighbour cells.
    bins.build(s, cutoff);
    const std::int64_t offsets[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
    for (std::size_t c = 0; c < bins.cellCount(); ++c) {
        const auto [begin, end] = bins.members(c);
        for (const std::uint32_t* a = begin; a != end; ++a) {
            for (const std::uint32_t* b = a + 1; b != end; ++b) pair(*a, *b);
            for (const auto& o : offsets) {
                const std::size_t d = bins.find(bins.cellX(c) + o[0], bins.cellY(c) + o[1]);
                if (d == bins.cellCount()) continue;
                const auto [nb, ne] = bins.members(d);
                for (const std::uint32_t* b = nb; b != ne; ++b) pair(*a, *b);
            }
        }
    }
}

}  // namespace granulab::dem
