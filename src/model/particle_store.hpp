// SPDX-License-Identifier: MIT
// Struct-of-arrays particle state indexed by slot, with stable ids (DESIGN.md "Particle state").
// Hot columns only; everything a step touches lives here, one std::vector per quantity.
#pragma once
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <type_traits>
#include <vector>

#include "core/types.hpp"
#include "model/shape_pool.hpp"

namespace granulab::model {

struct ParticleStore {
    std::vector<Real> x, y;               ///< [m] centre of mass
    std::vector<Real> vx, vy;             ///< [m/s]
    std::vector<Real> angle;              ///< [rad] counter-clockwise
    std::vector<Real> omega;              ///< [rad/s]
    std::vector<Real> fx, fy;             ///< [N] total force of the last force evaluation
    std::vector<Real> torque;             ///< [N m]
    std::vector<Real> radius;             ///< [m] disk radius / polygon circumradius (bounding circle)
    std::vector<Real> mass;               ///< [kg]
    std::vector<Real> invMass;            ///< [1/kg]
    std::vector<Real> invInertia;         ///< [1/(kg m^2)]
    std::vector<std::uint32_t> material;  ///< index into the material table
    std::vector<ParticleId> id;           ///< stable id
    std::vector<std::uint32_t> shape;     ///< index into the ShapePool, kDiskShape for disks

    /// Calls fn(column) for every column above, in declaration order (also the checkpoint order).
    /// The one list of the columns: reserve, permute, save, load and kBytesPerParticle go through
    /// it, so a new column is declared above, listed in visitColumns and filled in add().
    template <class Fn>
    constexpr void forEachColumn(Fn&& fn) {
        visitColumns(*this, fn);
    }
    template <class Fn>
    constexpr void forEachColumn(Fn&& fn) const {
        visitColumns(*this, fn);
    }

    std::size_t size() const noexcept { return x.size(); }
    /// True if every column has size() entries (an invariant outside add()).
    bool consistent() const noexcept;

    void reserve(std::size_t n);
    /// Appends one particle; forces start at zero. Returns its slot.
    std::size_t add(ParticleId pid, Vec2 pos, Vec2 vel, Real angle0, Real omega0, Real r, Real m,
                    Real inertia, std::uint32_t mat, std::uint32_t shapeIndex = kDiskShape);
    /// Reorders all columns: new slot k holds old slot order[k] (order is a permutation of the slots).
    void permute(const std::vector<std::uint32_t>& order);
    /// Removes every particle whose slot is not in `slots` (ascending); the kept ones keep their
    /// relative order (new slot k holds old slot slots[k]).
    void keep(const std::vector<std::uint32_t>& slots);

    /// Writes every column (size, then raw values; core/binary_io.hpp) in column order: the particle
    /// part of a DEM checkpoint.
    void save(std::ostream& os) const;
    /// Reads what save() wrote; throws std::runtime_error on a truncated or inconsistent stream.
    void load(std::istream& is);

    /// Bytes held per particle by the columns above (the sum of their element sizes).
    static const std::size_t kBytesPerParticle;

private:
    template <class Self, class Fn>
    static constexpr void visitColumns(Self& s, Fn& fn) {
        fn(s.x);
        fn(s.y);
        fn(s.vx);
        fn(s.vy);
        fn(s.angle);
        fn(s.omega);
        fn(s.fx);
        fn(s.fy);
        fn(s.torque);
        fn(s.radius);
        fn(s.mass);
        fn(s.invMass);
        fn(s.invInertia);
        fn(s.material);
        fn(s.id);
        fn(s.shape);
    }
    static constexpr std::size_t columnBytes() {
        std::size_t bytes = 0;
        const ParticleStore empty;
        empty.forEachColumn(
            [&](const auto& col) { bytes += sizeof(typename std::decay_t<decltype(col)>::value_type); });
        return bytes;
    }
};

inline constexpr std::size_t ParticleStore::kBytesPerParticle = ParticleStore::columnBytes();

}  // namespace granulab::model
