// SPDX-License-Identifier: MIT
// WallSet: polyline to segments, prescribed motion.
#include "model/walls.hpp"

#include <algorithm>
#include <cmath>

namespace granulab::model {

void WallSet::addPolyline(const std::string& name, const std::vector<Vec2>& points, bool closed,
                          std::uint32_t material, Vec2 velocity) {
    Wall wall;
    wall.name = name;
    wall.velocity = velocity;
    wall.firstSegment = static_cast<std::uint32_t>(segments.size());
    const std::size_t n = points.size();
    const std::size_t segCount = closed ? n : n - 1;
    for (std::size_t k = 0; k < segCount; ++k) {
        WallSegment s;
        s.a = points[k];
        s.b = points[(k + 1) % n];
        s.a0 = s.a;
        s.b0 = s.b;
        s.wall = static_cast<std::uint32_t>(walls.size());
        s.material = material;
        s.startShared = closed || k > 0;
        s.endShared = closed || k + 1 < segCount;
        if (s.startShared) {
            const Vec2 pa = points[(k + n - 1) % n];
            const Vec2 d = s.a - pa;
            s.prevDirection = d / norm(d);
        }
        segments.push_back(s);
    }
    wall.segmentCount = static_cast<std::uint32_t>(segCount);
    if (velocity.x != 0 || velocity.y != 0) {
        m_moving.push_back(static_cast<std::uint32_t>(walls.size()));
        m_maxSpeed = std::max(m_maxSpeed, norm(velocity));
    }
    walls.push_back(wall);
}

void WallSet::setTime(Real t) noexcept {
    for (const std::uint32_t index : m_moving) {
        const Wall& w = walls[index];
        const Vec2 d = w.velocity * t;
        for (std::uint32_t k = 0; k < w.segmentCount; ++k) {
            auto& s = segments[w.firstSegment + k];
            s.a = s.a0 + d;
            s.b = s.b0 + d;
        }
    }
}

}  // namespace granulab::model
