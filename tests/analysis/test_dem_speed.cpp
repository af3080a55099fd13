// SPDX-License-Identifier: MIT
// The DEM pile analyses on a 1e5-grain snapshot (gc2d spec section 7): every analysis of
// dem_pressure, dem_force_stats, dem_coordination, dem_surface, dem_roughness and dem_persistence
// together in well under 2 s, as the analysis of a production snapshot needs.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "analysis/dem_coordination.hpp"
#include "analysis/dem_force_stats.hpp"
#include "analysis/dem_persistence.hpp"
#include "analysis/dem_pressure.hpp"
#include "analysis/dem_roughness.hpp"
#include "analysis/dem_surface.hpp"
#include "dem_frames.hpp"

using namespace granulab;
using namespace granulab::analysis;

TEST(DemAnalysis, HundredThousandGrainSnapshotIsFast) {
    const Real r = 0.005;
    const GrainFrame g = test::latticeHeap(35, 760, 20, r);
    ASSERT_GT(g.size(), 100000u);
    // Lattice contacts: the grain above in the same column and the grain to the right in the same row.
    ContactFrame c;
    WallSegments walls;
    test::addSegment(walls, 0, {-1, 0}, {10, 0});
    std::vector<std::size_t> columnStart{0};
    for (std::size_t i = 1; i < g.size(); ++i)
        if (g.x[i] != g.x[i - 1]) columnStart.push_back(i);
    columnStart.push_back(g.size());
    for (std::size_t col = 0; col + 1 < columnStart.size(); ++col) {
        const std::size_t begin = columnStart[col], end = columnStart[col + 1];
        for (std::size_t i = begin; i < end; ++i) {
            const Vec2 p{g.x[i], g.y[i]};
            if (i == begin) test::addContact(c, g.id[i], -1, 0, {p.x, 0}, {0, -1}, {0.1, 1});
            if (i + 1 < end) test::addPair(c, g.id[i], g.id[i + 1], {0.01, -1});
            const std::size_t right = columnStart[col + 1] + (i - begin);
            if (col + 2 < columnStart.size() && right < columnStart[col + 2])
                test::addPair(c, g.id[i], g.id[right], {-0.5, 0.02});
        }
    }
    ASSERT_GT(c.size(), 200000u);

    const auto start = std::chrono::steady_clock::now();
    const WallPressure floor = wallPressure(c, walls, {{0}});
    PressureProfileParams profileParams;
    profileParams.walls = {0};
    profileParams.halfWidth = 0.05;
    profileParams.step = 0.01;
    profileParams.scale = measurePileScale(g, c, walls, {0}, 1800, 9.81);
    const PressureProfile profile = pressureProfile(c, walls, profileParams);
    const ForceDirections directions = forceDirections(c);
    const ForceMagnitudes magnitudes = forceMagnitudes(c);
    const Coordination coordinationResult = coordination(g, c);
    const SurfaceProfile surface = surfaceProfile(g, {2 * r, {}, {}, SurfaceHeight::Centroid});
    const Repose repose = angleOfRepose(surface);
    RoughnessParams roughnessParams;
    roughnessParams.ranges = {{repose.left.xFrom, repose.left.xTo}, {repose.right.xFrom, repose.right.xTo}};
    roughnessParams.baseLength = repose.integralLeft.base;
    const RoughnessSpectrum roughness = roughnessSpectrum(surface, roughnessParams);
    const ContactPersistence persistence = contactPersistence(c, c, g, {Rect{0, 2, 0, 1}});
    const Real seconds = std::chrono::duration<Real>(std::chrono::steady_clock::now() - start).count();

    EXPECT_LT(seconds, 2.0);
    EXPECT_NEAR(floor.pressure, static_cast<Real>(columnStart.size() - 1) / 11,
                1e-9);                                                // 1 N per column, l = 11 m
    EXPECT_NEAR(profile.p[profile.p.size() / 2], 1 / (2 * r), 1e-6);  // 1 N per 2r
    EXPECT_EQ(directions.forces, 2 * c.size() - floor.contacts);
    EXPECT_GT(magnitudes.meanForce, 0);
    EXPECT_GT(coordinationResult.meanK, 3);
    EXPECT_NEAR(repose.meanAngleDeg, 35, 0.5);
    EXPECT_FALSE(roughness.power.empty());
    EXPECT_DOUBLE_EQ(persistence.fraction, 1);
}
