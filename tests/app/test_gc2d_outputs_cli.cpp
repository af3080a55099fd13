// SPDX-License-Identifier: MIT
// gc2d's legacy files through `granulab run` (app/dem/gc2d_files.hpp; gc2d spec 9.1 naming and
// lock file, 9.5 column layouts): a hand-computed two-grain scene checked column by column at
// t = 0, the lock file's refusal and its override, a resumed run that appends without
// duplicates, a gsi scene named after its BASENAME, and the refusal of disks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "../support.hpp"
#include "io/gc2d_outputs.hpp"

using namespace granulab;
namespace fs = std::filesystem;

namespace {

/// The rows of a gc2d file as numbers.
std::vector<std::vector<double>> rowsOf(const fs::path& p) {
    std::vector<std::vector<double>> rows;
    const std::string text = test::readText(p);
    std::size_t from = 0;
    for (std::size_t nl = text.find('\n'); nl != std::string::npos; nl = text.find('\n', from)) {
        rows.push_back(io::gc2dFields(std::string_view(text).substr(from, nl - from)));
        from = nl + 1;
    }
    return rows;
}

/// The row whose first two fields are (id1, id2); fails the test if there is not exactly one.
std::vector<double> rowOf(const std::vector<std::vector<double>>& rows, double id1, double id2) {
    std::vector<double> found;
    int n = 0;
    for (const auto& r : rows)
        if (r.size() >= 2 && r[0] == id1 && r[1] == id2) {
            found = r;
            ++n;
        }
    EXPECT_EQ(n, 1) << "rows " << id1 << " " << id2;
    return found;
}

// Two squares touching face to face with a tiny overlap, under gravity, the gc2d area law with
// no damping and no friction, and one wall far below (not touching).
//
//   grain 0 (gc2d id 1): unit square, side 1, centre (0, 0), velocity (1, 2), omega 0.5 (ccw)
//   grain 1 (gc2d id 2): square of side 2, centre (x2, 0), angle pi/2 (the same square), at rest
//   wall 0 (gc2d id 0):  the segment (-5, -10) - (5, -10)
//
// w = 2^-31 m: x2 = 1.5 - w = 1.4999999995343387 (exact in binary), so the big square's left face
// is at x = 0.5 - w and the squares overlap in the strip 0.5 - w <= x <= 0.5, |y| <= 0.5. Start
// overlaps are refused, but an overlap of at most 1e-9 of the smaller area counts as touching
// (dem/scene_setup.cpp); w = 4.66e-10 is below that.
//
// By hand (gc2d spec 3.1-3.2, F_n = E A / l):
//   overlap area       A = w * 1 = w                                   [m^2]
//   boundary crossings c1 = (0.5 - w, -0.5), c2 = (0.5 - w, 0.5)       (the unit square's top and
//                      bottom edges cross the big square's left face)
//   contact point      s = (c1 + c2) / 2 = (0.5 - w, 0)
//   lever arms         r0 = |s - x0| = 0.5 - w, r1 = |s - x1| = 1
//   l = r0 r1 / (r0 + r1) = (0.5 - w) / (1.5 - w)                      (about 1/3 m)
//   E = 100 * 2^31 N/m, so E A = 100 N and F_n = 100 (1.5 - w) / (0.5 - w) = 300 N (to 1e-9)
//   the normal pushes grain 0 towards -x: F on grain 0 = (-300, 0) N, on grain 1 (+300, 0) N
//   masses (density 10 kg/m^2): m0 = 10 * 1 = 10 kg, m1 = 10 * 4 = 40 kg
//   weights (g = (0, -10) m/s^2): (0, -100) N and (0, -400) N
//   accelerations: a0 = (-300, -100) / 10 = (-30, -10), a1 = (300, -400) / 40 = (7.5, -10) m/s^2
//   torques: the force acts along the lever arms (through both centroids): alpha = 0
//   gpf angles clockwise: grain 1's pi/2 is written -pi/2, grain 0's omega 0.5 is written -0.5
constexpr const char* kPairScene = R"(
[run]
end_time = 2.0e-8

[dem]
dt = 1.0e-8
gravity = [0.0, -10.0]

[[material]]
name = "grain"
density = 10.0

[[material]]
name = "floor"

[[shape]]
name = "unit"
kind = "polygon"
corners = [[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]

[[shape]]
name = "big"
kind = "polygon"
corners = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]

[[contact]]
materials = ["grain", "*"]
normal = "area"
E = 214748364800.0
damping = "gamma"
gamma = 0.0
tangential = "gc2d"
mu = 0.0

[[particle]]
shape = "unit"
position = [0.0, 0.0]
velocity = [1.0, 2.0]
omega = 0.5
material = "grain"

[[particle]]
shape = "big"
position = [1.4999999995343387, 0.0]
angle = 1.5707963267948966
material = "grain"

[[wall]]
name = "floor"
points = [[-5.0, -10.0], [5.0, -10.0]]
material = "floor"

[output]
gc2d = true
gc2d_basename = "pair"
gc2d_line_interval = 1.0e-8
snapshot_interval = 0.0
)";

