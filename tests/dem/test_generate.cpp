// SPDX-License-Identifier: MIT
// Particle generation: lattice site counts and spacing, random placement without overlaps
// inside the region, truncated size distributions, thermal velocities (zero momentum, exact T).
#include <gtest/gtest.h>

#include <cmath>

#include "dem/generate.hpp"
#include "model/gc2d_generators.hpp"

using namespace granulab;
using namespace granulab::model;
using namespace granulab::dem;

namespace {
SceneDef sceneWith(const BlockDef& b) {
    SceneDef s;
    s.run.seed = 42;
    MaterialDef m;
    m.name = "g";
    m.density = 2.0;
    s.materials.push_back(m);
    s.blocks.push_back(b);
    return s;
}

BlockDef block(BlockDef::Lattice lattice) {
    BlockDef b;
    b.lattice = lattice;
    b.xmin = 0;
    b.ymin = 0;
    b.xmax = 10;
    b.ymax = 10;
    b.spacing = 1.0;
    b.radius.kind = SizeDistDef::Kind::Constant;
    b.radius.value = 0.4;
    b.material = std::string(1, 'g');  // not a literal: GCC 12 -Wrestrict false positive (PR 105651)
    return b;
}
}  // namespace

TEST(Generate, SquareAndHexagonalLatticeSites) {
    Diagnostics d;
    const auto square = generateParticles(sceneWith(block(BlockDef::Lattice::Square)), {"g"}, d);
    EXPECT_EQ(square.particles.size(), 100u);  // sites at 0.5 .. 9.5
    const auto hex = generateParticles(sceneWith(block(BlockDef::Lattice::Hexagonal)), {"g"}, d);
    // Rows sqrt(3)/2 apart from y = 0.5 below 10: 11 rows; even rows x = 0.5..9.5, odd rows
    // shifted by 1/2, x = 0.0..9.0: 10 sites each.
    EXPECT_EQ(hex.particles.size(), 110u);
    Real nearest = 1e9;
    for (std::size_t i = 0; i < hex.particles.size(); ++i)
        for (std::size_t j = i + 1; j < hex.particles.size(); ++j)
            nearest = std::min(nearest, norm(hex.particles[i].position - hex.particles[j].position));
    EXPECT_NEAR(nearest, 1.0, 1e-12);
    EXPECT_TRUE(d.empty());
}

TEST(Generate, RandomPlacementHasNoOverlapsAndStaysInside) {
    BlockDef b = block(BlockDef::Lattice::Random);
    b.count = 150;
    b.radius.kind = SizeDistDef::Kind::Uniform;
    b.radius.min = 0.2;
    b.radius.max = 0.4;
    Diagnostics d;
    const auto g = generateParticles(sceneWith(b), {"g"}, d);
    ASSERT_TRUE(d.empty());
    ASSERT_EQ(g.particles.size(), 150u);
    for (std::size_t i = 0; i < g.particles.size(); ++i) {
        const auto& p = g.particles[i];
        EXPECT_GE(p.position.x - p.radius, 0.0);
        EXPECT_LE(p.position.x + p.radius, 10.0);
        EXPECT_GE(p.radius, 0.2);
        EXPECT_LE(p.radius, 0.4);
        for (std::size_t j = i + 1; j < g.particles.size(); ++j)
            EXPECT_GE(norm(p.position - g.particles[j].position), p.radius + g.particles[j].radius);
    }
    // Too many for the region: a clear error instead of an endless loop.
    b.count = 5000;
    Diagnostics full;
    generateParticles(sceneWith(b), {"g"}, full);
    EXPECT_FALSE(full.empty());
}

TEST(Generate, TruncatedGaussianRadiiAndThermalVelocities) {
    BlockDef b = block(BlockDef::Lattice::Square);
    b.radius.kind = SizeDistDef::Kind::Gaussian;
    b.radius.mean = 0.35;
    b.radius.sigma = 0.1;
    b.radius.min = 0.3;
    b.radius.max = 0.45;
    b.temperature = 2.5;
    Diagnostics d;
    const auto g = generateParticles(sceneWith(b), {"g"}, d);
    Vec2 momentum;
    Real twiceKe = 0;
    for (const auto& p : g.particles) {
        EXPECT_GE(p.radius, 0.3);
        EXPECT_LE(p.radius, 0.45);
        const Real m = diskMass(2.0, p.radius);
        momentum += p.velocity * m;
        twiceKe += m * norm2(p.velocity);
    }
    EXPECT_NEAR(momentum.x, 0.0, 1e-12);
    EXPECT_NEAR(momentum.y, 0.0, 1e-12);
    const Real n = static_cast<Real>(g.particles.size());
    EXPECT_NEAR(twiceKe / (2 * n - 2), 2.5, 1e-12);  // kinetic temperature, exactly
    // Same seed, same particles.
    const auto again = generateParticles(sceneWith(b), {"g"}, d);
    EXPECT_EQ(again.particles[17].radius, g.particles[17].radius);
    EXPECT_EQ(again.particles[17].velocity, g.particles[17].velocity);
}

