// SPDX-License-Identifier: MIT
// Shape pool: re-centring and the cached mass properties of each shape (gc2d spec section 2.2).
#include "model/shape_pool.hpp"

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>
#include <stdexcept>

#include "core/binary_io.hpp"
#include "geom/polygon.hpp"

namespace granulab::model {

std::uint32_t ShapePool::add(const std::vector<Vec2>& ccw) {
    const geom::PolygonMass m = geom::polygonMass(ccw);
    const auto k = size();
    start.push_back(static_cast<std::uint32_t>(corners.size()));
    count.push_back(static_cast<std::uint32_t>(ccw.size()));
    Real rOut = 0;
    for (const Vec2& p : ccw) {
        corners.push_back(p - m.centroid);
        rOut = std::max(rOut, norm(p - m.centroid));
    }
    // Inscribed radius about the centroid: distance to the nearest edge line (convex polygon).
    const Real rIn = std::min(rOut, geom::inradiusAbout(ccw, m.centroid));
    area.push_back(m.area);
    secondMoment.push_back(m.secondMoment);
    circumradius.push_back(rOut);
    inradius.push_back(std::max<Real>(rIn, 0));
    return k;
}

std::vector<Vec2> ShapePool::shapeCorners(std::uint32_t k) const {
    return {corners.begin() + start[k], corners.begin() + start[k] + count[k]};
}

void ShapePool::save(std::ostream& os) const {
    writeVector(os, corners);
    writeVector(os, start);
    writeVector(os, count);
    writeVector(os, area);
    writeVector(os, secondMoment);
    writeVector(os, circumradius);
    writeVector(os, inradius);
}

void ShapePool::load(std::istream& is) {
    ShapePool p;
    readVector(is, p.corners);
    readVector(is, p.start);
    readVector(is, p.count);
    readVector(is, p.area);
    readVector(is, p.secondMoment);
    readVector(is, p.circumradius);
    readVector(is, p.inradius);
    const std::size_t n = p.start.size();
    bool ok = p.count.size() == n && p.area.size() == n && p.secondMoment.size() == n &&
              p.circumradius.size() == n && p.inradius.size() == n;
    for (std::size_t k = 0; ok && k < n; ++k)
        ok = p.count[k] >= 3 && std::uint64_t{p.start[k]} + p.count[k] <= p.corners.size();
    if (!ok) throw std::runtime_error("checkpoint corrupt (shape pool)");
    *this = std::move(p);
}

}  // namespace granulab::model