constexpr double kW = 4.656612873077393e-10;  // 2^-31 m
constexpr double kX2 = 1.4999999995343387;    // 1.5 - w

}  // namespace

TEST(Cli, Gc2dOutputsTwoGrainSceneColumnsMatchTheHandComputation) {
    test::ScratchDir tmp;
    test::writeText(tmp.path / "pair.toml", kPairScene);
    const auto run = test::runGranulab("run pair.toml --out out -q", tmp.path, 120);
    ASSERT_EQ(run.status, 0) << run.output;
    const fs::path out = tmp.path / "out";
    for (const char* f : {"pair.glk", "pair.ggf", "pair.0001.gff", "pair.0001.gpf", "pair.0002.gff",
                          "pair.0002.gpf", "pair.gtf", "pair.gpl", "pair.ps"})
        EXPECT_TRUE(fs::exists(out / f)) << f;
    EXPECT_EQ(fs::file_size(out / "pair.glk"), 0u);  // the lock is empty
    EXPECT_EQ(test::readText(out / "pair.ps").rfind("%!PS", 0), 0u);

    // ggf: the wall, then the grains; 3 + 2 * 64 = 131 columns; body frame (centroid at the
    // origin, angle 0): the wall's segment about its midpoint (0, -10), the squares' corners.
    const auto ggf = rowsOf(out / "pair.ggf");
    ASSERT_EQ(ggf.size(), 3u);
    for (const auto& r : ggf) EXPECT_EQ(r.size(), 131u);
    const auto expectOutline = [](const std::vector<double>& r, double id, double type,
                                  const std::vector<Vec2>& corners) {
        EXPECT_EQ(r[0], id);
        EXPECT_EQ(r[1], type);
        ASSERT_EQ(r[2], static_cast<double>(corners.size()));
        for (std::size_t k = 0; k < 64; ++k) {
            EXPECT_NEAR(r[3 + k], k < corners.size() ? corners[k].x : 0.0, 1e-15) << id << " x" << k;
            EXPECT_NEAR(r[3 + 64 + k], k < corners.size() ? corners[k].y : 0.0, 1e-15) << id << " y" << k;
        }
    };
    expectOutline(ggf[0], 0, 2, {{-5, 0}, {5, 0}});
    expectOutline(ggf[1], 1, 0, {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}});
    expectOutline(ggf[2], 2, 0, {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});

    // gff of snapshot 0 (t = 0): the contact in both orientations, then gravity (id2 = -1).
    const double fn = 100 * (1.5 - kW) / (0.5 - kW);  // E A / l = 300 N
    const double tolF = 1e-5 * fn;  // the overlap strip is 4.7e-10 m: corners round at 1e-16 m
    const auto gff = rowsOf(out / "pair.0001.gff");
    ASSERT_EQ(gff.size(), 4u);
    for (const auto& r : gff) EXPECT_EQ(r.size(), 8u);
    const auto c12 = rowOf(gff, 1, 2), c21 = rowOf(gff, 2, 1);
    ASSERT_EQ(c12.size(), 8u);
    ASSERT_EQ(c21.size(), 8u);
    EXPECT_EQ(c12[2], 0.0);  // x_s, y_s: the centroid of id1
    EXPECT_EQ(c12[3], 0.0);
    EXPECT_EQ(c21[2], kX2);
    EXPECT_EQ(c21[3], 0.0);
    for (const auto* r : {&c12, &c21}) {  // x_f, y_f: the middle of the contact line
        EXPECT_NEAR((*r)[4], 0.5 - kW, 1e-14);
        EXPECT_NEAR((*r)[5], 0.0, 1e-14);
    }
    EXPECT_NEAR(c12[6], -fn, tolF);  // the force on id1
    EXPECT_NEAR(c12[7], 0.0, tolF);
    EXPECT_EQ(c21[6], -c12[6]);  // the same force, the other way round
    EXPECT_EQ(c21[7], -c12[7] + 0.0);
    const auto g1 = rowOf(gff, 1, -1), g2 = rowOf(gff, 2, -1);
    EXPECT_EQ(g1, (std::vector<double>{1, -1, 0, 0, 0, 0, 0, -100}));  // m g = 10 * (0, -10)
    EXPECT_EQ(g2, (std::vector<double>{2, -1, kX2, 0, kX2, 0, 0, -400}));

    // gpf of snapshot 0: id x y phi vx vy omega ax ay alpha; the wall first.
    const auto gpf = rowsOf(out / "pair.0001.gpf");
    ASSERT_EQ(gpf.size(), 3u);
    EXPECT_EQ(gpf[0], (std::vector<double>{0, 0, -10, 0, 0, 0, 0, 0, 0, 0}));
    const std::vector<double> p1 = gpf[1], p2 = gpf[2];
    ASSERT_EQ(p1.size(), 10u);
    ASSERT_EQ(p2.size(), 10u);
    EXPECT_EQ((std::vector<double>(p1.begin(), p1.begin() + 7)),
              (std::vector<double>{1, 0, 0, 0, 1, 2, -0.5}));
    EXPECT_NEAR(p1[7], -fn / 10, tolF / 10);  // ax = F / m0
    EXPECT_NEAR(p1[8], -10, 1e-12);           // ay = g
    EXPECT_NEAR(p1[9], 0, 1e-6);              // alpha: round-off torque only
    EXPECT_EQ(p2[0], 2);
    EXPECT_EQ(p2[1], kX2);
    EXPECT_EQ(p2[2], 0);
    EXPECT_EQ(p2[3], -1.5707963267948966);  // pi/2 counter-clockwise = -pi/2 clockwise
    EXPECT_EQ((std::vector<double>(p2.begin() + 4, p2.begin() + 7)), (std::vector<double>{0, 0, 0}));
    EXPECT_NEAR(p2[7], fn / 40, tolF / 40);
    EXPECT_NEAR(p2[8], -10, 1e-12);
    EXPECT_NEAR(p2[9], 0, 1e-6);

    // gtf: file number, time, g, 0.0, scale factor; one line per dump (t = 0 and the end).
    const auto gtf = rowsOf(out / "pair.gtf");
    ASSERT_EQ(gtf.size(), 2u);
    EXPECT_EQ(gtf[0], (std::vector<double>{1, 0, 10, 0, 1}));
    EXPECT_EQ(gtf[1][0], 2);
    EXPECT_EQ(gtf[1][1], 2e-8);
    EXPECT_EQ(test::readText(out / "pair.gtf").substr(0, 15), "1 0 10 0.0 1\n2 ");

    // gpl: t g, then id type x y vx vy for the wall and both grains, every 1e-8 s from t = 0.
    const auto gpl = rowsOf(out / "pair.gpl");
    ASSERT_EQ(gpl.size(), 3u);
    for (const auto& r : gpl) EXPECT_EQ(r.size(), 2u + 3u * 6u);
    EXPECT_EQ(gpl[0], (std::vector<double>{0, 10, 0, 2, 0, -10, 0, 0, 1, 0, 0, 0, 1, 2, 2, 0, kX2, 0, 0, 0}));
    EXPECT_EQ(gpl[1][0], 1e-8);
    EXPECT_EQ(gpl[2][0], 2e-8);
}

