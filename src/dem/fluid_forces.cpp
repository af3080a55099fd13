// SPDX-License-Identifier: MIT
// Fluid forces and mutual attraction (dem/fluid_forces.hpp; cfddem spec 5.2-5.7).
#include "dem/fluid_forces.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <type_traits>

#include "core/communicator.hpp"

namespace granulab::dem {

namespace {

constexpr Real kMinVoidage = 0.1;  ///< floor of the voidage (Di Felice's factor diverges at 0)

/// The voidage cells' edge h [m] and slab depth [m] (docs/physics/fluid.md, Eq. F15): the
/// configured ones, else max(node spacing, 8 R_max) and 2 R_max.
struct VoidageGeometry {
    Real h, depth;
};
VoidageGeometry voidageGeometry(const FluidForceConfig& c, Real spacing, Real rmax) noexcept {
    return {c.voidageCell > 0 ? c.voidageCell : std::max(spacing, 8 * rmax),
            c.depth > 0 ? c.depth : 2 * rmax};
}

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

/// The voidage of (F15) on the ranks of a domain decomposition: the same cells as voidages()
/// (laid from the lower-left corner of every rank's owned particles), each holding the volume of
/// every rank's owned particles whose centre lies in it, summed in slot order per rank and then
/// in rank order. R_max for the default cell and slab is the largest radius on any rank.
void voidagesOnRanks(const model::ParticleStore& s, const FieldRanks& ranks, const FluidForceConfig& c,
                     Real spacing, VoidageScratch& scratch, std::vector<Real>& out) {
    const std::size_t owned = std::min(ranks.owned, s.size());
    double box[3] = {1e300, 1e300, 1e300};  // min x, min y, -R_max over the owned particles
    for (std::size_t i = 0; i < owned; ++i) {
        box[0] = std::min(box[0], s.x[i]);
        box[1] = std::min(box[1], s.y[i]);
        box[2] = std::min(box[2], -s.radius[i]);
    }
    ranks.comm->allMin(box);
    const Real x0 = box[0], y0 = box[1];
    const auto [h, depth] = voidageGeometry(c, spacing, -box[2]);
    const auto keyOf = [&](std::size_t i) { return CellBins::cellKey(s.x[i], s.y[i], x0, y0, h); };
    auto& keyed = scratch.keyed;
    keyed.resize(owned);
    for (std::size_t i = 0; i < owned; ++i) keyed[i] = {keyOf(i), static_cast<std::uint32_t>(i)};
    std::sort(keyed.begin(), keyed.end());  // by cell, then slot: each cell sums in slot order
    struct CellVolume {
        std::uint64_t key;
        Real volume;  // [m^3]
    };
    std::vector<CellVolume> mine;
    for (const auto& [key, slot] : keyed) {
        const Real v = 4.0 / 3.0 * kPi * std::pow(s.radius[slot], 3);
        if (mine.empty() || mine.back().key != key)
            mine.push_back({key, v});
        else
            mine.back().volume += v;
    }
    // Every rank's cells in rank order; a stable sort keeps that order within a cell.
    std::vector<CellVolume> all = allGatherPod(*ranks.comm, std::span<const CellVolume>(mine));
    std::stable_sort(all.begin(), all.end(),
                     [](const CellVolume& a, const CellVolume& b) { return a.key < b.key; });
    std::size_t cells = 0;
    for (std::size_t k = 0; k < all.size(); ++k) {
        if (cells > 0 && all[cells - 1].key == all[k].key)
            all[cells - 1].volume += all[k].volume;
        else
            all[cells++] = all[k];
    }
    all.resize(cells);
    const Real cellVolume = h * h * depth;
    for (std::size_t i = 0; i < owned; ++i) {
        const std::uint64_t key = keyOf(i);
        const auto it = std::lower_bound(all.begin(), all.end(), key,
                                         [](const CellVolume& c, std::uint64_t k) { return c.key < k; });
        out[i] = it != all.end() && it->key == key ? std::max(kMinVoidage, 1 - it->volume / cellVolume) : 1.0;
    }
}

template <class Drag, class Method>
void fluidLoop(model::ParticleStore& s, const Drag& drag, const Method& method,
               const fluid::FieldSeries& field, const FluidForceConfig& c, Vec2 g,
               const std::vector<Real>* voidage, fluid::LocalPatch* patches, std::size_t count,
               FluidStats& stats) noexcept {
    const fluid::FieldInterpolator* second = field.second();
    const Real w = field.weight();
    Real maxReynoldsArg2 = 0;  ///< [m^4/s^2] largest (|v_r| eps R)^2
    for (std::size_t i = 0; i < count; ++i) {
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
                    Vec2 g, FluidStats& stats, VoidageScratch& scratch, const FieldRanks& ranks) {
    stats = FluidStats{};
    std::vector<Real>& eps = scratch.eps;
    const std::vector<Real>* voidage = nullptr;
    // On ranks the forces and statistics are those of the owned particles (a ghost's are its
    // owner's); one process: every particle.
    const std::size_t count = ranks.comm ? std::min(ranks.owned, s.size()) : s.size();
    if (ranks.comm && fluid::needsVoidage(c.drag)) {  // a collective: even a rank without particles
        eps.resize(s.size());
        voidagesOnRanks(s, ranks, c, field.first().spacing(), scratch, eps);
        voidage = &eps;
        if (count)
            stats.minVoidage =
                *std::min_element(eps.begin(), eps.begin() + static_cast<std::ptrdiff_t>(count));
    }
    if (count == 0) return;
    if (!voidage && fluid::needsVoidage(c.drag)) {
        Real rmax = 0;
        for (const Real r : s.radius) rmax = std::max(rmax, r);
        const auto [h, depth] = voidageGeometry(c, field.first().spacing(), rmax);
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
                fluidLoop(s, drag, method, field, c, g, voidage, patches, count, stats);
            });
        },
        c.drag);
}

