// SPDX-License-Identifier: MIT
// WallSet: polylines and convex bodies to segments; the wall drivers (gc2d spec 6.1-6.4) and the
// checkpointed wall state.
#include "model/walls.hpp"

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>
#include <stdexcept>

#include "core/binary_io.hpp"
#include "geom/polygon.hpp"

namespace granulab::model {

namespace {

Real fraction(Real x) noexcept {
    return x - std::floor(x);
}

/// The driver's parameters as numbers, to tell whether a resumed scene changed a wall's motion.
std::vector<Real> driverKey(const WallDriver& d) {
    return {static_cast<Real>(d.kind),
            d.velocity.x,
            d.velocity.y,
            static_cast<Real>(d.vibration),
            d.direction.x,
            d.direction.y,
            d.width,
            d.frequency,
            d.from,
            d.to,
            d.targetForce,
            d.maxSpeed,
            d.gain,
            d.pivot.x,
            d.pivot.y,
            d.omega};
}

}  // namespace

VibrationState vibrationAt(const WallDriver& d, Real t) noexcept {
    VibrationState out;
    const bool inside = t > d.from && t < d.to;
    const Real tc = std::clamp(t, d.from, d.to);  // gc2d Eq. B.3 with the clamped time [audit]
    const Real W = d.width, f = d.frequency;
    const Real phase = 2 * kPi * f * tc;
    switch (d.vibration) {
        case VibrationType::Cosine:  // A = W (1 - cos 2 pi f t) / 2
            out.displacement = 0.5 * W * (1 - std::cos(phase));
            out.velocity = kPi * f * W * std::sin(phase);
            break;
        case VibrationType::Sawtooth:  // A = W frac(t f)
            out.displacement = W * fraction(tc * f);
            out.velocity = W * f;
            break;
        case VibrationType::Tapping: {  // A = W sin^30(2 pi f t)
            const Real s = std::sin(phase), c = std::cos(phase);
            const Real s29 = std::pow(s, 29);
            out.displacement = W * s29 * s;
            out.velocity = W * 30 * s29 * c * 2 * kPi * f;
            break;
        }
        case VibrationType::Triangle: {  // u = frac(t f); A = 2 W u or 2 W (1 - u) (erratum fixed)
            const Real u = fraction(tc * f);
            out.displacement = u < 0.5 ? 2 * W * u : 2 * W * (1 - u);
            out.velocity = u < 0.5 ? 2 * W * f : -2 * W * f;
            break;
        }
    }
    if (!inside) out.velocity = 0;  // the wall rests outside the window
    return out;
}

Real vibrationMaxSpeed(const WallDriver& d) noexcept {
    const Real W = std::abs(d.width), f = std::abs(d.frequency);
    switch (d.vibration) {
        case VibrationType::Cosine:
            return kPi * f * W;
        case VibrationType::Sawtooth:
            return W * f;             // plus the reset jump of W, which is a teleport (gc2d's behaviour)
        case VibrationType::Tapping:  // max of 60 pi f W sin^29 cos at tan^2 = 29
            return 60 * kPi * f * W * std::pow(29.0 / 30.0, 14.5) / std::sqrt(30.0);
        case VibrationType::Triangle:
            return 2 * W * f;
    }
    return 0;
}

void WallSet::addPolyline(const std::string& name, const std::vector<Vec2>& points, bool closed,
                          std::uint32_t material, Vec2 velocity) {
    Wall wall;
    wall.name = name;
    wall.material = material;
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
            s.prevDirection0 = s.prevDirection;
        }
        segments.push_back(s);
        corners.push_back(s.a);
    }
    wall.segmentCount = static_cast<std::uint32_t>(segCount);
    walls.push_back(wall);
    bodyInradius.push_back(0);
    bodyCentroid.push_back({});
    bodyCentroid0.push_back({});
    WallDriver d;
    if (velocity.x != 0 || velocity.y != 0) {
        d.kind = WallDriver::Kind::Velocity;
        d.velocity = velocity;
    }
    setDriver(static_cast<std::uint32_t>(walls.size() - 1), d);
}

void WallSet::addPolygon(const std::string& name, const std::vector<Vec2>& ccwCorners,
                         std::uint32_t material) {
    addPolyline(name, ccwCorners, true, material, {});
    Wall& w = walls.back();
    w.body = true;
    // Centroid and inradius about it (gc2d: an immovable particle; the closest-feature code needs both).
    const Vec2 c = geom::polygonMass(ccwCorners).centroid;
    const Real inradius = geom::inradiusAbout(ccwCorners, c);
    bodyCentroid.back() = c;
    bodyCentroid0.back() = c;
    bodyInradius.back() = std::max<Real>(inradius, 0);
}

void WallSet::setDriver(std::uint32_t index, const WallDriver& driver) {
    Wall& w = walls[index];
    w.driver = driver;
    m_moving.erase(std::remove(m_moving.begin(), m_moving.end(), index), m_moving.end());
    if (driver.kind != WallDriver::Kind::Fixed || w.solidUntil < 1e300) m_moving.push_back(index);
    std::sort(m_moving.begin(), m_moving.end());
    // Speed bound of every wall point: translation plus rotation about the pivot.
    m_maxSpeed = 0;
    m_speedBound.assign(walls.size(), 0);
    m_activeFrom.assign(walls.size(), 0);
    m_activeTo.assign(walls.size(), 1e300);
    for (std::size_t k = 0; k < walls.size(); ++k) {
        const auto& wall = walls[k];
        const auto& d = wall.driver;
        if (d.kind == WallDriver::Kind::Vibration) {
            m_activeFrom[k] = d.from;
            m_activeTo[k] = d.to;
        } else if (d.kind == WallDriver::Kind::Piston) {
            m_activeFrom[k] = d.from;
        }
        Real v = 0;
        switch (d.kind) {
            case WallDriver::Kind::Fixed:
                break;
            case WallDriver::Kind::Velocity:
                v = norm(d.velocity);
                break;
            case WallDriver::Kind::Vibration:
                v = vibrationMaxSpeed(d);
                break;
            case WallDriver::Kind::Piston:
                v = d.maxSpeed;
                break;
            case WallDriver::Kind::Rotation: {
                Real reach = 0;
                for (std::uint32_t k = 0; k < wall.segmentCount; ++k) {
                    const auto& s = segments[wall.firstSegment + k];
                    reach = std::max({reach, norm(s.a0 - d.pivot), norm(s.b0 - d.pivot)});
                }
                v = std::abs(d.omega) * reach;
                break;
            }
        }
        m_speedBound[k] = v;
        m_maxSpeed = std::max(m_maxSpeed, v);
    }
}

