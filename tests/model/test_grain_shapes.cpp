// SPDX-License-Identifier: MIT
// Grain shapes (gc2d spec section 2.3, App. B.1.6): areas of the deterministic shapes, the random
// grain modes (corners on the ellipse, sorted angles, corner-count bounds, RAND1 windows,
// truncated Gaussians), determinism, convexity of many random grains, and their generation into
// particles (shared pool entries for named shapes, one per grain, disk scenes unchanged).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "dem/generate.hpp"
#include "geom/polygon.hpp"
#include "model/grain_shapes.hpp"

using namespace granulab;
using namespace granulab::model;
using namespace granulab::dem;

namespace {
ShapeDef grainDef(const std::string& angles, const std::string& sizeMode, const std::string& countMode) {
    ShapeDef d;
    d.name = std::string(1, 'g');  // not a literal: GCC 12 -Wrestrict false positive (PR 105651)
    d.kind = std::string("grain");
    d.size = {1.0, 0.4};
    d.sizeVariation = 0.3;
    d.cornerCount = 6;
    d.cornerVariation = 3;
    d.cornerAngles = angles;
    d.sizeMode = sizeMode;
    d.cornerCountMode = countMode;
    return d;
}

Real wrap(Real phi) {
    phi = std::fmod(phi, 2 * kPi);
    return phi < 0 ? phi + 2 * kPi : phi;
}

/// Whether every window [(i - h) step, (i + h) step] (mod 2 pi) holds exactly one angle.
bool oneAnglePerWindow(const std::vector<Real>& angles, Real h) {
    const std::size_t n = angles.size();
    const Real step = 2 * kPi / static_cast<Real>(n);
    for (std::size_t i = 0; i < n; ++i) {
        int inside = 0;
        for (const Real phi : angles) {
            const Real rel = wrap(phi - (static_cast<Real>(i) - h) * step);  // offset from the window start
            inside += rel <= 2 * h * step + 1e-12;
        }
        if (inside != 1) return false;
    }
    return true;
}
}  // namespace

TEST(GrainShapes, RegularPolygonArea) {
    for (int n = 3; n <= 64; ++n) {
        const Real r = 0.37;
        const auto c = regularPolygon(n, r);
        ASSERT_EQ(c.size(), static_cast<std::size_t>(n));
        EXPECT_EQ(c[0], (Vec2{r, 0}));  // a corner on +x
        EXPECT_TRUE(geom::checkConvexPolygon(c).ok()) << n;
        EXPECT_NEAR(geom::polygonMass(c).area, 0.5 * n * r * r * std::sin(2 * kPi / n), 1e-12) << n;
        for (const auto& p : c) EXPECT_NEAR(norm(p), r, 1e-15);
    }
}

TEST(GrainShapes, RectangleChamferAndEllipseAreas) {
    const auto plain = rectangle(2.0, 0.5, 0.0);
    ASSERT_EQ(plain.size(), 4u);
    EXPECT_NEAR(geom::polygonMass(plain).area, 1.0, 1e-15);
    const Real c = 0.2;
    const auto cut = rectangle(2.0, 0.5, c);
    ASSERT_EQ(cut.size(), 8u);
    EXPECT_TRUE(geom::checkConvexPolygon(cut).ok());
    EXPECT_NEAR(geom::polygonMass(cut).area, 1.0 * (1 - 2 * c * c), 1e-15);  // four cut triangles
    EXPECT_NEAR(norm(cut[1] - cut[0]), 2.0 * (1 - 2 * c), 1e-15);            // bottom edge a (1 - 2c)
    EXPECT_NEAR(norm(cut[3] - cut[2]), 0.5 * (1 - 2 * c), 1e-15);            // right edge b (1 - 2c)
    // The ellipse polygon is the affine image of the regular one: area N/2 a b sin(2 pi / N).
    const auto e = ellipsePolygon(0.3, 0.1, 10);
    EXPECT_NEAR(geom::polygonMass(e).area, 5 * 0.3 * 0.1 * std::sin(2 * kPi / 10), 1e-15);
    for (const auto& p : e) EXPECT_NEAR(p.x * p.x / 0.09 + p.y * p.y / 0.01, 1.0, 1e-12);
}

