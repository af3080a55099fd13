// SPDX-License-Identifier: MIT
// The force evaluation (stages 4+6 of the DEM step, DESIGN.md): body forces (gravity, global viscous
// damping, pull springs of gc2d spec section 3.8), then the contact kernels of every bucket of pairs.
// Why this shape: the law form is dispatched once per bucket (std::visit over the three axis
// variants, dem/forces_detail.hpp), the loop body is a template with the law inlined; parameters of
// a material pair are read from the LawTable with the alternative known at compile time. Pairs are
// processed in list order, so the floating-point summation order is fixed. The kernels are headers
// included here only, so that they are compiled and inlined in this translation unit.
#include "dem/forces.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "core/error.hpp"
#include "dem/forces_area_pairs.hpp"
#include "dem/forces_depth.hpp"
#include "dem/forces_detail.hpp"

namespace granulab::dem {

using detail::kAreaForm;
using detail::kDepthForm;

void computeForces(model::ParticleStore& s, const model::WallSet& walls, NeighborList& list,
                   const LawTable& laws, const BodyForces& body, const DriftVelocities& drift, Real dt,
                   bool trialHistory, ForceStats& stats, std::vector<Vec2>& wallForce, ShapeContext& shapes,
                   ContactLog* log) noexcept {
    GL_ASSERT(wallForce.size() == walls.walls.size(), "one force per wall");
    const std::size_t n = s.size();
    const Vec2 weightG = body.weight ? body.gravity : Vec2{};
    for (std::size_t i = 0; i < n; ++i) {
        s.fx[i] = s.mass[i] * weightG.x - body.gamma * s.vx[i];
        s.fy[i] = s.mass[i] * weightG.y - body.gamma * s.vy[i];
        s.torque[i] = -body.gammaRotation * s.omega[i];
    }
    if (body.springs)
        for (const PullSpring& sp : *body.springs) {  // gc2d spec section 3.8
            const std::uint32_t i = sp.slot;
            GL_ASSERT(i < n, "spring slot in range");
            const Real c = std::cos(s.angle[i]), sn = std::sin(s.angle[i]);
            const Vec2 arm{c * sp.attach.x - sn * sp.attach.y, sn * sp.attach.x + c * sp.attach.y};
            const Vec2 f = (sp.freeEnd(body.time) - (Vec2{s.x[i], s.y[i]} + arm)) * sp.stiffness;
            s.fx[i] += f.x;
            s.fy[i] += f.y;
            s.torque[i] += cross(arm, f);
        }
    stats = ForceStats{};
    if (log) log->records.clear();
    for (auto& w : wallForce) w = Vec2{};
    if (trialHistory) {  // every evaluation of a step starts from the accepted history
        for (auto* l : {&list.pairs, &list.wallPairs}) {
            std::copy(l->xi.begin(), l->xi.end(), l->xiTrial.begin());
            std::copy(l->zeta.begin(), l->zeta.end(), l->zetaTrial.begin());
            std::copy(l->areaOld.begin(), l->areaOld.end(), l->areaOldTrial.begin());
        }
    }
    shapes.update(s);
    if (body.particleContacts)
        detail::forEachBucket(
            list.pairs, laws, [&](auto* nT, auto* dT, auto* tT, std::uint32_t b, std::uint32_t e) {
                using N = std::remove_pointer_t<decltype(nT)>;
                using D = std::remove_pointer_t<decltype(dT)>;
                using T = std::remove_pointer_t<decltype(tT)>;
                if constexpr (kAreaForm<N, D, T>) {
                    detail::areaPairs<N, D, T>(s, list.pairs, b, e, laws, drift, dt, trialHistory, stats,
                                               shapes, log);
                } else if constexpr (kDepthForm<N, D, T>) {
                    if (laws.hasRolling())
                        detail::diskPairs<N, D, T, true>(s, list.pairs, b, e, laws, drift, dt,
                                                         body.overlapGuard, trialHistory, stats, log);
                    else
                        detail::diskPairs<N, D, T, false>(s, list.pairs, b, e, laws, drift, dt,
                                                          body.overlapGuard, trialHistory, stats, log);
                }
            });
    if (body.wallContacts)
        detail::forEachBucket(
            list.wallPairs, laws, [&](auto* nT, auto* dT, auto* tT, std::uint32_t b, std::uint32_t e) {
                using N = std::remove_pointer_t<decltype(nT)>;
                using D = std::remove_pointer_t<decltype(dT)>;
                using T = std::remove_pointer_t<decltype(tT)>;
                if constexpr (kAreaForm<N, D, T>)
                    detail::areaWalls<N, D, T>(s, walls, list.wallPairs, b, e, laws, drift, dt, trialHistory,
                                               stats, wallForce, shapes, log);
                else if constexpr (kDepthForm<N, D, T>)
                    detail::diskWalls<N, D, T>(s, walls, list.wallPairs, b, e, laws, drift, dt, trialHistory,
                                               stats, wallForce, log);
            });
}

}  // namespace granulab::dem