// --- gc2d generators (spec section 6.5): rect/fcc lattices, jitter, velocity ranges, heaps ----

namespace {
BlockDef gridBlock(BlockDef::Lattice lattice) {
    BlockDef b = block(lattice);
    b.spacing = 0;
    b.xmax = 4;
    b.ymax = 3;
    b.grid = {1.0, 0.9};
    return b;
}

HeapDef diskHeap(HeapDef::Stacking stacking, Real slope) {
    HeapDef h;
    h.stacking = stacking;
    h.xLeft = 0;
    h.xRight = 6;
    h.base = 0;
    h.slope = slope;
    h.radius = 0.5;
    h.material = std::string(1, 'g');
    return h;
}

SceneDef sceneWithHeap(const HeapDef& h) {
    SceneDef s = sceneWith(block(BlockDef::Lattice::Square));
    s.blocks.clear();
    s.heaps.push_back(h);
    return s;
}

/// y0 + tan(psi) * (distance from the nearer end) at x.
Real slopeLine(const HeapDef& h, Real x) {
    return h.base + std::tan(h.slope) * std::min(x - h.xLeft, h.xRight - x);
}
}  // namespace

TEST(Generate, RectAndFccSitesAsDocumented) {
    Diagnostics d;
    // rect: sites (xmin + dx/2 + i dx, ymin + dy/2 + j dy) in [0, 4) x [0, 3): 4 per row, 3 rows
    // (y = 0.45, 1.35, 2.25; 3.15 is outside).
    const auto rect = generateParticles(sceneWith(gridBlock(BlockDef::Lattice::Rect)), {"g"}, d);
    ASSERT_EQ(rect.particles.size(), 12u);
    for (std::size_t k = 0; k < 12; ++k) {
        EXPECT_DOUBLE_EQ(rect.particles[k].position.x, 0.5 + static_cast<Real>(k % 4));
        EXPECT_DOUBLE_EQ(rect.particles[k].position.y, 0.45 + 0.9 * static_cast<Real>(k / 4));
    }
    // fcc: even rows as rect; odd rows shifted by dx/2, which makes them start at x = xmin:
    // x = 0, 1, 2, 3 (4 sites; 4.0 is outside the half-open region).
    const auto fcc = generateParticles(sceneWith(gridBlock(BlockDef::Lattice::Fcc)), {"g"}, d);
    ASSERT_EQ(fcc.particles.size(), 12u);
    for (std::size_t k = 0; k < 12; ++k) {
        const std::size_t row = k / 4, col = k % 4;
        const Real x = (row % 2 == 0 ? 0.5 : 0.0) + static_cast<Real>(col);
        EXPECT_DOUBLE_EQ(fcc.particles[k].position.x, x) << k;
        EXPECT_DOUBLE_EQ(fcc.particles[k].position.y, 0.45 + 0.9 * static_cast<Real>(row)) << k;
    }
    EXPECT_EQ(nearestSiteDistance(gridBlock(BlockDef::Lattice::Fcc)), 1.0);  // min(dx, 2 dy, hypot(dx/2, dy))
    BlockDef flat = gridBlock(BlockDef::Lattice::Fcc);
    flat.grid = {1.0, 0.4};
    EXPECT_EQ(nearestSiteDistance(flat), std::hypot(0.5, 0.4));
    flat.grid = {1.0, 0.2};
    EXPECT_EQ(nearestSiteDistance(flat), 0.4);
    EXPECT_NEAR(nearestSiteDistance(gridBlock(BlockDef::Lattice::Rect)), 0.9, 1e-15);
    // A count cap and an explicit origin.
    BlockDef capped = gridBlock(BlockDef::Lattice::Rect);
    capped.count = 5;
    capped.origin = Vec2{0.25, 0.25};
    const auto c = generateParticles(sceneWith(capped), {"g"}, d);
    ASSERT_EQ(c.particles.size(), 5u);
    EXPECT_DOUBLE_EQ(c.particles[4].position.x, 0.25);
    EXPECT_DOUBLE_EQ(c.particles[4].position.y, 1.15);
    EXPECT_TRUE(d.empty());
    EXPECT_GE(latticeSiteEstimate(gridBlock(BlockDef::Lattice::Fcc)), 12.0);
}