void WallSet::placeWall(Wall& w) noexcept {
    const bool rotating = w.driver.kind == WallDriver::Kind::Rotation;
    const Vec2 pivot = w.driver.pivot;
    const Real c = rotating ? std::cos(w.rotation) : 1, s = rotating ? std::sin(w.rotation) : 0;
    const auto place = [&](Vec2 p0) {
        if (!rotating) return p0 + w.displacement;
        const Vec2 r = p0 - pivot;
        return pivot + Vec2{c * r.x - s * r.y, s * r.x + c * r.y} + w.displacement;
    };
    for (std::uint32_t k = 0; k < w.segmentCount; ++k) {
        auto& seg = segments[w.firstSegment + k];
        seg.a = place(seg.a0);
        seg.b = place(seg.b0);
        corners[w.firstSegment + k] = seg.a;
        if (rotating && seg.startShared) {  // the previous segment's direction turns with the wall
            const Vec2 d0 = seg.prevDirection0;
            seg.prevDirection = {c * d0.x - s * d0.y, s * d0.x + c * d0.y};
        }
    }
    const auto index = static_cast<std::size_t>(&w - walls.data());
    if (w.body) bodyCentroid[index] = place(bodyCentroid0[index]);
}

void WallSet::advance(Real t, Real dt, const std::vector<Vec2>& force) noexcept {
    for (const std::uint32_t index : m_moving) {
        Wall& w = walls[index];
        const WallDriver& d = w.driver;
        w.solid = t < w.solidUntil;
        switch (d.kind) {
            case WallDriver::Kind::Fixed:
                continue;  // a lid only: nothing moves
            case WallDriver::Kind::Velocity:
                w.velocity = d.velocity;
                w.displacement = w.anchorDisplacement + d.velocity * (t - w.anchorTime);
                break;
            case WallDriver::Kind::Vibration: {
                const VibrationState v = vibrationAt(d, t);
                w.velocity = d.direction * v.velocity;
                w.displacement = w.anchorDisplacement + d.direction * v.displacement;
                break;
            }
            case WallDriver::Kind::Piston: {
                // gc2d 6.3, velocity controller: v = clamp(gain (F_target - F), -v_max, v_max), F the
                // force the grains exert against the direction of motion (docs/physics/walls.md).
                Real v = 0;
                if (t > d.from && dt > 0 && index < force.size()) {
                    const Real resisting = -dot(force[index], d.direction);
                    v = std::clamp(d.gain * (d.targetForce - resisting), -d.maxSpeed, d.maxSpeed);
                }
                w.pistonSpeed = v;
                w.velocity = d.direction * v;
                w.displacement += w.velocity * dt;
                break;
            }
            case WallDriver::Kind::Rotation:
                w.omega = d.omega;
                w.rotation = w.anchorRotation + d.omega * (t - w.anchorTime);
                break;
        }
        placeWall(w);
    }
}

void WallSet::save(std::ostream& os) const {
    writePod<std::uint64_t>(os, walls.size());
    for (const Wall& w : walls) {
        writeVector(os, driverKey(w.driver));
        for (const Real v :
             {w.displacement.x, w.displacement.y, w.rotation, w.velocity.x, w.velocity.y, w.omega,
              w.anchorDisplacement.x, w.anchorDisplacement.y, w.anchorRotation, w.anchorTime, w.pistonSpeed})
            writePod(os, v);
    }
}

void WallSet::load(std::istream& is, Real time) {
    if (readPod<std::uint64_t>(is) != walls.size())
        throw std::runtime_error("checkpoint corrupt or scene changed (wall count)");
    for (Wall& w : walls) {
        std::vector<Real> key;
        readVector(is, key);
        Real v[11];
        for (Real& x : v) x = readPod<Real>(is);
        for (const Real x : v)
            if (!std::isfinite(x))
                throw std::runtime_error("checkpoint corrupt (a wall position is not finite)");
        w.displacement = {v[0], v[1]};
        w.rotation = v[2];
        w.velocity = {v[3], v[4]};
        w.omega = v[5];
        w.pistonSpeed = v[10];
        if (key == driverKey(w.driver)) {  // same motion: the same anchors give a bit-for-bit resume
            w.anchorDisplacement = {v[6], v[7]};
            w.anchorRotation = v[8];
            w.anchorTime = v[9];
        } else {  // the scene changed the motion: continue from where the wall is, no jump
            w.anchorTime = time;
            w.anchorRotation = w.rotation;
            w.anchorDisplacement = w.displacement;
            if (w.driver.kind == WallDriver::Kind::Vibration)
                w.anchorDisplacement =
                    w.displacement - w.driver.direction * vibrationAt(w.driver, time).displacement;
        }
    }
    place(time);
}

}  // namespace granulab::model
