// SPDX-License-Identifier: MIT
// Walls as bodies (gc2d spec 3.7, 6.1; docs/physics/walls.md): a grain on a convex wall corner has
// one contact whose force is the area law's closed form; a grain hitting a thin divider's corner
// leaves as it leaves an immovable polygon particle of the same shape; a conveyor belt drags a
// resting square to the belt speed; a disk in a belt-lined drum spins in place at omega = -v/r.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "../support.hpp"
#include "dem/forces_area.hpp"
#include "geom/circle_contact.hpp"
#include "geom/polygon.hpp"

namespace granulab {
namespace {

const char* kAreaLaw = R"(
[[material]]
name = "grain"
density = 1000.0
[[material]]
name = "wall"
density = 1000.0
[[contact]]
materials = ["grain", "*"]
normal = "area"
E = 1.0e5
)";

TEST(WallBodies, GrainOnAConvexCornerFeelsOneContactOfTheClosedForm) {
    // Disk of radius r centred at (1 + a, 1 + a) on the corner (1, 1) of the unit-square body.
    const Real r = 0.1, a = 0.05, E = 1e5;
    const std::string toml = std::string(R"(
[run]
end_time = 1.0
[dem]
dt = 1e-5
)") + kAreaLaw + R"(
[[particle]]
position = [1.05, 1.05]
radius = 0.1
material = "grain"
[[wall]]
points = [[0, 0], [1, 0], [1, 1], [0, 1]]
closed = true
kind = "polygon"
material = "wall"
)";
    // Start overlaps are refused by the set-up; build the touching state through a moving particle.
    const std::string start = std::string(toml);
    auto scene = test::readSceneText(start, "test.toml", {});
    scene.particles[0].position = {1.2, 1.2};  // clear of the corner at set-up
    dem::PreparedScene prepared = app::checkAndPrepareDem(scene);
    prepared.initial.particles[0].position = {1 + a, 1 + a};
    dem::World w = dem::makeWorld(scene, prepared.initial);
    w.initialize();
    EXPECT_EQ(w.forceStats().wallContacts, 1u);
    // Closed form: lens A = disk n {x < 1, y < 1}, chord from (1, 1 + a - h) to (1 + a - h, 1).
    const Real h = std::sqrt(r * r - a * a);
    Real A = 0;
    const int n = 200000;
    const Real x0 = 1 + a - r, dx = (1 - x0) / n;
    for (int k = 0; k < n; ++k) {  // midpoint rule over x in [x0, 1]
        const Real x = x0 + (k + 0.5) * dx;
        const Real half = std::sqrt(std::max<Real>(0, r * r - (x - 1 - a) * (x - 1 - a)));
        const Real lo = 1 + a - half, hi = std::min<Real>(1, 1 + a + half);
        A += std::max<Real>(0, hi - lo) * dx;
    }
    const Vec2 s{1 + 0.5 * (a - h), 1 + 0.5 * (a - h)};  // chord midpoint
    const Real ri = norm(s - Vec2{1 + a, 1 + a}), rj = norm(s - Vec2{0.5, 0.5});
    const Real F = E * A * (ri + rj) / (ri * rj);  // gc2d Eq. 2.20, l from both arms (spec 3.7)
    const auto& st = w.store();
    EXPECT_NEAR(st.fx[0], F / std::sqrt(2.0), 2e-4 * F);
    EXPECT_NEAR(st.fy[0], F / std::sqrt(2.0), 2e-4 * F);
    EXPECT_NEAR(st.torque[0], 0.0, 1e-9 * F * r);
}

// A polyline wall stands for the plates of thickness 2 r behind its segments (spec 3.7). At a
// convex corner the two plates used to overlap behind it, and a grain pressing on the corner had
// its overlap counted twice (issue 34). Mitred along the corner's bisector, the plates cover the
// solid once: the overlap areas of the two plate contacts add up to the grain's overlap with the
// body that the polyline outlines, for a disk and for a square. A plate never reaches past its
// segment's end into space that is free on the grain's side: at a concave corner (a grain in a
// box's corner, or beside a face whose other side's plate it meets) the ends stay square.
TEST(WallBodies, PolylineCornerCountsTheOverlapOnce) {
    // The unit square drawn counter-clockwise; the corner (1, 1) is convex seen from outside
    // (grains at x, y > 1) and the corner of the box seen from inside (grains at x, y < 1).
    const std::vector<Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const Vec2 up{0, 1}, left{-1, 0};  // from (1, 1) along the two segments that meet there
    const Real r = 0.1;
    const auto plates = [&](Vec2 centre) {  // the right side and the top, mitred at (1, 1)
        dem::area::WallQuad right, top;
        dem::area::wallQuad({1, 0}, {1, 1}, centre, 2 * r, right, {}, left);
        dem::area::wallQuad({1, 1}, {0, 1}, centre, 2 * r, top, -up, {});
        return std::pair{right, top};
    };
    for (const Real a : {0.02, 0.04, 0.06}) {  // the disk reaches the corner: a sqrt(2) < r
        // Outside, on the convex corner: the disk's lens inside the square, counted once.
        const Vec2 c{1 + a, 1 + a};
        const auto [right, top] = plates(c);
        const Real plated = geom::circlePolygonContact(c, r, right.world, 4).area +
                            geom::circlePolygonContact(c, r, top.world, 4).area;
        const Real body = geom::circlePolygonContact(c, r, square.data(), 4).area;
        ASSERT_GT(body, 0);
        EXPECT_NEAR(plated, body, 1e-12) << "disk at the convex corner, a = " << a;
        {  // square ends, as before issue 34: both plates hold the whole lens
            dem::area::WallQuad rightSquare, topSquare;
            dem::area::wallQuad({1, 0}, {1, 1}, c, 2 * r, rightSquare);
            dem::area::wallQuad({1, 1}, {0, 1}, c, 2 * r, topSquare);
            EXPECT_NEAR(geom::circlePolygonContact(c, r, rightSquare.world, 4).area +
                            geom::circlePolygonContact(c, r, topSquare.world, 4).area,
                        2 * body, 1e-12);
        }
        // A square grain of half side 1.2 r, turned by 0.3 rad, on the same corner.
        std::vector<Vec2> grain;
        for (int k = 0; k < 4; ++k) {
            const Real phi = 0.3 + k * std::numbers::pi / 2;
            grain.push_back(c + Vec2{std::cos(phi), std::sin(phi)} * (r * std::sqrt(2.0)) * 1.2);
        }
        const std::vector<Vec2> qr(right.world, right.world + 4), qt(top.world, top.world + 4);
        const Real plated2 = geom::convexOverlap(grain, qr).area + geom::convexOverlap(grain, qt).area;
        const Real body2 = geom::convexOverlap(grain, square).area;
        ASSERT_GT(body2, 0);
        EXPECT_NEAR(plated2, body2, 1e-12) << "square at the convex corner, a = " << a;
        // Inside the box, in its corner (concave): both plates keep square ends. Outside beside
        // the right face just below the corner: the top's plate lies above y = 1 (a polyline is
        // solid on both sides), where the corner is concave, and keeps its square end instead of
        // leaning over the free space at x > 1; the right face's plate is mitred (convex there).
        const auto squareEnds = [&](Vec2 at, Vec2 a0, Vec2 b0, const dem::area::WallQuad& q) {
            dem::area::WallQuad square;
            dem::area::wallQuad(a0, b0, at, 2 * r, square);
            for (int k = 0; k < 4; ++k) {
                EXPECT_EQ(q.world[k].x, square.world[k].x) << "corner " << k;
                EXPECT_EQ(q.world[k].y, square.world[k].y) << "corner " << k;
            }
        };
        const Vec2 inBox{1 - a, 1 - a}, beside{1 + a, 1 - 2 * a};
        const auto [rightIn, topIn] = plates(inBox);
        squareEnds(inBox, {1, 0}, {1, 1}, rightIn);
        squareEnds(inBox, {1, 1}, {0, 1}, topIn);
        const auto [rightBeside, topBeside] = plates(beside);
        squareEnds(beside, {1, 1}, {0, 1}, topBeside);
        EXPECT_NEAR(rightBeside.world[1].x, 1 - 2 * r, 1e-15);  // the mitre's far corner (1 - 2r, 1 - 2r)
        EXPECT_NEAR(rightBeside.world[1].y, 1 - 2 * r, 1e-15);
    }
}

/// A disk shot at the top corner of a 1 mm divider: the divider as a wall body, and as an
/// immovable polygon particle (density 1e15) of the same shape. Returns the final velocity.
Vec2 shootAtDivider(bool asWall) {
    const std::string common = std::string(R"(
[run]
end_time = 0.02
[dem]
dt = 2e-6
integrator = "gear"
[[material]]
name = "grain"
density = 1000.0
[[material]]
name = "wall"
density = 1.0e15
[[contact]]
materials = ["*", "*"]
normal = "area"
E = 1.0e5
[[particle]]
position = [-0.004, 0.1012]
velocity = [0.5, 0.0]
radius = 0.002
material = "grain"
)");
    const std::string divider = asWall ? R"(
[[wall]]
points = [[-0.0005, 0.0], [0.0005, 0.0], [0.0005, 0.1], [-0.0005, 0.1]]
closed = true
kind = "polygon"
material = "wall"
)"
                                       : R"(
[[shape]]
name = "divider"
kind = "polygon"
corners = [[-0.0005, -0.05], [0.0005, -0.05], [0.0005, 0.05], [-0.0005, 0.05]]
[[particle]]
shape = "divider"
position = [0.0, 0.05]
material = "wall"
)";
    dem::World w = test::makeWorldFromToml(common + divider);
    for (int k = 0; k < 10000; ++k) w.step();
    return {w.store().vx[0], w.store().vy[0]};
}