TEST(Generate, JitterStaysInItsBoxAndFollowsTheSeed) {
    for (const auto jitter : {BlockDef::Jitter::Equal, BlockDef::Jitter::Gauss}) {
        for (const Real fraction : {1.0, 0.3}) {
            BlockDef b = gridBlock(BlockDef::Lattice::Fcc);
            b.xmax = 40;
            b.ymax = 30;
            b.radius.value = 0.01;
            Diagnostics d;
            const auto plain = generateParticles(sceneWith(b), {"g"}, d);
            b.jitter = jitter;
            b.jitterFraction = fraction;
            const auto g = generateParticles(sceneWith(b), {"g"}, d);
            ASSERT_EQ(g.particles.size(), plain.particles.size());
            Real maxX = 0, maxY = 0, sumX = 0, sumX2 = 0;
            for (std::size_t k = 0; k < g.particles.size(); ++k) {
                const Vec2 shift = g.particles[k].position - plain.particles[k].position;
                maxX = std::max(maxX, std::abs(shift.x));
                maxY = std::max(maxY, std::abs(shift.y));
                sumX += shift.x;
                sumX2 += shift.x * shift.x;
            }
            EXPECT_LE(maxX, 0.5 * fraction * 1.0);
            EXPECT_LE(maxY, 0.5 * fraction * 0.9);
            EXPECT_GT(maxX, 0.2 * fraction);  // it does move
            const Real n = static_cast<Real>(g.particles.size());
            const Real sigma = std::sqrt(sumX2 / n);
            // equal: sigma = f dx / sqrt(12); gauss: f dx / 10 (documented)
            const Real expected =
                jitter == BlockDef::Jitter::Equal ? fraction / std::sqrt(12.0) : fraction / 10;
            EXPECT_NEAR(sigma, expected, 0.1 * expected);
            EXPECT_NEAR(sumX / n, 0.0, 4 * expected / std::sqrt(n));
            const auto again = generateParticles(sceneWith(b), {"g"}, d);
            EXPECT_EQ(again.particles[123].position, g.particles[123].position);
            SceneDef other = sceneWith(b);
            other.run.seed = 43;
            EXPECT_NE(generateParticles(other, {"g"}, d).particles[123].position, g.particles[123].position);
        }
    }
}

TEST(Generate, VelocityRangesAreRespected) {
    BlockDef b = gridBlock(BlockDef::Lattice::Rect);
    b.xmax = 60;
    b.ymax = 60;
    b.velocity = {0.0, -1.0};
    b.directionRange = {0.5, 1.5};
    b.speedRange = {2.0, 3.0};
    Diagnostics d;
    const auto g = generateParticles(sceneWith(b), {"g"}, d);
    ASSERT_GT(g.particles.size(), 3000u);
    Real sumAngle = 0, sumSpeed = 0;
    for (const auto& p : g.particles) {
        const Vec2 v = p.velocity - b.velocity;  // the range velocity is added to `velocity`
        const Real speed = norm(v), angle = std::atan2(v.y, v.x);
        EXPECT_GE(speed, 2.0 - 1e-12);
        EXPECT_LE(speed, 3.0 + 1e-12);
        EXPECT_GE(angle, 0.5 - 1e-12);
        EXPECT_LE(angle, 1.5 + 1e-12);
        sumAngle += angle;
        sumSpeed += speed;
    }
    const Real n = static_cast<Real>(g.particles.size());
    EXPECT_NEAR(sumAngle / n, 1.0, 0.02);  // uniform: sd of the mean 1/sqrt(12 n)
    EXPECT_NEAR(sumSpeed / n, 2.5, 0.02);
    // The default range [0, 0] leaves velocities and every other draw untouched.
    BlockDef plain = block(BlockDef::Lattice::Hexagonal);
    plain.temperature = 1.0;
    const auto a = generateParticles(sceneWith(plain), {"g"}, d);
    plain.directionRange = {0.0, 1.0};
    const auto c = generateParticles(sceneWith(plain), {"g"}, d);
    for (std::size_t k = 0; k < a.particles.size(); ++k)
        EXPECT_EQ(a.particles[k].velocity, c.particles[k].velocity);
    EXPECT_TRUE(d.empty());
}

