// SPDX-License-Identifier: MIT
// Surface profile and angle of repose (gc2d spec 7 item 5): synthetic lattice heaps of disks with
// flank angles 20, 30 and 35 degrees give their construction angle within 0.5 degree by the
// top-centroid fit (5a) and the integral method (5b), with centroids and with grain tops; the
// integral method is exact on a right-triangle profile and ignores a constant offset.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "analysis/dem_surface.hpp"
#include "dem_frames.hpp"

using namespace granulab;
using namespace granulab::analysis;

namespace {

constexpr Real kR = 0.005;  // [m] disk radius of the synthetic heaps

/// Profile of a lattice heap with bins of one lattice spacing centred on the columns.
SurfaceProfile heapProfile(const GrainFrame& g, SurfaceHeight height) {
    Real lo = g.x[0], hi = g.x[0];
    for (Real x : g.x) {
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    }
    SurfaceParams params;
    params.binWidth = 2 * kR;
    params.xMin = lo - kR;  // column centres in the middle of their bins
    params.xMax = hi + kR;
    params.height = height;
    return surfaceProfile(g, params);
}

/// Profile h(x) given bin by bin.
SurfaceProfile handProfile(Real x0, Real dx, const std::vector<Real>& h) {
    SurfaceProfile p;
    p.binWidth = dx;
    p.h = h;
    p.meanRadius = dx / 2;
    for (std::size_t i = 0; i < h.size(); ++i) p.x.push_back(x0 + dx * static_cast<Real>(i));
    p.grains.assign(h.size(), 1);
    return p;
}

}  // namespace

class ReposeHeap : public ::testing::TestWithParam<Real> {};

TEST_P(ReposeHeap, BothMethodsGiveTheConstructionAngle) {
    const Real angle = GetParam();  // [deg]
    const GrainFrame g = test::latticeHeap(angle, 500, 40, kR);
    for (SurfaceHeight height : {SurfaceHeight::Centroid, SurfaceHeight::Top}) {
        const Repose r = angleOfRepose(heapProfile(g, height));
        const std::string what = height == SurfaceHeight::Top ? "tops" : "centroids";
        EXPECT_NEAR(r.left.angleDeg, angle, 0.5) << what;
        EXPECT_NEAR(r.right.angleDeg, angle, 0.5) << what;
        EXPECT_NEAR(r.meanAngleDeg, angle, 0.5) << what;
        EXPECT_GT(r.left.slope, 0) << what;
        EXPECT_LT(r.right.slope, 0) << what;
        EXPECT_NEAR(r.integralLeft.angleDeg, angle, 0.5) << what;
        EXPECT_NEAR(r.integralRight.angleDeg, angle, 0.5) << what;
        EXPECT_NEAR(r.apexX, 2.5, 0.05) << what;  // L/2 = 250 columns of 0.01 m
        // The feet: where the heap meets the floor layer, near x = 0 and x = L.
        EXPECT_NEAR(r.profile.x[r.footLeft], 0, 0.05) << what;
        EXPECT_NEAR(r.profile.x[r.footRight], 5, 0.05) << what;
        EXPECT_TRUE(r.notes.empty()) << what;
    }
}

INSTANTIATE_TEST_SUITE_P(Repose, ReposeHeap, ::testing::Values(20.0, 30.0, 35.0));

TEST(Repose, IntegralMethodIsExactOnARightTriangleWhateverTheOffset) {
    // Flat floor level at h = 0.7, rising with slope 0.4 from x = 2 to x = 7 (bins of 0.25 m).
    std::vector<Real> h;
    for (int i = 0; i <= 40; ++i) {
        const Real x = 0.25 * i;
        h.push_back(0.7 + 0.4 * std::clamp(x - 2, 0.0, 5.0));
    }
    const SurfaceProfile p = handProfile(0, 0.25, h);
    const IntegralRepose r = integralRepose(p, 2, 7);
    EXPECT_NEAR(r.tanPhi, 0.4, 1e-12);
    EXPECT_NEAR(r.base, 5, 1e-12);
    EXPECT_NEAR(r.rise, 2, 1e-12);
    EXPECT_NEAR(r.area, 5, 1e-12);
    EXPECT_NEAR(r.level, 0.7, 1e-12);
    std::vector<Real> shifted = h;
    for (Real& v : shifted) v -= 0.3;  // e.g. centroids instead of tops
    EXPECT_NEAR(integralRepose(handProfile(0, 0.25, shifted), 2, 7).tanPhi, 0.4, 1e-12);
    // Empty bins inside the range are bridged by the trapezoids (exact for a straight flank).
    std::vector<Real> holes = h;
    holes[13] = holes[17] = std::numeric_limits<Real>::quiet_NaN();
    EXPECT_NEAR(integralRepose(handProfile(0, 0.25, holes), 2, 7).tanPhi, 0.4, 1e-12);
    EXPECT_THROW(integralRepose(p, 7, 2), std::invalid_argument);
    const IntegralRepose tooFew = integralRepose(p, 2.01, 2.2);
    EXPECT_TRUE(std::isnan(tooFew.tanPhi));
}

