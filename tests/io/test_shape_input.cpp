// SPDX-License-Identifier: MIT
// [[shape]] input (gc2d spec sections 2.1-2.3; docs/scene-format.md "Shapes"): a scene with every
// shape kind reads, validates and generates; bad shapes, shape references, radii, mass models
// and start overlaps of polygons give their specific message with file:line.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/scene.hpp"
#include "app/dem/dem_engine.hpp"
#include "geom/overlap_tests.hpp"
#include "geom/polygon.hpp"
#include "io/scene_reader.hpp"
#include "io/shape_checks.hpp"

using namespace granulab;

namespace {
const char* kBase = R"([run]
end_time = 1.0
[dem]
dt = 1e-5
[[material]]
name = "g"
density = 5000.0
[[contact]]
materials = ["g", "g"]
kn = 1e5
[[shape]]
name = "hex"
kind = "regular"
corner_count = 6
radius = 0.05
)";

const char* kAllKinds = R"([[shape]]
name = "tri"
kind = "polygon"
corners = [[0.0, 0.0], [0.1, 0.0], [0.0, 0.1]]
[[shape]]
name = "brick"
kind = "rectangle"
size = [0.1, 0.05]
chamfer = 0.1
[[shape]]
name = "egg"
kind = "ellipse"
size = [0.06, 0.04]
corner_count = 12
rotation_mode = "equal"
[[shape]]
name = "sand"
kind = "grain"
size = [0.04, 0.03]
size_mode = "gauss"
size_variation = 0.2
corner_count = 8
corner_count_mode = "equal"
corner_variation = 1
corner_angles = "rand1"
rotation_mode = "equal"
[[particle]]
shape = "tri"
position = [0.0, 0.0]
material = "g"
[[particle]]
shape = "hex"
position = [0.5, 0.0]
material = "g"
[[particle]]
shape = "brick"
position = [1.0, 0.0]
angle = 0.3
material = "g"
[[particle]]
shape = "egg"
position = [1.5, 0.0]
material = "g"
[[particle]]
position = [2.0, 0.0]
radius = 0.02
material = "g"
[[block]]
shape = "sand"
region = [0.0, 1.0, 1.0, 1.5]
spacing = 0.1
material = "g"
[[block]]
shape = "hex"
lattice = "random"
count = 10
region = [2.0, 1.0, 3.0, 2.0]
material = "g"
[[wall]]
points = [[-1.0, -0.5], [4.0, -0.5]]
material = "g"
)";

std::string particle(const std::string& shape, Real x, Real y, const std::string& extra = "") {
    return fmt::format("[[particle]]\nshape = \"{}\"\nposition = [{}, {}]\nmaterial = \"g\"\n{}", shape, x, y,
                       extra);
}

