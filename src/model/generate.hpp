// SPDX-License-Identifier: MIT
// Expands explicit particles and generated blocks (lattices, random placement, size
// distributions, thermal velocities) into one list of initial particles, deterministically
// from the scene seed (core/rng.hpp).
#pragma once
#include <cstdint>
#include <vector>

#include "core/error.hpp"
#include "model/scene_def.hpp"
#include "model/shape_pool.hpp"

namespace granulab::model {

struct InitialParticle {
    Vec2 position, velocity;
    Real angle = 0, omega = 0;
    Real radius = 0;                      ///< [m] disk radius, or the polygon's circumradius
    std::uint32_t shape = kDiskShape;     ///< index into InitialParticles::shapes
    std::uint32_t material = 0;
    std::uint32_t origin = 0;  ///< index into InitialParticles::origins (where it was defined)
};

struct InitialParticles {
    std::vector<InitialParticle> particles;  ///< id = index
    std::vector<SourceLoc> origins;          ///< explicit particles and blocks, by origin index
    ShapePool shapes;                        ///< polygon shapes of the particles
};

/// Mass [kg] and moment of inertia [kg m^2] of a disk of radius r [m] and areal density rho.
inline Real diskMass(Real rho, Real r) noexcept { return rho * kPi * r * r; }
inline Real diskInertia(Real mass, Real r) noexcept { return 0.5 * mass * r * r; }

/// How a 2D particle of radius r gets its mass: a disk (coin) of areal density [kg/m^2], as in
/// gc2d and LAMMPS density/disc, or a sphere moving in the plane, density [kg/m^3], as in the
/// cfddem seed (spec section 2.1).
enum class MassModel { Disk, Sphere };
inline MassModel massModelOf(const std::string& name) noexcept {
    return name == "sphere" ? MassModel::Sphere : MassModel::Disk;
}
inline Real particleMass(MassModel model, Real rho, Real r) noexcept {
    return model == MassModel::Sphere ? rho * 4.0 / 3.0 * kPi * r * r * r : diskMass(rho, r);
}
inline Real particleInertia(MassModel model, Real mass, Real r) noexcept {
    return model == MassModel::Sphere ? 0.4 * mass * r * r : diskInertia(mass, r);
}

/// Smallest and largest radius a size distribution can produce [m].
Real minRadius(const SizeDistDef& d) noexcept;
Real maxRadius(const SizeDistDef& d) noexcept;

/// Generates all particles. `materialIndex` maps a material name to its index (-1 unknown).
/// Problems (a block that cannot place its particles) go to `diags`.
InitialParticles generateParticles(const SceneDef& scene,
                                   const std::vector<std::string>& materialNames,
                                   Diagnostics& diags);

}  // namespace granulab::model
