// SPDX-License-Identifier: MIT
// gc2d's legacy data files, the pure writers (io/gc2d_outputs.hpp; gc2d spec 9.1 naming, 9.5
// column layouts, 2.1 clockwise angles): names, ggf width and padding, both orientations of every
// gff contact line, one-body lines, gpf signs, gtf and gpl lines, round-trip numbers, and what a
// resumed run keeps of an appended file.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "../support.hpp"
#include "io/gc2d_outputs.hpp"

using namespace granulab;

namespace {

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t from = 0;
    for (std::size_t nl = text.find('\n'); nl != std::string::npos; nl = text.find('\n', from)) {
        lines.push_back(text.substr(from, nl - from));
        from = nl + 1;
    }
    EXPECT_EQ(from, text.size()) << "every line ends with a newline";
    return lines;
}

/// Two grains (ids 4 and 7) and one wall: a frame as the adapter fills it.
analysis::GrainFrame twoGrains() {
    analysis::GrainFrame g;
    g.id = {4, 7};
    g.x = {1.0, 3.0};
    g.y = {2.0, 2.5};
    g.vx = {0.5, 0.0};
    g.vy = {-1.0, 0.0};
    g.omega = {2.0, 0.0};    // counter-clockwise
    g.angle = {0.25, -1.0};  // counter-clockwise
    g.mass = {2.0, 8.0};
    g.radius = {1.0, 1.0};
    g.speed = {1.0, 0.0};
    g.material = {0, 0};
    g.cornerStart = {0, 0, 0};
    return g;
}

io::Gc2dWalls oneWall() {
    io::Gc2dWalls w;
    w.centroid = {{0.0, -1.0}};
    w.angle = {0.5};
    w.velocity = {{0.25, 0.0}};
    w.omega = {0.0};
    return w;
}

}  // namespace

TEST(Gc2dOutputs, FileNamesFollowTheBasenameAndFourDigitNumbers) {
    EXPECT_EQ(io::gc2dFileName("foo-out", "ggf"), "foo-out.ggf");
    EXPECT_EQ(io::gc2dFileName("foo-out", "glk"), "foo-out.glk");
    EXPECT_EQ(io::gc2dFileName("foo-out", 1, "gff"), "foo-out.0001.gff");
    EXPECT_EQ(io::gc2dFileName("foo-out", 42, "gpf"), "foo-out.0042.gpf");
    EXPECT_EQ(io::gc2dFileName("foo-out", 12345, "gpf"), "foo-out.12345.gpf");  // past 9999: wider
}

TEST(Gc2dOutputs, GgfLineHasThreePlusTwoNmaxFieldsPaddedWithZeros) {
    const std::vector<Vec2> triangle = {{-1, -0.5}, {1, -0.5}, {0, 1}};
    const std::string line = io::ggfLine(5, io::kGc2dParticle, triangle);
    ASSERT_EQ(line.back(), '\n');
    const std::vector<double> f = io::gc2dFields(line);
    ASSERT_EQ(f.size(), 3u + 2u * 64u);  // 131 columns
    EXPECT_EQ(f[0], 5);
    EXPECT_EQ(f[1], 0);  // a particle
    EXPECT_EQ(f[2], 3);  // N
    // x_1..x_3, then zeros up to x_64; y_1..y_3 from field 3 + 64, then zeros.
    EXPECT_EQ(f[3], -1);
    EXPECT_EQ(f[4], 1);
    EXPECT_EQ(f[5], 0);
    for (std::size_t k = 6; k < 3 + 64; ++k) EXPECT_EQ(f[k], 0) << k;
    EXPECT_EQ(f[3 + 64], -0.5);
    EXPECT_EQ(f[3 + 65], -0.5);
    EXPECT_EQ(f[3 + 66], 1);
    for (std::size_t k = 3 + 67; k < f.size(); ++k) EXPECT_EQ(f[k], 0) << k;

    const std::vector<Vec2> segment = {{-5, 0}, {5, 0}};  // an open wall polyline
    const std::vector<double> w = io::gc2dFields(io::ggfLine(0, io::kGc2dWall, segment));
    EXPECT_EQ(w[1], 2);
    EXPECT_EQ(w[2], 2);
}