TEST(GrainShapes, RandomGrainsOfEveryModeAreConvexOnTheEllipseAndInBounds) {
    const std::vector<std::string> modes = {"const", "equal", "gauss"};
    for (const std::string angles : {"regular", "rand1", "rand2", "full"}) {
        for (const auto& sizeMode : modes) {
            for (const auto& countMode : modes) {
                SCOPED_TRACE(angles + "/" + sizeMode + "/" + countMode);
                const ShapeDef d = grainDef(angles, sizeMode, countMode);
                CounterRng rng(7, 99);
                std::set<int> counts;
                for (int k = 0; k < 10000; ++k) {
                    const Grain g = randomGrain(d, rng);
                    const Real a = g.semiAxes.x, b = g.semiAxes.y;
                    ASSERT_TRUE(geom::checkConvexPolygon(g.corners).ok()) << k;
                    ASSERT_GE(a, 0.7 - 1e-15);
                    ASSERT_LE(a, 1.3 + 1e-15);
                    ASSERT_GE(b, 0.4 * 0.7 - 1e-15);
                    ASSERT_LE(b, 0.4 * 1.3 + 1e-15);
                    if (sizeMode == "const") {
                        ASSERT_TRUE(a == 1.0 && b == 0.4);
                    }
                    const int n = static_cast<int>(g.corners.size());
                    ASSERT_GE(n, 3);
                    ASSERT_LE(n, 9);
                    if (countMode == "const") {
                        ASSERT_EQ(n, 6);
                    }
                    counts.insert(n);
                    ASSERT_EQ(g.angles.size(), g.corners.size());
                    for (std::size_t i = 0; i < g.corners.size(); ++i) {
                        const Vec2 p = g.corners[i];
                        ASSERT_NEAR(p.x * p.x / (a * a) + p.y * p.y / (b * b), 1.0, 1e-12);
                        ASSERT_GE(g.angles[i], 0.0);
                        ASSERT_LT(g.angles[i], 2 * kPi);
                        if (i > 0) {
                            ASSERT_LT(g.angles[i - 1], g.angles[i]);  // sorted ascending
                        }
                    }
                }
                if (countMode == "equal") {
                    EXPECT_EQ(counts.size(), 7u);  // every count of [3, 9] occurs
                }
            }
        }
    }
}

TEST(GrainShapes, Rand1AnglesStayInTheirWindowsAndRand2DoesNot) {
    ShapeDef d = grainDef("rand1", "const", "const");
    CounterRng rng(3, 4);
    for (int k = 0; k < 2000; ++k) ASSERT_TRUE(oneAnglePerWindow(randomGrain(d, rng).angles, 0.5)) << k;
    // The check can fail: RAND2's wider windows [(i-1), (i+1)] 2 pi/N break it for some grains,
    // while every RAND2 angle still lies within one step of its regular angle.
    d.cornerAngles = std::string("rand2");
    int broken = 0;
    for (int k = 0; k < 2000; ++k) broken += !oneAnglePerWindow(randomGrain(d, rng).angles, 0.5);
    EXPECT_GT(broken, 100);
    d.cornerAngles = std::string("regular");
    const Grain g = randomGrain(d, rng);
    for (std::size_t i = 0; i < g.angles.size(); ++i)
        EXPECT_NEAR(g.angles[i], static_cast<Real>(i) * 2 * kPi / 6, 1e-15);
}

TEST(GrainShapes, SpecialTruncatedGaussianAndGaussModes) {
    CounterRng rng(11, 12);
    Real sum = 0, sum2 = 0;
    const int n = 200000;
    for (int k = 0; k < n; ++k) {
        const Real u = specialGaussianUnit(rng);
        ASSERT_GE(u, 0.0);
        ASSERT_LE(u, 1.0);
        sum += u;
        sum2 += u * u;
    }
    const Real mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
    EXPECT_NEAR(mean, 0.5, 1e-3);  // N(0.5, 0.1): the truncation at 5 sigma hardly shows
    EXPECT_NEAR(sd, 0.1, 1e-3);
    // GAUSS semi-axes: lo + u (hi - lo), mean l, standard deviation 0.1 (hi - lo) = 0.06 l.
    const ShapeDef d = grainDef("rand1", "gauss", "gauss");
    Real sa = 0, sa2 = 0;
    std::vector<int> hist(10, 0);
    for (int k = 0; k < 20000; ++k) {
        const Grain g = randomGrain(d, rng);
        sa += g.semiAxes.x;
        sa2 += g.semiAxes.x * g.semiAxes.x;
        ++hist[static_cast<std::size_t>(g.drawnCorners)];
    }
    const Real ma = sa / 20000, sda = std::sqrt(sa2 / 20000 - ma * ma);
    EXPECT_NEAR(ma, 1.0, 3e-3);
    EXPECT_NEAR(sda, 0.06, 2e-3);
    // Corner counts round(3 + 6 u): 6 is the mode, and 3 or 9 need u beyond 4.2 sigma.
    EXPECT_GT(hist[6], hist[5]);
    EXPECT_GT(hist[6], hist[7]);
    EXPECT_LT(hist[3] + hist[9], 5);
    // GAUSS rotation lies in the open interval (phi_0 - pi/2, phi_0 + pi/2).
    ShapeDef r = d;
    r.rotationMode = std::string("gauss");
    r.rotation = 1.0;
    Real rmin = 1e9, rmax = -1e9, rs = 0, rs2 = 0;
    for (int k = 0; k < 20000; ++k) {
        const Real phi = drawRotation(r, rng);
        rmin = std::min(rmin, phi);
        rmax = std::max(rmax, phi);
        rs += phi;
        rs2 += phi * phi;
    }
    EXPECT_GT(rmin, 1.0 - kPi / 2);
    EXPECT_LT(rmax, 1.0 + kPi / 2);
    const Real rmean = rs / 20000, rsd = std::sqrt(rs2 / 20000 - rmean * rmean);
    EXPECT_NEAR(rmean, 1.0, 0.01);
    EXPECT_NEAR(rsd, kPi / 10, 0.01);  // 0.1 of the interval width pi
    r.rotationMode = std::string("equal");
    for (int k = 0; k < 1000; ++k) {
        const Real phi = drawRotation(r, rng);
        ASSERT_TRUE(phi >= 0 && phi < 2 * kPi);
    }
    r.rotationMode = std::string("const");
    EXPECT_EQ(drawRotation(r, rng), 1.0);
}

