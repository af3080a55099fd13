// SPDX-License-Identifier: MIT
// The cohesive draining crater of gc2d spec 8.8 end to end, reduced for CI
// (examples/studies/crater/): a box 40 grain diameters wide, filled with 684 regular 15-gons
// (r = 1.5 mm, d = 3 mm) that settle behind a lid, then a bottom outlet 16 d wide opens.
//  * Without cohesion the box drains: the outlet removes grains in every 0.02 s of the first
//    0.1 s after opening and more than half of them within 0.3 s. The bounds are physical: 16 d
//    is three times the outlet width below which dry 2D packings jam (about 5 d), and Beverloo's
//    2D flow W = C rho_b sqrt(g) (D - k d)^(3/2) (C ~ 1, k ~ 2, docs/machines-examples.md) empties
//    the fill (23.5 kg per m depth) in ~0.2 s; the residual slopes at the dry repose angle hold
//    ~100 grains (two triangles 12 d wide at 30 deg), so more than half must have left.
//  * With k_coh = 2.5e5 N/m, above the thesis' clogging threshold of 2e5 N/m for 15-20 d outlets,
//    the flow stops: the removed count stays constant over the 0.04 s before the [[change]]
//    (1.6 times the 25 ms a grain needs to fall one diameter from rest) while resting grains
//    bridge the outlet (every diameter-wide strip over it holds one). In this model the whole
//    fill hangs over the outlet from the start (the measured clogging threshold is lower than
//    the thesis', see the study's README).
//  * After the [[change]] to cohesion 0 at 0.12 s the flow restarts: the dry packing cannot
//    arch over 16 d, so grains leave within the 0.08 s that remain.
// The dry run uses dt = 1e-5 s (stable without cohesion; granulab info advises 1.84e-5 s), the
// cohesive one the thesis' 2e-6 s (dt = 1e-5 s heats a cohesive fill). About 40 s on one core.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "../support.hpp"
#include "io/vtk_reader.hpp"

using namespace granulab;

namespace {

constexpr double kOutletHalf = 0.024;  // [m] the outlet spans x in [-24, 24] mm (16 d)
constexpr double kOpenAt = 0.06;       // [s] outlet opens (both scenes)
constexpr double kChangeAt = 0.12;     // [s] clog_reduced.toml: cohesion off

struct Row {
    double t = 0;
    long removed = 0;
    long particles = 0;
};

std::vector<Row> readSeries(const std::filesystem::path& dir) {
    std::vector<std::string> header;
    std::vector<Row> rows;
    for (const auto& r : test::readCsv(dir / "series.csv", header))
        rows.push_back({std::stod(r.at("time")), std::lround(std::stod(r.at("outlet_orifice_removed"))),
                        std::lround(std::stod(r.at("particles")))});
    return rows;
}

/// The removed count at the last series row at or before t.
long removedAt(const std::vector<Row>& rows, double t) {
    long n = 0;
    for (const auto& r : rows)
        if (r.t <= t + 1e-9) n = r.removed;
    return n;
}

std::string scene(const std::string& name) {
    return std::string(GRANULAB_SOURCE_DIR) + "/examples/studies/crater/" + name;
}

}  // namespace

TEST(Cli, CraterDrainsWithoutCohesion) {
    test::ScratchDir dir;
    const auto r = test::runGranulab(
        fmt::format("run '{}' -q --out out --set contact[0].cohesion=0 dem.dt=1e-5 run.end_time=0.36 "
                    "output.vtk=false",
                    scene("mono_reduced.toml")),
        dir.path, 300);
    ASSERT_EQ(r.status, 0) << r.output;
    const auto rows = readSeries(dir.path / "out");
    ASSERT_FALSE(rows.empty());
    const long total = rows.front().particles;
    EXPECT_EQ(removedAt(rows, kOpenAt), 0) << "grains left through the lid";
    for (double t = kOpenAt; t < kOpenAt + 0.1 - 1e-9; t += 0.02)
        EXPECT_GT(removedAt(rows, t + 0.02), removedAt(rows, t))
            << "no grain left in [" << t << ", " << t + 0.02 << "] s: the dry flow stopped";
    const long removed = rows.back().removed;
    std::printf("crater, dry: %ld of %ld grains removed by %.2f s\n", removed, total, rows.back().t);
    EXPECT_GT(2 * removed, total) << "less than half of the grains left in 0.3 s";
}

TEST(Cli, CraterClogsWithCohesionAndRestartsWhenItIsSwitchedOff) {
    test::ScratchDir dir;
    const auto r =
        test::runGranulab(fmt::format("run '{}' -q --out out", scene("clog_reduced.toml")), dir.path, 300);
    ASSERT_EQ(r.status, 0) << r.output;
    const auto rows = readSeries(dir.path / "out");
    ASSERT_FALSE(rows.empty());

    // The grains over the outlet when the cohesion is switched off (the snapshot at 0.12 s): a
    // plug bridges the outlet, so every diameter-wide strip above it holds a grain at rest
    // (slower than 1 cm/s: a grain falling from rest is faster after 1 ms). Cohesive cliffs
    // standing at the outlet's edges with an open gap between them would leave strips empty.
    std::string particles;
    for (const auto& e : io::readPvd((dir.path / "out" / "snapshots.pvd").string()))
        if (e.part == 0 && std::abs(e.time - kChangeAt) < 1e-6) particles = e.file;
    ASSERT_FALSE(particles.empty()) << "no snapshot at the change";
    const auto grains = io::readParticlesVtp((dir.path / "out" / particles).string());
    constexpr int kStrips = 16;  // the outlet is 16 d wide
    std::vector<int> strip(kStrips, 0);
    int over = 0;
    for (std::size_t i = 0; i < grains.size(); ++i) {
        if (std::abs(grains.x[i]) >= kOutletHalf || grains.y[i] <= 0 || grains.speed[i] > 0.01) continue;
        ++over;
        ++strip[std::min(kStrips - 1,
                         static_cast<int>((grains.x[i] + kOutletHalf) / (2 * kOutletHalf) * kStrips))];
    }
    const int covered =
        static_cast<int>(std::count_if(strip.begin(), strip.end(), [](int n) { return n > 0; }));

    const long atStall = removedAt(rows, kChangeAt - 0.04), atChange = removedAt(rows, kChangeAt);
    const long atEnd = rows.back().removed;
    std::printf(
        "crater, k_coh = 2.5e5 N/m: removed %ld at %.2f s, %ld at the change (%d grains at rest over the "
        "outlet), %ld at %.2f s\n",
        atStall, kChangeAt - 0.04, atChange, over, atEnd, rows.back().t);
    EXPECT_EQ(atChange, atStall) << "the cohesive fill did not clog";
    EXPECT_EQ(covered, kStrips) << "the resting grains over the outlet do not bridge it (" << covered
                                << " of " << kStrips << " strips): not a plug";
    EXPECT_GE(atEnd - atChange, 10) << "the flow did not restart after cohesion was switched off";
}