TEST(Gc2dOutputs, GgfWidensBeyondSixtyFourCornersOnlyWhenAsked) {
    std::vector<Vec2> many(70, Vec2{1, 2});
    EXPECT_THROW(io::ggfLine(1, 0, many), std::invalid_argument);  // N_max = 64
    EXPECT_EQ(io::gc2dOutlineWidth(8), 64u);
    EXPECT_EQ(io::gc2dOutlineWidth(70), 70u);
    const std::vector<double> f = io::gc2dFields(io::ggfLine(1, 0, many, io::gc2dOutlineWidth(70)));
    EXPECT_EQ(f.size(), 3u + 2u * 70u);
    EXPECT_EQ(f[2], 70);
}

TEST(Gc2dOutputs, NumbersRoundTripExactly) {
    const double awkward[] = {0.1 + 0.2, 1.0 / 3.0, 6.02214076e23, -2.5e-300, 1.4999999995343387};
    std::vector<Vec2> corners;
    for (const double v : awkward) corners.push_back({v, -v});
    const std::vector<double> f = io::gc2dFields(io::ggfLine(9, 0, corners));
    for (std::size_t k = 0; k < corners.size(); ++k) {
        EXPECT_EQ(f[3 + k], awkward[k]);
        EXPECT_EQ(f[3 + 64 + k], -awkward[k]);
    }
}

TEST(Gc2dOutputs, GpfWritesWallsFirstAndAnglesClockwise) {
    const io::Gc2dIds ids{1};  // one wall: grains are 1 + granulab id
    const analysis::GrainFrame g = twoGrains();
    io::GrainAccelerations acc;
    acc.ax = {-30, 7.5};
    acc.ay = {-10, -10};
    acc.alpha = {0.75, 0.0};  // counter-clockwise
    const std::vector<std::string> lines = splitLines(io::gpfText(ids, oneWall(), g, acc));
    ASSERT_EQ(lines.size(), 3u);
    // id x y phi vx vy omega ax ay alpha; phi, omega and alpha clockwise.
    EXPECT_EQ(lines[0], "0 0 -1 -0.5 0.25 0 0 0 0 0");
    EXPECT_EQ(lines[1], "5 1 2 -0.25 0.5 -1 -2 -30 -10 -0.75");
    EXPECT_EQ(lines[2], "8 3 2.5 1 0 0 0 7.5 -10 0");  // no "-0": a zero stays 0
}

TEST(Gc2dOutputs, GffWritesEveryContactInBothOrientationsAndOneBodyForces) {
    const io::Gc2dIds ids{1};
    const analysis::GrainFrame g = twoGrains();
    analysis::ContactFrame c;
    const auto add = [&](std::int64_t a, std::int64_t b, std::int32_t wall, Vec2 p, Vec2 f) {
        c.a.push_back(a);
        c.b.push_back(b);
        c.wall.push_back(wall);
        c.px.push_back(p.x);
        c.py.push_back(p.y);
        c.fx.push_back(f.x);
        c.fy.push_back(f.y);
        for (auto* col : {&c.nx, &c.ny, &c.fn, &c.ft, &c.depth, &c.area, &c.length}) col->push_back(0);
    };
    add(4, 7, -1, {2, 2.25}, {-3, 0.5});  // grain 4 <- grain 7
    add(7, -1, 0, {3, 1.5}, {0, 6});      // grain 7 <- wall 0
    const std::vector<io::OneBodyForce> oneBody = {{4, {1, 2}, {0, -20}}, {7, {3.5, 2.5}, {1, 0}}};
    const std::vector<std::string> lines = splitLines(io::gffText(ids, oneWall(), g, c, oneBody));
    ASSERT_EQ(lines.size(), 6u);
    // id1 id2 x_s y_s x_f y_f f_x f_y: (x_s, y_s) the centroid of id1, f the force on id1.
    EXPECT_EQ(lines[0], "5 8 1 2 2 2.25 -3 0.5");
    EXPECT_EQ(lines[1], "8 5 3 2.5 2 2.25 3 -0.5");
    EXPECT_EQ(lines[2], "8 0 3 2.5 3 1.5 0 6");
    EXPECT_EQ(lines[3], "0 8 0 -1 3 1.5 0 -6");     // the wall's line, from its centroid
    EXPECT_EQ(lines[4], "5 -1 1 2 1 2 0 -20");      // gravity at the centroid
    EXPECT_EQ(lines[5], "8 -1 3 2.5 3.5 2.5 1 0");  // a spring at its attachment point

    const std::vector<io::OneBodyForce> stranger = {{99, {0, 0}, {1, 1}}};
    EXPECT_THROW(io::gffText(ids, oneWall(), g, analysis::ContactFrame{}, stranger), std::invalid_argument);
}