TEST(GrainShapes, SpecialRectangleAndFullAxes) {
    ShapeDef d = grainDef("special_rectangle", "const", "const");
    d.fullAxes = true;  // size = full axes: semi-axes (0.5, 0.2), rectangle 1 x 0.4
    CounterRng rng(1, 2);
    const Grain g = randomGrain(d, rng);
    ASSERT_EQ(g.corners.size(), 8u);
    EXPECT_EQ(g.semiAxes, (Vec2{0.5, 0.2}));
    EXPECT_NEAR(geom::polygonMass(g.corners).area,
                0.4 * (1 - 2 * kSpecialRectangleChamfer * kSpecialRectangleChamfer), 1e-15);
    EXPECT_NEAR(maxPlacementRadius(d), std::hypot(0.5, 0.2 * (1 - 2 * kSpecialRectangleChamfer)), 1e-15);
    d.cornerAngles = std::string("rand1");
    d.sizeMode = std::string("equal");
    EXPECT_NEAR(maxPlacementRadius(d), 0.5 * 1.3, 1e-15);  // largest semi-axis that can be drawn
}

TEST(GrainShapes, DeterministicPerSeedAndStream) {
    const ShapeDef d = grainDef("full", "equal", "equal");
    CounterRng a(5, 1), b(5, 1), c(6, 1);
    bool differs = false;
    for (int k = 0; k < 100; ++k) {
        const Grain ga = randomGrain(d, a), gb = randomGrain(d, b), gc = randomGrain(d, c);
        ASSERT_EQ(ga.corners, gb.corners);
        differs = differs || ga.corners != gc.corners;
    }
    EXPECT_TRUE(differs);
}

TEST(GrainShapes, ClockwisePolygonIsReversedAndInvalidParametersGiveNothing) {
    ShapeDef d;
    d.kind = std::string("polygon");
    d.corners = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};  // clockwise
    const auto c = deterministicCorners(d);
    ASSERT_TRUE(c.has_value());
    EXPECT_TRUE(geom::checkConvexPolygon(*c).ok());
    EXPECT_EQ(c->front(), (Vec2{1, 0}));
    d.corners = {{0, 0}, {2, 0}, {1, 0.2}, {1, 1}};  // non-convex
    EXPECT_FALSE(deterministicCorners(d).has_value());
    d.kind = std::string("regular");
    d.cornerCount = 2;
    d.radius = 1;
    EXPECT_FALSE(deterministicCorners(d).has_value());
}

namespace {
SceneDef shapeScene() {
    SceneDef s;
    s.run.seed = 9;
    MaterialDef m;
    m.name = std::string(1, 'g');
    m.density = 2.0;
    s.materials.push_back(m);
    ShapeDef hex;
    hex.name = std::string("hex");
    hex.kind = std::string("regular");
    hex.cornerCount = 6;
    hex.radius = 0.1;
    s.shapes.push_back(hex);
    s.shapes.push_back(grainDef("rand1", "equal", "equal"));
    s.shapes.back().size = {0.1, 0.08};
    s.shapes.back().rotationMode = std::string("equal");
    return s;
}

BlockDef shapeBlock(const std::string& shape, BlockDef::Lattice lattice) {
    BlockDef b;
    b.lattice = lattice;
    b.shape = shape;
    b.xmin = 0;
    b.ymin = 0;
    b.xmax = 2;
    b.ymax = 2;
    b.spacing = 0.3;
    b.count = lattice == BlockDef::Lattice::Random ? 40 : -1;
    b.material = std::string(1, 'g');
    return b;
}
}  // namespace

