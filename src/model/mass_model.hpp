// SPDX-License-Identifier: MIT
// How a 2D particle gets its mass and moment of inertia (gc2d spec section 2.1, cfddem spec
// section 2.1): a disk (coin) of areal density, a sphere moving in the plane, or a polygon of
// areal density. The one place of the particle mass formula.
#pragma once
#include <string>

#include "core/types.hpp"

namespace granulab::model {

/// Mass [kg] and moment of inertia [kg m^2] of a disk of radius r [m] and areal density rho.
inline Real diskMass(Real rho, Real r) noexcept {
    return rho * kPi * r * r;
}
inline Real diskInertia(Real mass, Real r) noexcept {
    return 0.5 * mass * r * r;
}

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

/// Mass [kg] of a round particle of radius r [m] (polygonArea < 0) or of a polygon of area
/// polygonArea [m^2] (areal density rho [kg/m^2]; polygons are always areal, gc2d).
inline Real grainMass(MassModel model, Real rho, Real r, Real polygonArea) noexcept {
    return polygonArea >= 0 ? rho * polygonArea : particleMass(model, rho, r);
}

}  // namespace granulab::model
