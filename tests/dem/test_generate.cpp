// SPDX-License-Identifier: MIT
// Particle generation: lattice site counts and spacing, random placement without overlaps
// inside the region, truncated size distributions, thermal velocities (zero momentum, exact T).
#include <gtest/gtest.h>

#include <cmath>

#include "dem/generate.hpp"

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