TEST(Generate, HeapOfSquaresMatchesHandCount) {
    // Squares 1 x 1, hexagonal, x_range [0, 6], tan(psi) = 1.5. Row centres y = 0.5 + k; the
    // allowed |x - 3| is 3 - y / 1.5: 2.67, 2, 1.33, 0.67, 0. Even rows x = 3 + i, odd rows
    // x = 3.5 + i: 5 + 4 + 3 + 2 + 1 = 15 grains.
    HeapDef h = diskHeap(HeapDef::Stacking::Hexagonal, std::atan(1.5));
    h.radius = 0;
    h.size = {1.0, 1.0};
    Diagnostics d;
    const auto g = generateParticles(sceneWithHeap(h), {"g"}, d);
    ASSERT_TRUE(d.empty());
    ASSERT_EQ(g.particles.size(), 15u);
    EXPECT_NE(g.particles[0].shape, kDiskShape);
    EXPECT_DOUBLE_EQ(g.particles[0].position.x, 1.0);
    EXPECT_DOUBLE_EQ(g.particles[0].position.y, 0.5);
    EXPECT_DOUBLE_EQ(g.particles[5].position.x, 1.5);
    EXPECT_DOUBLE_EQ(g.particles[14].position.x, 3.0);
    EXPECT_DOUBLE_EQ(g.particles[14].position.y, 4.5);
    for (std::size_t i = 0; i < g.particles.size(); ++i)
        for (std::size_t j = i + 1; j < g.particles.size(); ++j) {  // axis-aligned: separated along x or y
            const Vec2 s = g.particles[i].position - g.particles[j].position;
            EXPECT_TRUE(std::abs(s.x) >= 1 - 1e-12 || std::abs(s.y) >= 1 - 1e-12) << i << " " << j;
        }
    // Rectangular stacking: columns x = 3 + i; rows y = 0.5 + k with |i| <= 3 - y / 1.5:
    // 5 + 5 + 3 + 1 + 1 = 15, each grain right above another.
    h.stacking = HeapDef::Stacking::Rectangular;
    const auto columns = generateParticles(sceneWithHeap(h), {"g"}, d);
    ASSERT_EQ(columns.particles.size(), 15u);
    EXPECT_DOUBLE_EQ(columns.particles[9].position.x, 5.0);
    EXPECT_DOUBLE_EQ(columns.particles[10].position.x, 2.0);
    EXPECT_DOUBLE_EQ(columns.particles[14].position.y, 4.5);
}

TEST(Generate, HexagonalDiskHeapProfileAndContacts) {
    for (const Real slope : {0.4, std::atan(1.5), 1.1}) {  // 1.1 rad: close to arctan 2 = 1.107
        SCOPED_TRACE(slope);
        HeapDef h = diskHeap(HeapDef::Stacking::Hexagonal, slope);
        h.xRight = 30;
        h.base = 0.25;
        h.gap = {0.05, 0.0};
        Diagnostics d;
        const auto g = generateParticles(sceneWithHeap(h), {"g"}, d);
        ASSERT_TRUE(d.empty());
        ASSERT_GT(g.particles.size(), 20u);
        EXPECT_DOUBLE_EQ(g.particles[0].position.y, 0.75);  // the bottom row stands on the base
        const Real q = std::sqrt(1.0 - 0.25 * 1.05 * 1.05);
        for (std::size_t i = 0; i < g.particles.size(); ++i) {
            const Vec2 c = g.particles[i].position;
            EXPECT_LE(c.y, slopeLine(h, c.x) + 1e-9) << i;
            EXPECT_GE(c.x, h.xLeft);
            EXPECT_LE(c.x, h.xRight);
            int below = 0;
            for (std::size_t j = 0; j < g.particles.size(); ++j) {
                if (j == i) continue;
                const Real dist = norm(c - g.particles[j].position);
                EXPECT_GE(dist, 1.0 - 1e-12) << i << " " << j;  // no start overlaps
                if (g.particles[j].position.y < c.y - 0.5 * q && dist < 1.0 + 1e-12) ++below;
            }
            if (c.y > 1.0) {
                EXPECT_EQ(below, 2) << "grain " << i << " must rest on two grains";
            }
        }
        // Symmetric about the middle of x_range.
        Real sumX = 0;
        for (const auto& p : g.particles) sumX += p.position.x;
        EXPECT_NEAR(sumX / static_cast<Real>(g.particles.size()), 15.0, 1e-9);
    }
    // The hand-computed small heap: radius 0.5, no gaps, x_range [0, 6], tan(psi) = 1.5, rows
    // sqrt(3)/2 apart: |x - 3| <= 3 - y / 1.5 allows 5, 4, 3, 2, 1 grains in rows 0..4.
    Diagnostics d;
    EXPECT_EQ(
        generateParticles(sceneWithHeap(diskHeap(HeapDef::Stacking::Hexagonal, std::atan(1.5))), {"g"}, d)
            .particles.size(),
        15u);
    EXPECT_GE(heapSiteEstimate(diskHeap(HeapDef::Stacking::Hexagonal, std::atan(1.5)), {}), 15.0);
}

TEST(Generate, HeapIdsFollowTheBlocks) {
    SceneDef s = sceneWithHeap(diskHeap(HeapDef::Stacking::Rectangular, 0.8));
    s.blocks.push_back(block(BlockDef::Lattice::Square));
    Diagnostics d;
    const auto g = generateParticles(s, {"g"}, d);
    ASSERT_GT(g.particles.size(), 100u);
    EXPECT_EQ(g.particles[99].origin, 0u);   // the block's 100 sites come first
    EXPECT_EQ(g.particles[100].origin, 1u);  // then the heap
    EXPECT_DOUBLE_EQ(g.particles[100].position.y, 0.5);
}
