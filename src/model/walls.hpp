// SPDX-License-Identifier: MIT
// Walls (DESIGN.md "model/ walls"; gc2d spec sections 3.7 and 6.1-6.4, cfddem spec section 3.11):
// rigid bodies of infinite mass, either open or closed polylines of segments, or convex polygon
// bodies (one contact per grain, like gc2d's immovable particles). Every wall has a driver (fixed,
// constant velocity, vibration, piston, rotation about a pivot), an optional conveyor-belt surface
// velocity (tangential only), and a time until which it is solid (the lid of a closed outlet).
// Wall positions are state: the displacement and rotation are advanced by the driver and saved in
// checkpoints, so a resumed run continues from where the walls are.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace granulab::model {

struct WallSegment {
    Vec2 a, b;           ///< [m] end points, current position
    Vec2 a0, b0;         ///< [m] end points in the wall's reference placement (displacement 0, angle 0)
    std::uint32_t wall;  ///< index of the wall it belongs to
    std::uint32_t material;
    bool startShared = false;  ///< a is also the end b of the previous segment of the wall
    bool endShared = false;    ///< b is also the start a of the next segment
    Vec2 prevDirection;        ///< unit direction of the previous segment (valid if startShared)
    Vec2 prevDirection0;       ///< the same in the reference placement
};

/// Vibration profiles of gc2d App. B.1.5.2 (spec 6.4), displacement A(t) along a direction.
enum class VibrationType { Cosine, Sawtooth, Tapping, Triangle };

/// Prescribed or controlled motion of a wall.
struct WallDriver {
    enum class Kind { Fixed, Velocity, Vibration, Piston, Rotation };
    Kind kind = Kind::Fixed;
    Vec2 velocity;  ///< [m/s] Velocity: rigid translation
    // Vibration (gc2d 6.4): A(t_c) along `direction`, t_c = clamp(t, from, to).
    VibrationType vibration = VibrationType::Cosine;
    Vec2 direction{0, 1};  ///< unit; vibration and piston
    Real width = 0;        ///< [m] W
    Real frequency = 0;    ///< [1/s] f
    Real from = 0;         ///< [s] start of the vibration window / piston start
    Real to = 1e300;       ///< [s] end of the vibration window
    // Piston (gc2d 6.3): v = clamp(gain (F_target - F), -vMax, vMax) along `direction`, F the
    // contact force the grains exert against the motion.
    Real targetForce = 0;  ///< [N] (per unit depth in 2D)
    Real maxSpeed = 1;     ///< [m/s]
    Real gain = 0;         ///< [m/(N s)]
    // Rotation: the wall turns about `pivot` with angular velocity omega (counter-clockwise).
    Vec2 pivot;      ///< [m]
    Real omega = 0;  ///< [rad/s]
};

struct Wall {
    std::string name;
    std::uint32_t firstSegment = 0, segmentCount = 0;
    bool body = false;  ///< convex polygon body: its segments are the polygon's edges, counter-clockwise
    std::uint32_t material = 0;
    Vec2 surfaceVelocity;     ///< [m/s] conveyor belt: only its tangential part acts, the wall does not move
    Real solidUntil = 1e300;  ///< [s] the wall exists for t < solidUntil (an outlet's lid)
    WallDriver driver;
    // State (advanced by WallSet::advance, saved by save()):
    Vec2 displacement;  ///< [m] translation of the reference placement
    Real rotation = 0;  ///< [rad] rotation about driver.pivot (Rotation driver)
    Vec2 velocity;      ///< [m/s] current translational velocity
    Real omega = 0;     ///< [rad/s] current angular velocity
    bool solid = true;  ///< false once t >= solidUntil
    // Anchor of the analytic motion: displacement(t) = anchorDisplacement + motion since anchorTime.
    Vec2 anchorDisplacement;
    Real anchorRotation = 0;
    Real anchorTime = 0;
    Real pistonSpeed = 0;  ///< [m/s] piston speed along the direction (state of the controller)
};

