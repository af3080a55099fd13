// SPDX-License-Identifier: MIT
// Struct-of-arrays particle state indexed by slot, with stable ids (DESIGN.md "Particle state").
// Hot columns only; everything a step touches lives here, one std::vector per quantity.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "model/shape_pool.hpp"

namespace granulab::model {


struct ParticleStore {
    std::vector<Real> x, y;        ///< [m] centre of mass
    std::vector<Real> vx, vy;      ///< [m/s]
    std::vector<Real> angle;       ///< [rad] counter-clockwise
    std::vector<Real> omega;       ///< [rad/s]
    std::vector<Real> fx, fy;      ///< [N] total force of the last force evaluation
    std::vector<Real> torque;      ///< [N m]
    std::vector<Real> radius;      ///< [m] disk radius / polygon circumradius (bounding circle)
    std::vector<Real> mass;        ///< [kg]
    std::vector<Real> invMass;     ///< [1/kg]
    std::vector<Real> invInertia;  ///< [1/(kg m^2)]
    std::vector<std::uint32_t> material;  ///< index into the material table
    std::vector<ParticleId> id;           ///< stable id
    std::vector<std::uint32_t> shape;     ///< index into the ShapePool, kDiskShape for disks

    std::size_t size() const noexcept { return x.size(); }

    void reserve(std::size_t n);
    /// Appends one particle; forces start at zero. Returns its slot.
    std::size_t add(ParticleId pid, Vec2 pos, Vec2 vel, Real angle0, Real omega0, Real r, Real m,
                    Real inertia, std::uint32_t mat, std::uint32_t shapeIndex = kDiskShape);
    /// Reorders all columns: new slot k holds old slot order[k].
    void permute(const std::vector<std::uint32_t>& order);

    /// Bytes held per particle by the columns above.
    static constexpr std::size_t kBytesPerParticle = 13 * sizeof(Real) + 2 * sizeof(std::uint32_t) +
                                                     sizeof(ParticleId);
};

}  // namespace granulab::model