TEST(Cli, Gc2dOutputsLockFileRefusesUnlessOverwrittenOrIgnoredAndAResumeAppends) {
    test::ScratchDir tmp;
    test::writeText(tmp.path / "pair.toml", kPairScene);
    ASSERT_EQ(test::runGranulab("run pair.toml --out out -q", tmp.path, 120).status, 0);
    ASSERT_TRUE(fs::exists(tmp.path / "out" / "pair.glk"));

    const auto locked = test::runGranulab("run pair.toml --out out -q", tmp.path, 60);
    EXPECT_EQ(locked.status, 2) << locked.output;
    EXPECT_NE(locked.output.find("pair.glk"), std::string::npos) << locked.output;
    EXPECT_NE(locked.output.find("--ignore-lock"), std::string::npos) << locked.output;
    // --overwrite removes the earlier run's files, its lock among them (an explicit consent).
    for (const char* args :
         {"run pair.toml --out out -q --overwrite", "run pair.toml --out out -q --overwrite -l",
          "run pair.toml --out out -q --overwrite --ignore-lock"}) {
        const auto passed = test::runGranulab(args, tmp.path, 120);
        EXPECT_EQ(passed.status, 0) << args << "\n" << passed.output;
    }
    // Only the lock in an otherwise empty folder: --ignore-lock alone passes.
    fs::create_directories(tmp.path / "lonely");
    test::writeText(tmp.path / "lonely" / "pair.glk", "");
    EXPECT_EQ(test::runGranulab("run pair.toml --out lonely -q", tmp.path, 60).status, 2);
    EXPECT_EQ(test::runGranulab("run pair.toml --out lonely -q -l", tmp.path, 120).status, 0);

    // A resumed run into its own folder continues under its own lock and appends: no gtf, gpl
    // or ggf line twice.
    const auto resumed =
        test::runGranulab("run pair.toml --set run.end_time=4e-8 --resume out -q", tmp.path, 120);
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    const fs::path out = tmp.path / "out";
    EXPECT_EQ(rowsOf(out / "pair.ggf").size(), 3u);
    const auto gtf = rowsOf(out / "pair.gtf");
    ASSERT_EQ(gtf.size(), 3u);  // t = 0, 2e-8 (the first run's end), 4e-8
    for (std::size_t k = 0; k < gtf.size(); ++k) EXPECT_EQ(gtf[k][0], static_cast<double>(k + 1));
    EXPECT_EQ(gtf[2][1], 4e-8);
    EXPECT_TRUE(fs::exists(out / "pair.0003.gff"));
    EXPECT_TRUE(fs::exists(out / "pair.0003.gpf"));
    const auto gpl = rowsOf(out / "pair.gpl");
    ASSERT_EQ(gpl.size(), 5u);  // t = 0, 1, 2, 3, 4 e-8
    for (std::size_t k = 1; k < gpl.size(); ++k) EXPECT_GT(gpl[k][0], gpl[k - 1][0]);
}