TEST(GrainGeneration, NamedShapesShareOneEntryGrainsGetOneEach) {
    SceneDef s = shapeScene();
    ParticleDef p;
    p.shape = std::string("hex");
    p.position = {-1, -1};
    p.angle = 0.25;
    p.material = std::string(1, 'g');
    s.particles.push_back(p);
    s.blocks.push_back(shapeBlock("hex", BlockDef::Lattice::Square));
    s.blocks.push_back(shapeBlock("g", BlockDef::Lattice::Hexagonal));
    Diagnostics d;
    const auto g = generateParticles(s, {"g"}, d);
    ASSERT_TRUE(d.empty());
    std::size_t hexes = 0, grains = 0;
    std::set<std::uint32_t> grainShapes;
    for (const auto& q : g.particles) {
        ASSERT_NE(q.shape, kDiskShape);
        ASSERT_LT(q.shape, g.shapes.size());
        EXPECT_EQ(q.radius, g.shapes.circumradius[q.shape]);
        if (q.shape == 0) {
            ++hexes;
        } else {
            grainShapes.insert(q.shape);
            ++grains;
        }
    }
    EXPECT_EQ(hexes, 1u + 49u);             // the explicit particle and a 7 x 7 square lattice
    EXPECT_EQ(grainShapes.size(), grains);  // one pool entry per grain
    EXPECT_EQ(g.shapes.size(), 1u + grains);
    EXPECT_EQ(g.particles[0].angle, 0.25);  // const rotation 0 plus the particle's own angle
    EXPECT_NEAR(g.shapes.area[0], 3 * 0.01 * std::sin(2 * kPi / 6), 1e-15);
    // Lattice grains: the ellipse, not the centroid, sits on the lattice site, so every corner
    // lies within the largest semi-axis 0.1 (1 + 0.3) of its site and neighbours 0.3 m apart
    // cannot overlap.
    const Real dy = 0.3 * std::sqrt(3.0) / 2;
    bool offCentre = false;
    for (std::size_t k = 50; k < g.particles.size(); ++k) {
        const auto& q = g.particles[k];
        const long row = std::lround((q.position.y - 0.15) / dy);
        const Real shift = row % 2 ? 0.15 : 0.0;
        const Vec2 site{0.15 + shift + 0.3 * std::round((q.position.x - 0.15 - shift) / 0.3),
                        0.15 + dy * static_cast<Real>(row)};
        const Real c = std::cos(q.angle), sn = std::sin(q.angle);
        for (const Vec2 v : g.shapes.shapeCorners(q.shape))
            EXPECT_LE(norm(q.position + Vec2{c * v.x - sn * v.y, sn * v.x + c * v.y} - site), 0.13 + 1e-12)
                << k;
        offCentre = offCentre || norm(q.position - site) > 1e-6;
    }
    EXPECT_TRUE(offCentre);  // random angles move the centroid off the ellipse centre
}

TEST(GrainGeneration, RandomPolygonBlockUsesCircumradiiAndKeepsDiskScenesUnchanged) {
    SceneDef s = shapeScene();
    BlockDef disks = shapeBlock("disk", BlockDef::Lattice::Random);
    disks.radius.value = 0.05;
    s.blocks.push_back(disks);
    Diagnostics d;
    const auto before = generateParticles(s, {"g"}, d);
    s.blocks.push_back(shapeBlock("g", BlockDef::Lattice::Random));
    const auto after = generateParticles(s, {"g"}, d);
    ASSERT_TRUE(d.empty());
    ASSERT_EQ(after.particles.size(), before.particles.size() + 40);
    // Same seed, same grains and places; another seed, other ones.
    const auto again = generateParticles(s, {"g"}, d);
    EXPECT_EQ(again.shapes.corners, after.shapes.corners);
    EXPECT_EQ(again.particles.back().position, after.particles.back().position);
    s.run.seed += 1;
    const auto other = generateParticles(s, {"g"}, d);
    EXPECT_NE(other.shapes.corners, after.shapes.corners);
    s.run.seed -= 1;
    for (std::size_t k = 0; k < before.particles.size(); ++k) {
        EXPECT_EQ(after.particles[k].position, before.particles[k].position);
        EXPECT_EQ(after.particles[k].shape, kDiskShape);
    }
    for (std::size_t i = 0; i < after.particles.size(); ++i) {
        const auto& p = after.particles[i];
        EXPECT_GE(p.position.x - p.radius, 0.0);
        EXPECT_LE(p.position.y + p.radius, 2.0);
        if (i > before.particles.size()) {
            EXPECT_LE(p.radius, after.particles[i - 1].radius);  // largest first
        }
        for (std::size_t j = i + 1; j < after.particles.size(); ++j)
            EXPECT_GE(norm(p.position - after.particles[j].position), p.radius + after.particles[j].radius);
    }
}
