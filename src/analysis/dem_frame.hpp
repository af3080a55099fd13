// SPDX-License-Identifier: MIT
// One DEM snapshot as the pile analyses read it (gc2d spec section 7, "available raw data"): the
// grains (positions, velocities, shapes as world corners), the contacts with their forces and
// the wall segments. Pure data, filled by io's snapshot readers (io/vtk_reader.hpp,
// io/contact_file.hpp) or by a test. Gravity is not a contact: body forces are kept apart
// (spec 7 item 7, "ID2 = -1 lines are excluded").
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace granulab::analysis {

/// The grains of one snapshot, in file order: disks first, then polygons (io/vtk_writer.hpp).
struct GrainFrame {
    double time = 0;                     ///< [s]
    std::vector<std::int64_t> id;        ///< global particle id (creation order)
    std::vector<double> x, y;            ///< [m] centre of mass
    std::vector<double> vx, vy;          ///< [m/s]
    std::vector<double> omega;           ///< [rad/s] counter-clockwise
    std::vector<double> angle;           ///< [rad] counter-clockwise
    bool hasAngle = true;                ///< false: smooth spheres (no angle array, angle read as 0)
    std::vector<double> radius;          ///< [m] disk radius; polygons: circumradius about the centre
    std::vector<double> speed;           ///< [m/s]
    std::vector<double> mass;            ///< [kg] (2D: areal density x area)
    std::vector<std::int32_t> material;  ///< material index of the scene
    /// Polygon outlines: the world corners (counter-clockwise) of grain i are
    /// corners[cornerStart[i] .. cornerStart[i + 1]); an empty range is a disk. size() + 1 entries.
    std::vector<std::size_t> cornerStart{0};
    std::vector<Vec2> corners;  ///< [m]

    std::size_t size() const noexcept { return x.size(); }
    std::size_t cornerCount(std::size_t i) const noexcept { return cornerStart[i + 1] - cornerStart[i]; }
    bool isPolygon(std::size_t i) const noexcept { return cornerCount(i) > 0; }
    /// Area of grain i [m^2]: the polygon's shoelace area or pi r^2.
    double area(std::size_t i) const noexcept;
};

/// The contacts of one snapshot: the forces of the last force evaluation of the step that ended
/// at `time`. Body b is a grain (b >= 0, wall = -1) or a wall segment of wall `wall` (b = -1).
/// Sign conventions: n points from a toward b; (fx, fy) is the force ON a, b gets the opposite,
/// both applied at the contact point; fn = -F.n > 0 for a repulsive contact, ft = F.t with
/// t = perp(n) = (-ny, nx).
struct ContactFrame {
    double time = 0;                 ///< [s]
    std::vector<std::int64_t> a, b;  ///< particle ids (b = -1 at a wall)
    std::vector<std::int32_t> wall;  ///< wall index of the scene, -1 for grain pairs
    std::vector<double> px, py;      ///< [m] contact point (area law: middle of the contact line)
    std::vector<double> nx, ny;      ///< unit normal from a toward b
    std::vector<double> fx, fy;      ///< [N] force on a (2D: per metre of depth is the
                                     ///< same number, the thesis' N/m convention)
    std::vector<double> fn, ft;      ///< [N] normal (repulsive > 0) and tangential components
    std::vector<double> depth;       ///< [m] overlap depth (area law: A / l, Eq. 2.15)
    std::vector<double> area;        ///< [m^2] overlap area (disks: the lens or circle segment)
    std::vector<double> length;      ///< [m] length of the contact line (chord of the overlap)

    std::size_t size() const noexcept { return a.size(); }
    bool atWall(std::size_t k) const noexcept { return wall[k] >= 0; }
};

/// The wall segments of one snapshot.
struct WallSegments {
    std::vector<Vec2> a, b;          ///< [m] end points
    std::vector<std::int32_t> wall;  ///< wall index of each segment (the scene's [[wall]] order)
    std::size_t size() const noexcept { return a.size(); }
};

}  // namespace granulab::analysis