struct WallSet {
    std::vector<Wall> walls;
    std::vector<WallSegment> segments;
    /// [m] current start corner of every segment (segments[k].a), so that a body's corners are
    /// contiguous: wall w's polygon is corners[firstSegment ... firstSegment + segmentCount).
    std::vector<Vec2> corners;
    std::vector<Real> bodyInradius;   ///< [m] per wall: largest circle about the centroid inside (bodies)
    std::vector<Vec2> bodyCentroid;   ///< [m] per wall: current centroid (bodies)
    std::vector<Vec2> bodyCentroid0;  ///< [m] per wall: centroid in the reference placement

    /// Adds a polyline wall; `closed` joins the last corner to the first.
    void addPolyline(const std::string& name, const std::vector<Vec2>& points, bool closed,
                     std::uint32_t material, Vec2 velocity);
    /// Adds a convex polygon body (corners counter-clockwise, checked by the caller).
    void addPolygon(const std::string& name, const std::vector<Vec2>& ccwCorners, std::uint32_t material);
    /// Sets the driver of the last wall added (and recomputes the speed bound).
    void setDriver(std::uint32_t wall, const WallDriver& driver);

    /// Places every wall at time t [s] after a step of dt [s]: analytic drivers from their
    /// anchor, the piston from its controller with `force[w]` = contact force [N] the grains
    /// exerted on wall w at the last evaluation (may be empty at set-up: no piston motion).
    void advance(Real t, Real dt, const std::vector<Vec2>& force) noexcept;
    /// Places the walls at time t without moving a piston (set-up and resume).
    void place(Real t) noexcept { advance(t, 0, {}); }
    /// Velocity [m/s] of the material point p of wall w (translation and rotation).
    Vec2 velocityAt(std::uint32_t w, Vec2 p) const noexcept {
        const Wall& wall = walls[w];
        return wall.velocity + perp(p - (wall.driver.pivot + wall.displacement)) * wall.omega;
    }
    /// Upper bound of any wall point's speed [m/s] over the whole run (kept by setDriver).
    Real maxSpeed() const noexcept { return m_maxSpeed; }
    /// Upper bound of any wall point's speed [m/s] during [t0, t1]: a vibrating wall outside its
    /// window, or a piston before it starts, rests (neighbour-list and tunnelling checks).
    Real maxSpeedBetween(Real t0, Real t1) const noexcept {
        Real v = 0;
        for (const std::uint32_t w : m_moving)
            if (t1 > m_activeFrom[w] && t0 < m_activeTo[w]) v = v > m_speedBound[w] ? v : m_speedBound[w];
        return v;
    }
    bool anyMoving() const noexcept { return !m_moving.empty(); }

    /// Saves the wall state (displacement, rotation, velocities, anchors, piston speed) and the
    /// drivers they were computed with; load() re-anchors a wall whose driver changed since (a
    /// scene edited between checkpoint and resume), so the wall continues from where it was.
    void save(std::ostream& os) const;
    void load(std::istream& is, Real time);

private:
    void placeWall(Wall& w) noexcept;
    std::vector<std::uint32_t> m_moving;         ///< walls with a driver other than Fixed, or a lid
    Real m_maxSpeed = 0;                         ///< [m/s]
    std::vector<Real> m_speedBound;              ///< [m/s] per wall
    std::vector<Real> m_activeFrom, m_activeTo;  ///< [s] per wall: when it may move
};

/// Displacement A(t) [m] and velocity dA/dt [m/s] of a vibration profile (gc2d Eq. B.3, spec 6.4,
/// TRIANGLE erratum fixed), t clamped to [from, to].
struct VibrationState {
    Real displacement = 0, velocity = 0;
};
VibrationState vibrationAt(const WallDriver& d, Real t) noexcept;
/// Largest |dA/dt| [m/s] of a profile.
Real vibrationMaxSpeed(const WallDriver& d) noexcept;

}  // namespace granulab::model