TEST(WallBodies, DividerCornerBounceEqualsAnImmovablePolygonParticle) {
    const Vec2 wall = shootAtDivider(true);
    const Vec2 particle = shootAtDivider(false);
    RecordProperty("wall_vx", std::to_string(wall.x));
    RecordProperty("wall_vy", std::to_string(wall.y));
    // The grain was deflected upward by the corner (it did not meet a plate sticking out).
    EXPECT_GT(wall.y, 0.05);
    EXPECT_NEAR(wall.x, particle.x, 1e-6);
    EXPECT_NEAR(wall.y, particle.y, 1e-6);
}

const char* kFrictionLaw = R"(
[[material]]
name = "grain"
density = 1000.0
[[material]]
name = "belt"
[[contact]]
materials = ["grain", "*"]
normal = "area"
E = 1.0e5
damping = "gamma"
gamma = 0.5
tangential = "gc2d"
mu = 0.5
)";

TEST(WallBodies, ConveyorBeltDragsARestingSquareToTheBeltSpeed) {
    const std::string toml = std::string(R"(
[run]
end_time = 1.0
[dem]
dt = 1e-5
gravity = [0.0, -9.81]
)") + kFrictionLaw + R"(
[[shape]]
name = "square"
kind = "regular"
corner_count = 4
radius = 0.005
rotation = 0.7853981633974483
[[particle]]
shape = "square"
position = [0.0, 0.0036]
material = "grain"
[[wall]]
points = [[-1, -0.02], [1, -0.02], [1, 0], [-1, 0]]
closed = true
kind = "polygon"
surface_velocity = [0.2, 0.0]
material = "belt"
)";
    dem::World w = test::makeWorldFromToml(toml);
    // Slip phase: mu g = 4.9 m/s^2 needs 0.04 s to reach 0.2 m/s; run 0.2 s.
    for (int k = 0; k < 20000; ++k) w.step();
    EXPECT_NEAR(w.store().vx[0], 0.2, 2e-3);
    EXPECT_NEAR(w.store().vy[0], 0.0, 1e-3);
    EXPECT_EQ(w.walls().walls[0].displacement.x, 0.0);  // the belt's wall does not move
}

