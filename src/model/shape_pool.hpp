// SPDX-License-Identifier: MIT
// Pool of convex polygon shapes, stored once in the body frame (gc2d spec sections 2.1-2.2):
// counter-clockwise corners relative to the centroid at angle 0. Particles refer to a shape by
// index; disks have no entry (kDiskShape). The particles of one named deterministic shape
// (polygon, regular, rectangle, ellipse) share one entry, random gc2d grains get one entry each.
// The pool never changes after set-up (model/generate.cpp fills it). Thermal size scaling s (spec
// section 2.4) is not implemented (s = 1); it would be a per-particle factor where the world
// corners are computed (dem::ShapeContext::update in dem/shape_context.cpp, gc2d Eq. 2.35).
#pragma once
#include <cstdint>
#include <iosfwd>
#include <vector>

#include "core/types.hpp"

namespace granulab::model {

inline constexpr std::uint32_t kDiskShape = 0xFFFFFFFFu;

struct ShapePool {
    std::vector<Vec2> corners;         ///< [m] body frame, centroid at the origin, counter-clockwise
    std::vector<std::uint32_t> start;  ///< first corner of shape k in `corners`
    std::vector<std::uint32_t> count;  ///< corner count of shape k (>= 3)
    std::vector<Real> area;            ///< [m^2]
    std::vector<Real> secondMoment;    ///< [m^4] polar second moment of area about the centroid
    std::vector<Real> circumradius;    ///< [m] largest distance of a corner from the centroid
    std::vector<Real> inradius;        ///< [m] largest circle around the centroid inside the polygon

    std::uint32_t size() const noexcept { return static_cast<std::uint32_t>(start.size()); }
    /// Adds a strictly convex counter-clockwise polygon given in any frame (checked by the
    /// caller with geom::checkConvexPolygon); it is shifted so that its centroid is at the
    /// origin. Returns the shape index.
    std::uint32_t add(const std::vector<Vec2>& ccwCorners);
    /// Corners of shape k in the body frame.
    std::vector<Vec2> shapeCorners(std::uint32_t k) const;
    /// Checkpoint of the pool (sources add grains during a run); load() checks consistency.
    void save(std::ostream& os) const;
    void load(std::istream& is);
    std::size_t memoryBytes() const noexcept {
        return corners.capacity() * sizeof(Vec2) + (start.capacity() + count.capacity()) * 4 +
               (area.capacity() + secondMoment.capacity() + circumradius.capacity() + inradius.capacity()) *
                   sizeof(Real);
    }
};

}  // namespace granulab::model