std::string errorsOf(const std::string& text) {
    try {
        app::checkAndPrepareDem(test::readSceneText(text, "s.toml"));
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

/// "s.toml:N" for the line where `needle` starts (its last occurrence, or the first).
std::string lineOf(const std::string& text, const std::string& needle, bool last = true) {
    const auto pos = last ? text.rfind(needle) : text.find(needle);
    EXPECT_NE(pos, std::string::npos) << needle;
    return "s.toml:" +
           std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

#define EXPECT_HAS(text, part) \
    EXPECT_NE((text).find(part), std::string::npos) << "missing '" << (part) << "' in:\n" << (text)
}  // namespace

TEST(ShapeInput, EveryKindReadsValidatesAndGenerates) {
    const std::string text = std::string(kBase) + kAllKinds;
    const model::SceneDef scene = test::readSceneText(text, "s.toml");
    ASSERT_EQ(scene.shapes.size(), 5u);
    EXPECT_EQ(scene.shapes[4].sizeMode, "gauss");
    EXPECT_EQ(scene.shapes[4].cornerVariation, 1);
    EXPECT_EQ(scene.shapes[2].chamfer, 0.1);
    const dem::PreparedScene v = app::checkAndPrepareDem(scene);
    EXPECT_TRUE(v.warnings.empty());
    const auto& init = v.initial;
    const auto& ps = init.particles;
    ASSERT_GE(ps.size(), 5u + 10u + 40u);
    // Explicit particles: tri, hex, brick, egg by pool entry, then a disk.
    for (std::uint32_t k = 0; k < 4; ++k) {
        EXPECT_EQ(ps[k].shape, k);
        EXPECT_EQ(ps[k].radius, init.shapes.circumradius[k]);
    }
    EXPECT_EQ(ps[4].shape, model::kDiskShape);
    EXPECT_EQ(ps[4].radius, 0.02);
    EXPECT_NEAR(init.shapes.area[0], 0.005, 1e-15);
    EXPECT_NEAR(init.shapes.area[2], 0.005 * (1 - 2 * 0.01), 1e-15);
    EXPECT_EQ(ps[2].angle, 0.3);
    // The random hex block shares the hex entry; every sand grain has its own.
    std::size_t hexes = 0;
    for (const auto& p : ps) hexes += p.shape == 1;
    EXPECT_EQ(hexes, 11u);
    EXPECT_EQ(init.shapes.size(), 4u + (ps.size() - 15u));
}

TEST(ShapeInput, NonConvexCollinearAndDuplicateCornersNameTheCorner) {
    const std::string shape = "[[shape]]\nname = \"bad\"\nkind = \"polygon\"\ncorners = ";
    std::string text = std::string(kBase) + shape + "[[0.0, 0.0], [1.0, 0.0], [0.2, 0.2], [0.0, 1.0]]\n";
    std::string err = errorsOf(text);
    EXPECT_HAS(err, lineOf(text, "[[shape]]") + ": shape[1].corners: the polygon is not convex at corner 2");
    text = std::string(kBase) + shape + "[[0.0, 0.0], [0.5, 0.0], [1.0, 0.0], [0.0, 1.0]]\n";
    EXPECT_HAS(errorsOf(text), "corner 1 lies on the straight line through its neighbours");
    text = std::string(kBase) + shape + "[[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 1.0]]\n";
    EXPECT_HAS(errorsOf(text), "corner 2 coincides with a neighbouring corner");
    text = std::string(kBase) + shape + "[[0.0, 0.0], [1.0, 0.0]]\n";
    EXPECT_HAS(errorsOf(text), "a polygon needs at least 3 corners, got 2");
    // Clockwise and non-convex: the corner index is that of the list as written.
    text = std::string(kBase) + shape + "[[0.0, 0.0], [0.0, 1.0], [0.2, 0.2], [1.0, 0.0]]\n";
    EXPECT_HAS(errorsOf(text), "not convex at corner 2");
}

TEST(ShapeInput, ClockwisePolygonIsFixedWithAWarning) {
    const std::string text = std::string(kBase) +
                             "[[shape]]\nname = \"cw\"\nkind = \"polygon\"\ncorners = [[0.0, 0.0], [0.0, "
                             "0.1], [0.1, 0.1], [0.1, 0.0]]\n" +
                             particle("cw", 0.0, 0.0);
    const dem::PreparedScene v = app::checkAndPrepareDem(test::readSceneText(text, "s.toml"));
    ASSERT_EQ(v.warnings.size(), 1u);
    EXPECT_HAS(v.warnings[0], lineOf(text, "[[shape]]") + ": shape[1].corners");
    EXPECT_HAS(v.warnings[0], "listed clockwise; reversed to counter-clockwise");
    const auto corners = v.initial.shapes.shapeCorners(v.initial.particles[0].shape);
    EXPECT_TRUE(geom::checkConvexPolygon(corners).ok());
    EXPECT_NEAR(geom::polygonMass(corners).area, 0.01, 1e-15);
}

TEST(ShapeInput, ShapeReferencesAndRadii) {
    std::string text = std::string(kBase) + particle("hexx", 0, 0);
    std::string err = errorsOf(text);
    EXPECT_HAS(err,
               lineOf(text, "[[particle]]") +
                   ": particle[0].shape: unknown shape 'hexx' (did you mean 'hex'?); defined: disk, hex");
    text = std::string(kBase) + particle("hex", 0, 0, "radius = 0.01\n");
    err = errorsOf(text);
    EXPECT_HAS(err, lineOf(text, "radius = 0.01") +
                        ": particle[0].radius: radius belongs to disks; the size of shape 'hex' comes from "
                        "its [[shape]]");
    text = std::string(kBase) +
           "[[block]]\nshape = \"hex\"\nregion = [0.0, 0.0, 1.0, 1.0]\nspacing = 0.2\nradius = "
           "0.01\nmaterial = \"g\"\n";
    EXPECT_HAS(errorsOf(text), lineOf(text, "radius = 0.01") + ": block[0].radius: radius belongs to disks");
    // Disks still need their radius.
    text = std::string(kBase) + "[[particle]]\nposition = [0.0, 0.0]\nmaterial = \"g\"\n";
    EXPECT_HAS(errorsOf(text), "particle[0].radius: missing: radius in m");
    // A lattice of a fixed shape (size and orientation) may be tighter than its circumcircles; the
    // exact overlap check decides: hexagons with corners on +-x (0.1 m wide, 0.0866 m high) on a
    // square lattice fit at spacing 0.101 m and overlap at 0.09 m.
    text = std::string(kBase) +
           "[[block]]\nshape = \"hex\"\nregion = [0.0, 0.0, 1.0, 1.0]\nspacing = 0.101\nlattice = "
           "\"square\"\nmaterial = \"g\"\n";
    EXPECT_EQ(errorsOf(text).find("overlap"), std::string::npos) << errorsOf(text);
    text = std::string(kBase) +
           "[[block]]\nshape = \"hex\"\nregion = [0.0, 0.0, 1.0, 1.0]\nspacing = 0.09\nlattice = "
           "\"square\"\nmaterial = \"g\"\n";
    EXPECT_HAS(errorsOf(text), "polygon particles 0 and 1 overlap at start");
    // Random rotations need the circumcircle bound: 2 x 0.05 > 0.09.
    text = std::string(kBase) +
           "[[shape]]\nname = \"spun\"\nkind = \"regular\"\ncorner_count = 6\nradius = 0.05\nrotation_mode = "
           "\"equal\"\n"
           "[[block]]\nshape = \"spun\"\nregion = [0.0, 0.0, 1.0, 1.0]\nspacing = 0.09\nmaterial = \"g\"\n";
    EXPECT_HAS(
        errorsOf(text),
        "block[0].spacing: spacing 0.09 m is smaller than 0.1 m, twice the largest circumradius 0.05 m "
        "of shape 'spun'");
}

TEST(ShapeInput, ShapeKeysAndRanges) {
    const std::string head = std::string(kBase) + "[[shape]]\nname = \"s\"\n";
    std::string text = head + "kind = \"regular\"\ncorner_count = 2\nradius = 0.1\n";
    std::string err = errorsOf(text);
    EXPECT_HAS(err, lineOf(text, "[[shape]]") + ": shape[1].corner_count: must be in [3, 10000]");
    EXPECT_HAS(err, "got 2");
    text = head + "kind = \"rectangle\"\nsize = [0.1, 0.1]\nradius = 0.1\n";
    err = errorsOf(text);
    EXPECT_HAS(err, lineOf(text, "radius = 0.1") +
                        ": shape[1].radius: does not apply to a shape of kind 'rectangle'");
    EXPECT_HAS(err, "keys of rectangle shapes: name, kind, size, chamfer, rotation_mode, rotation");
    text = head + "kind = \"grain\"\nsize = [0.1, 0.1]\ncorner_count = 6\ncorner_cont_mode = \"equal\"\n";
    EXPECT_HAS(errorsOf(text), "unknown key (did you mean 'corner_count_mode'?)");
    text = head +
           "kind = \"grain\"\nsize = [0.1, 0.1]\ncorner_count = 6\ncorner_count_mode = "
           "\"equal\"\ncorner_variation = 4\n"
           "size_variation = 1.0\ncorner_angles = \"rand3\"\nrotation_mode = \"gaus\"\n";
    err = errorsOf(text);
    EXPECT_HAS(err, "shape[1].corner_variation: corner counts [2, 10]");
    EXPECT_HAS(err, "shape[1].size_variation: must be in [0, 1), got 1");
    EXPECT_HAS(err, "shape[1].corner_angles: 'rand3' is not allowed (did you mean 'rand1'?)");
    EXPECT_HAS(err,
               "shape[1].rotation_mode: 'gaus' is not allowed (did you mean 'gauss'?); allowed: const, "
               "equal, gauss");
    text = head + "kind = \"rectangle\"\nsize = [0.1, -0.1]\nchamfer = 0.5\n";
    err = errorsOf(text);
    EXPECT_HAS(err, "shape[1].size: both entries must be > 0");
    EXPECT_HAS(err, "shape[1].chamfer: must be in [0, 0.5), got 0.5");
    text = head + "kind = \"ellipse\"\nsize = [0.1, 0.1]\n";
    EXPECT_HAS(errorsOf(text),
               "shape[1].corner_count: missing: number of corners, >= 3 (required for kind 'ellipse')");
    text = std::string(kBase) + "[[shape]]\nname = \"disk\"\n";
    err = errorsOf(text);
    EXPECT_HAS(err,
               "shape[1].kind: missing: shape kind, allowed: polygon, regular, rectangle, ellipse, grain");
    text = std::string(kBase) +
           "[[shape]]\nname = \"disk\"\nkind = \"regular\"\ncorner_count = 5\nradius = 1.0\n"
           "[[shape]]\nname = \"hex\"\nkind = \"regular\"\ncorner_count = 5\nradius = 1.0\n";
    err = errorsOf(text);
    EXPECT_HAS(err, "shape[1].name: 'disk' cannot name a shape");
    EXPECT_HAS(err, "shape[2].name: duplicate shape name 'hex' (first defined at s.toml:11)");
}

TEST(ShapeInput, PolygonsNeedTheAreaMassModel) {
    std::string scene = std::string(kBase) + particle("hex", 0, 0);
    scene.insert(scene.find("[[material]]"), "mass_model = \"sphere\"\n");
    const std::string err = errorsOf(scene);
    EXPECT_HAS(err,
               "s.toml:3: dem.mass_model: polygon particles need mass_model = \"disk\" (areal density in "
               "kg/m^2), got 'sphere'");
    EXPECT_HAS(err, "particle[0] (" + lineOf(scene, "[[particle]]") + ", shape 'hex')");
}

TEST(ShapeInput, PolygonStartOverlapsAreExact) {
    // Hexagons with a corner on +x have flat edges at y = +-r sqrt(3)/2 = +-0.0433 m: stacked
    // 0.0866 m apart they touch (allowed), 0.085 m apart they overlap although the
    // circumcircles overlap in both cases.
    const Real h = 0.05 * std::sqrt(3.0);
    EXPECT_EQ(errorsOf(std::string(kBase) + particle("hex", 0, 0) + particle("hex", 0, h + 1e-9)), "");
    std::string text = std::string(kBase) + particle("hex", 0, 0) + particle("hex", 0, 0.085);
    std::string err = errorsOf(text);
    EXPECT_HAS(err, lineOf(text, "[[particle]]", false) +
                        ": particle: polygon particles 0 and 1 overlap at start (overlap area");
    // Disk against polygon: centre 0.0433 + 0.0099 m above a hexagon with a 0.01 m radius.
    auto diskAt = [](Real y) {
        return fmt::format("[[particle]]\nposition = [0.0, {}]\nradius = 0.01\nmaterial = \"g\"\n", y);
    };
    EXPECT_HAS(errorsOf(std::string(kBase) + particle("hex", 0, 0) + diskAt(h / 2 + 0.0099)),
               "particles 0 and 1 overlap by 0.0001");
    EXPECT_EQ(errorsOf(std::string(kBase) + particle("hex", 0, 0) + diskAt(h / 2 + 0.0101)), "");
    // Polygon against a wall: a floor 0.04 m below the centre cuts the hexagon, 0.044 m does not.
    auto wallAt = [](Real y) {
        return fmt::format("[[wall]]\npoints = [[-1.0, {}], [1.0, {}]]\nmaterial = \"g\"\n", y, y);
    };
    text = std::string(kBase) + particle("hex", 0, 0) + wallAt(-0.04);
    err = errorsOf(text);
    EXPECT_HAS(err, "particle 0 at (0, 0) overlaps wall[0] at start (the wall is defined at " +
                        lineOf(text, "[[wall]]") + ")");
    EXPECT_EQ(errorsOf(std::string(kBase) + particle("hex", 0, 0) + wallAt(-0.044)), "");
    // A short wall entirely inside the polygon is caught too.
    EXPECT_HAS(errorsOf(std::string(kBase) + particle("hex", 0, 0) +
                        "[[wall]]\npoints = [[-0.01, 0.0], [0.01, 0.0]]\nmaterial = \"g\"\n"),
               "overlaps wall[0]");
}

TEST(ShapeInput, OverlapGeometryHelpers) {
    const std::vector<Vec2> sq = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    EXPECT_NEAR(geom::diskPolygonOverlap({0.5, 0.5}, 0.1, sq), 0.6,
                1e-15);  // inside: r + distance to the boundary
    EXPECT_NEAR(geom::diskPolygonOverlap({0.5, -0.05}, 0.1, sq), 0.05, 1e-15);
    EXPECT_LT(geom::diskPolygonOverlap({1.1, 1.1}, 0.1, sq), 0);  // the corner is 0.141 away
    EXPECT_TRUE(geom::segmentEntersPolygon({-1, 0.5}, {2, 0.5}, sq));
    EXPECT_TRUE(geom::segmentEntersPolygon({0.4, 0.4}, {0.6, 0.6}, sq));  // inside
    EXPECT_FALSE(geom::segmentEntersPolygon({-1, 0}, {2, 0}, sq));        // along an edge: touching
    EXPECT_FALSE(geom::segmentEntersPolygon({-1, 1}, {1, -1}, sq));       // through a corner only
    EXPECT_FALSE(geom::segmentEntersPolygon({-1, -0.1}, {2, -0.1}, sq));
}