namespace {

/// [N] Pull on a particle of mass mi [kg] at xi towards one of mass mj at xj (cfddem Eq. 3.72);
/// zero for coincident centres or beyond `cutoff` [m] (0: none).
inline Vec2 attractionOn(Vec2 xi, Real mi, Vec2 xj, Real mj, Real constant, Real cutoff) noexcept {
    const Real dx = xj.x - xi.x, dy = xj.y - xi.y;
    const Real d2 = dx * dx + dy * dy;
    if (d2 == 0 || (cutoff > 0 && d2 > cutoff * cutoff)) return {0, 0};
    const Real d = std::sqrt(d2);
    const Real f = constant * mi * mj / d2;
    return {f * dx / d, f * dy / d};
}

/// All pairs on the ranks of a domain decomposition: every rank's owned particles gathered, and
/// each owned particle pulled by all others in rank and slot order (one process sums the pair
/// forces in pair order instead: the two agree to round-off).
void attractionOnRanks(model::ParticleStore& s, Real constant, const FieldRanks& ranks) {
    struct Body {
        Real x, y, mass;
    };
    const std::size_t owned = std::min(ranks.owned, s.size());
    std::vector<Body> mine(owned);
    for (std::size_t i = 0; i < owned; ++i) mine[i] = {s.x[i], s.y[i], s.mass[i]};
    const std::vector<Body> all = allGatherPod(*ranks.comm, std::span<const Body>(mine));
    for (std::size_t i = 0; i < owned; ++i) {
        const Vec2 xi{s.x[i], s.y[i]};
        Vec2 sum{0, 0};
        for (const Body& b : all) sum += attractionOn(xi, s.mass[i], {b.x, b.y}, b.mass, constant, 0);
        s.fx[i] += sum.x;
        s.fy[i] += sum.y;
    }
}

}  // namespace

void addAttraction(model::ParticleStore& s, Real constant, Real cutoff, CellBins& bins,
                   const FieldRanks& ranks) {
    if (ranks.comm && cutoff <= 0) {
        attractionOnRanks(s, constant, ranks);
        return;
    }
    const std::size_t n = s.size();
    const auto pair = [&](std::size_t i, std::size_t j) {
        const Vec2 f =
            attractionOn({s.x[i], s.y[i]}, s.mass[i], {s.x[j], s.y[j]}, s.mass[j], constant, cutoff);
        s.fx[i] += f.x;
        s.fy[i] += f.y;
        s.fx[j] -= f.x;
        s.fy[j] -= f.y;
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
