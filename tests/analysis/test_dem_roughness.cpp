// SPDX-License-Identifier: MIT
// Surface-roughness power spectrum (gc2d spec 7 item 11): the DFT power of known sines and
// Parseval, a sloped profile with a known ripple, and the average over two regions.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/dem_roughness.hpp"

using namespace granulab;
using namespace granulab::analysis;

namespace {

/// Profile h = slope x + 0.02 + amplitude sin(2 pi x / wavelength) on bins of dx from x0.
SurfaceProfile ripple(Real x0, Real dx, std::size_t n, Real slope, Real amplitude, Real wavelength) {
    SurfaceProfile p;
    p.binWidth = dx;
    for (std::size_t i = 0; i < n; ++i) {
        const Real x = x0 + dx * static_cast<Real>(i);
        p.x.push_back(x);
        p.h.push_back(slope * x + 0.02 + amplitude * std::sin(2 * kPi * (x - x0) / wavelength));
        p.grains.push_back(1);
    }
    return p;
}

}  // namespace

TEST(DemRoughness, PowerSpectrumOfKnownSines) {
    const std::size_t n = 64;
    std::vector<Real> s(n);
    Real meanSquare = 0;
    for (std::size_t j = 0; j < n; ++j) {
        const Real t = 2 * kPi * static_cast<Real>(j) / static_cast<Real>(n);
        s[j] = 0.3 * std::sin(5 * t) + 0.1 * std::cos(11 * t) + 0.05;
        meanSquare += s[j] * s[j] / static_cast<Real>(n);
    }
    const std::vector<Real> p = powerSpectrum(s);
    ASSERT_EQ(p.size(), 33u);
    Real sum = 0;
    for (std::size_t m = 0; m < p.size(); ++m) {
        sum += p[m];
        const Real expected = m == 0 ? 0.05 * 0.05 : m == 5 ? 0.09 / 2 : m == 11 ? 0.01 / 2 : 0;
        EXPECT_NEAR(p[m], expected, 1e-15) << "m " << m;
    }
    EXPECT_NEAR(sum, meanSquare, 1e-15);  // Parseval
    EXPECT_THROW(powerSpectrum({}), std::invalid_argument);
}

TEST(DemRoughness, SlopedProfileWithARipple) {
    // 400 bins of 5 mm, ripple of 2 mm amplitude and 0.1 m wavelength (20 periods), base l = 1.5 m.
    const SurfaceProfile p = ripple(0, 0.005, 400, 0.6, 0.002, 0.1);
    RoughnessParams params;
    params.ranges = {{0, 2}};
    params.baseLength = 1.5;
    const RoughnessSpectrum r = roughnessSpectrum(p, params);
    ASSERT_EQ(r.samples, 400u);
    ASSERT_EQ(r.k.size(), 200u);
    std::size_t peak = 0;
    for (std::size_t m = 0; m < r.power.size(); ++m)
        if (r.power[m] > r.power[peak]) peak = m;
    EXPECT_EQ(peak, 19u);                               // m = 20
    EXPECT_NEAR(r.k[peak], 2 * kPi * 1.5 / 0.1, 1e-9);  // k l = 2 pi l / wavelength
    EXPECT_NEAR(r.power[peak], 0.002 * 0.002 / 2, 0.03 * 0.002 * 0.002 / 2);
    EXPECT_NEAR(r.lines[0].slope, 0.6, 0.01);
    EXPECT_NEAR(r.rmsDeviation, 0.002 / std::sqrt(2.0), 1e-4);
    const Table t = toTable(r);
    EXPECT_EQ(t.name, "roughness_spectrum");
    EXPECT_EQ(t.columns[0].unit, "1/l");
    EXPECT_EQ(t.columns[1].unit, "m^2");
}

TEST(DemRoughness, AveragesOverTwoRegions) {
    // Region A: x in [0, 1) with amplitude 3 mm; region B: x in [2, 3.5) with amplitude 1 mm, both
    // 0.1 m wavelength; B is longer and is cut to A's 200 central bins (an integer number of periods).
    SurfaceProfile a = ripple(0, 0.005, 200, 0.5, 0.003, 0.1);
    const SurfaceProfile b = ripple(2, 0.005, 300, -0.7, 0.001, 0.1);
    SurfaceProfile both = a;
    for (Real x = a.x.back() + 0.005; x < 1.999; x += 0.005) {  // empty bins between the regions
        both.x.push_back(x);
        both.h.push_back(std::numeric_limits<Real>::quiet_NaN());
        both.grains.push_back(0);
    }
    both.x.insert(both.x.end(), b.x.begin(), b.x.end());
    both.h.insert(both.h.end(), b.h.begin(), b.h.end());
    both.grains.insert(both.grains.end(), b.grains.begin(), b.grains.end());
    RoughnessParams params;
    params.ranges = {{-0.001, 1.2}, {1.9, 3.6}};  // empty end bins are dropped
    params.baseLength = 1;
    const RoughnessSpectrum r = roughnessSpectrum(both, params);
    EXPECT_EQ(r.ranges, 2u);
    EXPECT_EQ(r.samples, 200u);
    EXPECT_EQ(r.interpolatedBins, 0u);
    const Real expected = (0.003 * 0.003 / 2 + 0.001 * 0.001 / 2) / 2;
    EXPECT_NEAR(r.power[9], expected, 0.05 * expected);  // m = 10 periods over 200 bins
    EXPECT_NEAR(r.lines[0].slope, 0.5, 0.02);
    EXPECT_NEAR(r.lines[1].slope, -0.7, 0.02);
    // Nonsense parameters and too little data.
    params.baseLength = 0;
    EXPECT_THROW(roughnessSpectrum(both, params), std::invalid_argument);
    params.baseLength = 1;
    params.ranges = {{1, 0}};
    EXPECT_THROW(roughnessSpectrum(both, params), std::invalid_argument);
    params.ranges = {};
    EXPECT_THROW(roughnessSpectrum(both, params), std::invalid_argument);
    params.ranges = {{1.2, 1.8}};
    const RoughnessSpectrum empty = roughnessSpectrum(both, params);
    EXPECT_TRUE(empty.power.empty());
    EXPECT_TRUE(std::isnan(empty.rmsDeviation));
    EXPECT_FALSE(empty.notes.empty());
}

TEST(DemRoughness, InteriorGapsAreInterpolated) {
    SurfaceProfile p = ripple(0, 0.01, 100, 0.3, 0.0, 1);
    p.h[40] = p.h[41] = std::numeric_limits<Real>::quiet_NaN();  // a straight line with a hole
    RoughnessParams params;
    params.ranges = {{0, 1}};
    params.baseLength = 1;
    const RoughnessSpectrum r = roughnessSpectrum(p, params);
    EXPECT_EQ(r.interpolatedBins, 2u);
    EXPECT_LT(r.rmsDeviation, 1e-12);
}