TEST(WallBodies, DiskInABeltLinedDrumSpinsInPlace) {
    // A disk resting at the bottom of a drum whose belt runs counter-clockwise at v (+x at the
    // bottom): friction turns it until its contact point, at -r y from the centre, moves with the
    // belt: v_x + omega r = v, and the disk spins near omega = v / r (counter-clockwise).
    const Real v = 0.1, r = 0.005;
    const std::string toml = std::string(R"(
[run]
end_time = 1.0
[dem]
dt = 1e-5
gravity = [0.0, -9.81]
)") + kFrictionLaw + R"(
[[particle]]
position = [0.0, -0.0945]
radius = 0.005
material = "grain"
[[drum]]
inner_radius = 0.1
thickness = 0.01
count = 60
surface_speed = 0.1
material = "belt"
)";
    dem::World w = test::makeWorldFromToml(toml);
    for (int k = 0; k < 30000; ++k) w.step();
    const auto& s = w.store();
    // No slip: the contact point (at -r y near the bottom) moves with the belt, v_x + omega r = v;
    // the disk spins at about v / r and rolls like a pendulum about the bottom, without drifting.
    EXPECT_NEAR(s.vx[0] + s.omega[0] * r, v, 0.02 * v);
    EXPECT_NEAR(s.omega[0] * r, v, 0.15 * v);
    EXPECT_NEAR(s.x[0], 0.0, 0.01);
}

}  // namespace
}  // namespace granulab
