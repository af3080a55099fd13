// SPDX-License-Identifier: MIT
// Wall segments (DESIGN.md "model/ walls"): every wall polyline is stored as segments that know
// whether their end points are shared with a neighbour, so that a disk touching a convex joint
// gets exactly one contact (see geom/segment.hpp, diskSegmentContact).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace granulab::model {

struct WallSegment {
    Vec2 a, b;           ///< [m] end points, current position
    Vec2 a0, b0;         ///< [m] end points at t = 0
    std::uint32_t wall;  ///< index of the wall (polyline) it belongs to
    std::uint32_t material;
    bool startShared = false;  ///< a is also the end b of the previous segment of the wall
    bool endShared = false;    ///< b is also the start a of the next segment
    Vec2 prevDirection;        ///< unit direction of the previous segment (valid if startShared)
};

struct Wall {
    std::string name;
    std::uint32_t firstSegment = 0, segmentCount = 0;
    Vec2 velocity;  ///< [m/s] prescribed rigid translation
};

struct WallSet {
    std::vector<Wall> walls;
    std::vector<WallSegment> segments;

    /// Adds a polyline wall; `closed` joins the last corner to the first.
    void addPolyline(const std::string& name, const std::vector<Vec2>& points, bool closed,
                     std::uint32_t material, Vec2 velocity);
    /// Places every wall at its prescribed position for time t [s] (x = x0 + v t, no drift).
    void setTime(Real t) noexcept;
    /// Largest speed [m/s] of any wall (kept by addPolyline: constant during a run).
    Real maxSpeed() const noexcept { return m_maxSpeed; }

private:
    std::vector<std::uint32_t> m_moving;  ///< walls with a non-zero velocity (setTime moves only these)
    Real m_maxSpeed = 0;                  ///< [m/s]
};

}  // namespace granulab::model