TEST(Gc2dOutputs, GtfAndGplLines) {
    EXPECT_EQ(io::gtfLine(3, 0.5, 9.81, 1.0), "3 0.5 9.81 0.0 1\n");
    const io::Gc2dIds ids{1};
    // t g, then id type x y vx vy for the wall (type 2) and the grains (type 0).
    EXPECT_EQ(io::gplLine(ids, 0.125, 9.81, oneWall(), twoGrains()),
              "0.125 9.81 0 2 0 -1 0.25 0 5 0 1 2 0.5 -1 8 0 3 2.5 0 0\n");
}

TEST(Gc2dOutputs, OutlineCentroid) {
    const std::vector<Vec2> triangle = {{0, 0}, {3, 0}, {0, 3}};
    const Vec2 c = io::outlineCentroid(triangle, true);
    EXPECT_NEAR(c.x, 1.0, 1e-15);
    EXPECT_NEAR(c.y, 1.0, 1e-15);
    const std::vector<Vec2> polyline = {{0, 0}, {4, 0}, {4, 2}};  // open: the mean of the points
    const Vec2 m = io::outlineCentroid(polyline, false);
    EXPECT_NEAR(m.x, 8.0 / 3.0, 1e-15);
    EXPECT_NEAR(m.y, 2.0 / 3.0, 1e-15);
}

TEST(Gc2dOutputs, AResumedRunKeepsCompleteLinesUpToItsCheckpoint) {
    const test::ScratchDir tmp;
    const std::string gtf = (tmp.path / "a.gtf").string();
    test::writeText(gtf, "1 0 9.81 0.0 1\n2 0.5 9.81 0.0 1\n3 1 9.81 0.0 1\n4 1.5 9.8");  // cut last line
    io::keepGc2dLines(gtf, [](std::string_view l) { return io::gc2dFields(l)[1] <= 0.5; });
    EXPECT_EQ(test::readText(gtf), "1 0 9.81 0.0 1\n2 0.5 9.81 0.0 1\n");
    io::keepGc2dLines((tmp.path / "none.gtf").string(), [](std::string_view) { return true; });
    EXPECT_FALSE(std::filesystem::exists(tmp.path / "none.gtf"));

    const io::Gc2dIds ids{2};
    const std::string ggf = (tmp.path / "a.ggf").string();
    const std::vector<Vec2> tri = {{-1, 0}, {1, 0}, {0, 1}};
    test::writeText(ggf, io::ggfLine(0, 2, tri) + io::ggfLine(1, 2, tri) + io::ggfLine(2, 0, tri) +
                             io::ggfLine(6, 0, tri));
    const io::GgfContents c = io::readGgfContents(ggf, ids);
    EXPECT_TRUE(c.exists);
    EXPECT_EQ(c.width, 64u);
    EXPECT_TRUE(c.walls);
    EXPECT_EQ(c.nextGrainId, 5);  // gc2d id 6 is granulab grain 4
    EXPECT_FALSE(io::readGgfContents((tmp.path / "none.ggf").string(), ids).exists);
}

TEST(Gc2dOutputs, AppenderTruncatesOrAppends) {
    const test::ScratchDir tmp;
    const std::string path = (tmp.path / "x.gpl").string();
    {
        io::Gc2dAppender a(path, false);
        a.write("1 2\n");
    }
    {
        io::Gc2dAppender a(path, true);
        a.write("3 4\n");
    }
    EXPECT_EQ(test::readText(path), "1 2\n3 4\n");
    {
        io::Gc2dAppender a(path, false);
        a.write("5\n");
    }
    EXPECT_EQ(test::readText(path), "5\n");
    EXPECT_THROW(io::Gc2dAppender((tmp.path / "no" / "such" / "x.ggf").string(), false), std::runtime_error);
}