TEST(Cli, Gc2dOutputsGsiSceneWritesFilesNamedAfterBasename) {
    test::ScratchDir tmp;
    // The pulled block of tests/data/gsi (a spring, a belt wall), 20 steps, a dump every 10 and
    // a gpl line every 5; BASENAME's folder part is dropped (the files go into --out).
    test::writeText(tmp.path / "pulled.gsi",
                    "PARAMETER v1.4\n\nDelta_T 1e-5\nTime 0 0.0002\nSteps_Data 10\nSteps_Dumpline 5\n"
                    "Basename runs/Pulled\n"
                    "PARTICLE\nCORNERS\n-0.005 -0.005\n0.005 -0.005\n0.005 0.005\n-0.005 0.005\nEND\n"
                    "COM 0 0.005\nDrag_K 200\nDrag_Fixing_Point 0.005 0\nDrag_Pulling_Point 0.01 0.005\n"
                    "Drag_Velocity 0.05\nDrag_Angle 0\nDrag_Time 0 1\n"
                    "WALL\nCORNERS\n-0.05 -0.01\n0.05 -0.01\n0.05 0\n-0.05 0\nEND\nVelocity 0.01 0\n"
                    "END_OF_FILE\n");
    const auto run = test::runGranulab("run pulled.gsi --out out -q", tmp.path, 120);
    ASSERT_EQ(run.status, 0) << run.output;
    const fs::path out = tmp.path / "out";
    for (const char* f : {"Pulled.glk", "Pulled.ggf", "Pulled.0001.gff", "Pulled.0002.gpf", "Pulled.0003.gff",
                          "Pulled.0003.gpf", "Pulled.gtf", "Pulled.gpl", "Pulled.ps"})
        EXPECT_TRUE(fs::exists(out / f)) << f;
    EXPECT_FALSE(fs::exists(out / "Pulled.0004.gff"));
    EXPECT_EQ(rowsOf(out / "Pulled.gtf").size(), 3u);  // steps 0, 10, 20
    EXPECT_EQ(rowsOf(out / "Pulled.gpl").size(), 5u);  // steps 0, 5, 10, 15, 20
    const auto ggf = rowsOf(out / "Pulled.ggf");
    ASSERT_EQ(ggf.size(), 2u);  // the wall body (id 0, type 2), the block (id 1, type 0)
    EXPECT_EQ(ggf[0][1], 2);
    EXPECT_EQ(ggf[0][2], 4);
    EXPECT_EQ(ggf[1][0], 1);
    EXPECT_EQ(ggf[1][1], 0);
    // The spring at t = 0: attached at the centroid (0, 0.005) + (0.005, 0), its free end at
    // (0.01, 0.005): F = 200 N/m * (0.005, 0) m = (1, 0) N, an id2 = -1 line at (0.005, 0.005);
    // gravity: m g = 5000 kg/m^2 * 1e-4 m^2 * 9.81 m/s^2 = 4.905 N down.
    const auto gff = rowsOf(out / "Pulled.0001.gff");
    int springs = 0, weights = 0;
    for (const auto& r : gff) {
        if (r[0] != 1 || r[1] != -1) continue;
        if (std::abs(r[6]) > 0.5) {
            ++springs;
            EXPECT_NEAR(r[4], 0.005, 1e-15);
            EXPECT_NEAR(r[5], 0.005, 1e-15);
            EXPECT_NEAR(r[6], 1.0, 1e-12);
            EXPECT_NEAR(r[7], 0.0, 1e-12);
        } else {
            ++weights;
            EXPECT_NEAR(r[7], -4.905, 1e-12);
        }
    }
    EXPECT_EQ(springs, 1);
    EXPECT_EQ(weights, 1);
}

TEST(Cli, Gc2dOutputsDiskScenesAreRefused) {
    test::ScratchDir tmp;
    const std::string disks = R"(
[run]
end_time = 0.01
[dem]
dt = 1e-4
[[material]]
name = "grain"
density = 1.0
[[contact]]
materials = ["grain", "*"]
kn = 1e4
[[particle]]
position = [0.0, 0.0]
radius = 0.01
material = "grain"
[output]
gc2d = true
)";
    test::writeText(tmp.path / "disks.toml", disks);
    const auto run = test::runGranulab("run disks.toml --out out -q", tmp.path, 60);
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_NE(run.output.find("polygons only"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("particle[0]"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(tmp.path / "out" / "default.glk"));
}
