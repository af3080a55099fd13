// SPDX-License-Identifier: MIT
// Validation: head-on disk-disk and disk-wall collisions against the closed form of the
// damped linear spring (docs/physics/contact-laws.md): restitution and contact time, relative
// error < 1e-3 at 50 steps per contact, for every damping convention.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "../support/dem_world_builder.hpp"

using namespace granulab;

namespace {

struct Closed {
    Real e, tc;
};

/// Closed form for meff, kn and damping coefficient c (unclipped linear law).
Closed closedForm(Real meff, Real kn, Real c) {
    const Real w0 = std::sqrt(kn / meff), rate = c / (2 * meff);
    const Real wd = std::sqrt(w0 * w0 - rate * rate);
    const Real tc = kPi / wd;
    return {std::exp(-rate * tc), tc};
}

struct Measured {
    Real e = 0, tc = 0;
};

/// A damping convention of the linear law: the [[contact]] damping key and its parameters.
struct Damping {
    std::string name;
    std::map<std::string, Real> params;
    Real c = 0;  ///< damping coefficient for meff [N s/m], set in the test
};

/// Runs a head-on collision along x; `wall` puts a wall at x = 0 instead of a second disk. The
/// scene is built in code (test::DemSceneBuilder), without scene text.
Measured collide(const Damping& damping, bool wall, Real dt) {
    const Real r = 0.5, v = 1.0;  // [m], [m/s]
    auto params = damping.params;
    params["kn"] = 1.0e4;
    test::DemSceneBuilder b(dt, 1.0);
    b.material("a", 1.0).contact("*", "*", "hooke", damping.name, params);
    if (wall)
        b.disk({0.6, 0.0}, {-1.0, 0.0}, 0.5, "a").wall({{0.0, -2.0}, {0.0, 2.0}}, "a");
    else
        b.disk({-0.6, 0.0}, {1.0, 0.0}, 0.5, "a").disk({0.6, 0.0}, {-1.0, 0.0}, 0.5, "a");
    dem::World w = b.world();
    const auto& s = w.store();
    auto slotOf = [&](ParticleId id) {
        for (std::size_t k = 0; k < s.size(); ++k)
            if (s.id[k] == id) return k;
        return std::size_t{0};
    };
    auto gap = [&] {
        if (wall) return s.x[slotOf(0)] - r;
        return s.x[slotOf(1)] - s.x[slotOf(0)] - 2 * r;
    };
    auto relSpeed = [&] {  // closing speed along x (positive when approaching)
        if (wall) return -s.vx[slotOf(0)];
        return s.vx[slotOf(0)] - s.vx[slotOf(1)];
    };
    const Real approach = wall ? v : 2 * v;
    Real tStart = -1, tEnd = -1;
    Real prevGap = gap(), prevTime = 0;
    for (int k = 0; k < 200000 && tEnd < 0; ++k) {
        w.step();
        const Real g = gap();
        if (tStart < 0 && g < 0) tStart = prevTime + prevGap / approach;  // free flight before: exact
        if (tStart >= 0 && g > 0) {
            w.step();  // one more free step to read the separation speed
            const Real vsep = -relSpeed();
            tEnd = w.time() - gap() / vsep;  // extrapolate free flight back to zero gap
        }
        prevGap = g;
        prevTime = w.time();
    }
    Measured m;
    m.e = -relSpeed() / approach;
    m.tc = tEnd - tStart;
    return m;
}

}  // namespace

class LinearCollision : public ::testing::TestWithParam<bool> {};

TEST_P(LinearCollision, RestitutionAndContactTimeMatchClosedForm) {
    const bool wall = GetParam();
    const Real m = kPi * 0.25;             // density 1, r = 0.5
    const Real meff = wall ? m : 0.5 * m;  // wall: infinite mass
    const Real kn = 1.0e4;
    const Real e = 0.7;
    const Real beta = -std::log(e) / std::sqrt(kPi * kPi + std::log(e) * std::log(e));
    const Damping cases[] = {
        {"none", {}, 0.0},
        {"restitution", {{"e", 0.7}}, 2 * beta * std::sqrt(meff * kn)},
        {"coefficient", {{"cn", 3.0}}, 3.0},
        {"lammps", {{"gamma_n", 20.0}}, 20.0 * meff},
    };
    for (const auto& c : cases) {
        const Closed ref = closedForm(meff, kn, c.c);
        const Measured got = collide(c, wall, ref.tc / 50);
        SCOPED_TRACE(c.name);
        std::printf("%s %-34s e %.6f (closed %.6f, rel %.1e)  tc %.6g (closed %.6g, rel %.1e)\n",
                    wall ? "wall" : "pair", c.name.c_str(), got.e, ref.e, std::abs(got.e - ref.e) / ref.e,
                    got.tc, ref.tc, std::abs(got.tc - ref.tc) / ref.tc);
        EXPECT_LT(std::abs(got.e - ref.e) / ref.e, 1e-3) << "e measured " << got.e << " expected " << ref.e;
        EXPECT_LT(std::abs(got.tc - ref.tc) / ref.tc, 1e-3)
            << "tc measured " << got.tc << " expected " << ref.tc;
    }
    // The restitution convention reproduces the requested e exactly (up to discretisation).
    const Measured got = collide({"restitution", {{"e", 0.7}}, 0.0}, wall,
                                 closedForm(meff, kn, 2 * beta * std::sqrt(meff * kn)).tc / 50);
    EXPECT_NEAR(got.e, 0.7, 0.7e-3);
}

INSTANTIATE_TEST_SUITE_P(DiskDiskAndDiskWall, LinearCollision, ::testing::Values(false, true),
                         [](const auto& info) {
                             return info.param ? std::string("DiskWall") : std::string("DiskDisk");
                         });