TEST(Repose, ExplicitHalfPileRangesOfACrater) {
    // A V-shaped crater: region A descends at 30 deg, region B rises at 40 deg.
    const Real ta = std::tan(30 * kPi / 180), tb = std::tan(40 * kPi / 180);
    std::vector<Real> h;
    for (int i = 0; i <= 200; ++i) {
        const Real x = 0.01 * i;
        h.push_back(x < 1 ? 2 - ta * x : 2 - ta + tb * (x - 1));
    }
    const SurfaceProfile p = handProfile(0, 0.01, h);
    EXPECT_NEAR(integralRepose(p, 0.2, 1.0).angleDeg, 30, 1e-9);
    EXPECT_NEAR(integralRepose(p, 1.0, 1.8).angleDeg, 40, 1e-9);
}

TEST(Repose, FitFollowsTheApexAndTheBand) {
    // A tent with flanks of slope +1 and -0.5 on a floor at h = 0; apex bin at x = 4.
    std::vector<Real> h;
    for (int i = 0; i <= 16; ++i) {
        const Real x = i;
        h.push_back(std::max(0.0, x <= 4 ? x - 1 : 3 - 0.5 * (x - 4)));
    }
    const SurfaceProfile p = handProfile(0, 1, h);
    const Repose r = angleOfRepose(p);
    EXPECT_EQ(r.apexFirst, 4u);
    EXPECT_NEAR(r.left.slope, 1, 1e-12);
    EXPECT_NEAR(r.right.slope, -0.5, 1e-12);
    EXPECT_NEAR(r.left.angleDeg, 45, 1e-9);
    EXPECT_EQ(r.footLeft, 1u);   // h = 0
    EXPECT_EQ(r.footRight, 9u);  // h = 0.5 <= 0 + the default tolerance (mean radius 0.5)
    // band 0.2..0.8 of 3: h in [0.6, 2.4] -> x = 2, 3 left; 6, 7, 8 right
    EXPECT_EQ(r.left.points, 2u);
    EXPECT_EQ(r.right.points, 3u);
    EXPECT_NEAR(r.integralLeft.tanPhi, 1, 1e-12);
    EXPECT_NEAR(r.integralRight.tanPhi, 0.5, 1e-12);
    const Table t = toTable(r);
    EXPECT_EQ(t.name, "repose_profile");
    ASSERT_EQ(t.columns.size(), 4u);
    EXPECT_EQ(t.columns[2].name, "fit_left");
    EXPECT_TRUE(std::isnan(t.columns[2].values[0]));
    EXPECT_NEAR(t.columns[2].values[3], 2, 1e-12);
    EXPECT_TRUE(std::isnan(t.columns[2].values[5]));
    EXPECT_NEAR(t.columns[3].values[6], 2, 1e-12);
    EXPECT_TRUE(std::isnan(t.columns[3].values[12]));
    EXPECT_EQ(t.notes[1], "repose_left_deg = 45 deg");
    // An explicit apex splits the flanks elsewhere.
    ReposeParams params;
    params.apexX = 6.2;
    EXPECT_EQ(angleOfRepose(p, params).apexFirst, 6u);
}

TEST(Repose, RejectsNonsenseAndReportsMissingData) {
    GrainFrame g;
    test::addDisk(g, 1, 0, 0, 0.1);
    EXPECT_THROW(surfaceProfile(g, {0.0, {}, {}, SurfaceHeight::Centroid}), std::invalid_argument);
    EXPECT_THROW(surfaceProfile(g, {0.1, 1.0, 0.0, SurfaceHeight::Centroid}), std::invalid_argument);
    const SurfaceProfile one = surfaceProfile(g, {0.1, {}, {}, SurfaceHeight::Top});
    ASSERT_EQ(one.h.size(), 1u);
    EXPECT_DOUBLE_EQ(one.h[0], 0.1);
    const Repose r = angleOfRepose(one);
    EXPECT_TRUE(std::isnan(r.meanAngleDeg));
    EXPECT_FALSE(r.notes.empty());
    ReposeParams band;
    band.bandLo = 0.8;
    band.bandHi = 0.2;
    EXPECT_THROW(angleOfRepose(one, band), std::invalid_argument);
    ReposeParams outside;
    outside.apexX = 50;
    const SurfaceProfile tent = handProfile(0, 1, {0, 1, 2, 1, 0});
    EXPECT_THROW(angleOfRepose(tent, outside), std::invalid_argument);
}
