// SPDX-License-Identifier: MIT
// `granulab render`: a 3-disk scene with a floor, rendered and inspected pixel by pixel
// (existence, width, disk colours, white background, y axis pointing up); a polygon scene
// (filled true outlines in the speed colour); one colour scale over frames and --range; force
// lines from each centroid to the contact point; pressure and coordination from contacts;
// --view; option errors (exit 2); --movie without ffmpeg.
#include <cairo.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "../support.hpp"
#include "app/render.hpp"
#include "app/render_colors.hpp"
#include "app/render_forces.hpp"
#include "io/contact_file.hpp"
#include "io/vtk_writer.hpp"

namespace granulab::app {
namespace {

namespace fs = std::filesystem;

struct Rgb8 {
    int r, g, b;
};

/// Decoded PNG; pixel(x, y) with y down as in the file.
class Png {
public:
    explicit Png(const fs::path& p) : m_s(cairo_image_surface_create_from_png(p.c_str())) {}
    ~Png() { cairo_surface_destroy(m_s); }
    Png(const Png&) = delete;
    Png& operator=(const Png&) = delete;
    bool ok() const { return cairo_surface_status(m_s) == CAIRO_STATUS_SUCCESS; }
    int width() const { return cairo_image_surface_get_width(m_s); }
    int height() const { return cairo_image_surface_get_height(m_s); }
    Rgb8 pixel(int x, int y) const {
        cairo_surface_flush(m_s);
        const unsigned char* row =
            cairo_image_surface_get_data(m_s) + y * cairo_image_surface_get_stride(m_s);
        const std::uint32_t v = reinterpret_cast<const std::uint32_t*>(row)[x];
        const auto channel = [v](int shift) { return static_cast<int>((v >> shift) & 255); };
        return {channel(16), channel(8), channel(0)};
    }
    Rgb8 at(Vec2 px) const { return pixel(static_cast<int>(px.x), static_cast<int>(px.y)); }

private:
    cairo_surface_t* m_s;
};

bool isWhite(Rgb8 c) {
    return c.r == 255 && c.g == 255 && c.b == 255;
}
bool near(Rgb8 c, Rgb8 want, int tol = 12) {
    return std::abs(c.r - want.r) <= tol && std::abs(c.g - want.g) <= tol && std::abs(c.b - want.b) <= tol;
}

constexpr double kR = 0.1;  // [m] disk radius

/// Renders `dir` with the options `edit` sets on top of the defaults (quiet).
int render(const fs::path& dir, int width, void (*edit)(RenderOptions&) = nullptr) {
    RenderOptions o;
    o.outDir = dir.string();
    o.width = width;
    o.quiet = true;
    if (edit) edit(o);
    return renderCommand(o);
}

/// Slow disk A, fast disk B on a floor at y = 0.1, disk C (medium speed) highest.
void writeScene(const fs::path& dir) {
    model::WallSet walls;
    walls.addPolyline("floor", {{0.0, 0.1}, {1.0, 0.1}}, false, 0, {});
    io::PvdWriter pvd((dir / "snapshots.pvd").string());
    for (int k = 0; k < 2; ++k) {
        model::ParticleStore s;
        s.add(0, {0.2, 0.2}, {0.0, 0.0}, 0.0, 0.0, kR, 1.0, 1.0, 0);
        s.add(1, {0.5, 0.2}, {2.0, 0.0}, 0.0, 0.0, kR, 1.0, 1.0, 0);
        s.add(2, {0.35, 0.9 - 0.05 * k}, {0.0, -1.0}, 1.0, 0.0, kR, 1.0, 1.0, 0);
        io::writeSnapshot(dir.string(), k, s, model::ShapePool{}, walls, 0.5 * k, pvd);
    }
}

TEST(Render, DrawsDisksWithYUp) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    writeScene(dir);
    ASSERT_EQ(render(dir, 400), 0);
    EXPECT_TRUE(fs::exists(dir / "png" / "frame_000001.png"));

    const Png png(dir / "png" / "frame_000000.png");
    ASSERT_TRUE(png.ok());
    EXPECT_EQ(png.width(), 400);
    // Box of the scene: walls x 0..1, disks and floor y 0.1..1.0.
    const RenderLayout L = makeLayout({0.0, 0.1}, {1.0, 1.0}, 400);
    EXPECT_EQ(png.height(), L.height);
    EXPECT_LT(png.height(), 600);  // aspect 0.9 plus margins and header, not square-stretched

    // Sample half a radius above each centre (the angle mark points along +x).
    const Rgb8 slow = png.at(L.toPixel({0.2, 0.2 + 0.5 * kR}));
    const Rgb8 fast = png.at(L.toPixel({0.5, 0.2 + 0.5 * kR}));
    const Rgb8 mid = png.at(L.toPixel({0.35, 0.9 + 0.5 * kR}));
    EXPECT_FALSE(isWhite(png.at(L.toPixel({0.2, 0.2}))));
    EXPECT_TRUE(near(slow, {68, 1, 84})) << slow.r << "," << slow.g << "," << slow.b;     // viridis(0)
    EXPECT_TRUE(near(fast, {253, 231, 37})) << fast.r << "," << fast.g << "," << fast.b;  // viridis(1)
    EXPECT_TRUE(near(mid, {33, 145, 140}, 20)) << mid.r << "," << mid.g << "," << mid.b;  // viridis(.5)
    EXPECT_TRUE(isWhite(png.at(L.toPixel({0.9, 0.7}))));
    EXPECT_TRUE(isWhite(png.at(L.toPixel({0.8, 0.95}))));
    EXPECT_FALSE(isWhite(png.at(L.toPixel({0.95, 0.1}))));  // floor line

    // Orientation without the layout: the pixels of disk C's colour (scene area only) lie in the
    // upper half of the image, those of disk A's colour in the lower half.
    double sumC = 0, sumA = 0;
    int nC = 0, nA = 0;
    for (int y = L.headerHeight; y < png.height(); ++y)
        for (int x = 0; x < png.width(); ++x) {
            const Rgb8 c = png.pixel(x, y);
            if (near(c, mid, 3)) sumC += y, ++nC;
            if (near(c, slow, 3)) sumA += y, ++nA;
        }
    ASSERT_GT(nC, 100);
    ASSERT_GT(nA, 100);
    EXPECT_LT(sumC / nC, 0.5 * png.height());
    EXPECT_GT(sumA / nA, 0.5 * png.height());
}

/// Hexagon A at rest, fast hexagon B, slow square C (the speed scale is set by B).
constexpr const char* kPolygonScene = R"(
[run]
end_time = 0.01
[dem]
dt = 1.0e-6
[[material]]
name = "grain"
density = 2.0
[[shape]]
name = "hex"
kind = "regular"
corner_count = 6
radius = 0.001
[[shape]]
name = "square"
kind = "polygon"
corners = [[-0.001, -0.001], [0.001, -0.001], [0.001, 0.001], [-0.001, 0.001]]
[[particle]]
shape = "hex"
position = [0.0, 0.0]
angle = 0.3
material = "grain"
[[particle]]
shape = "hex"
position = [0.004, 0.0]
velocity = [0.5, 0.0]
angle = 1.0
material = "grain"
[[particle]]
shape = "square"
position = [0.002, 0.003]
velocity = [0.0, 0.25]
angle = 0.5
material = "grain"
[[contact]]
materials = ["*", "*"]
normal = "area"
E = 1e7
)";

/// Polygon area [m^2] (shoelace) of world corners.
double polygonArea(const std::vector<Vec2>& c) {
    double a2 = 0;
    for (std::size_t k = 0; k < c.size(); ++k) a2 += cross(c[k], c[(k + 1) % c.size()]);
    return 0.5 * a2;
}

TEST(Render, DrawsPolygonsAsFilledOutlines) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    const dem::World world = test::makeWorldFromToml(kPolygonScene);
    io::PvdWriter pvd((dir / "snapshots.pvd").string());
    io::writeSnapshot(dir.string(), 0, world.store(), world.shapes(), world.walls(), 0.0, pvd);
    ASSERT_EQ(render(dir, 800), 0);
    const Png png(dir / "png" / "frame_000000.png");
    ASSERT_TRUE(png.ok());

    // The layout the renderer used: the box of all polygon corners (no walls).
    const io::ParticleFrame f = io::readParticlesVtp((dir / "vtk" / "particles_000000.vtp").string());
    ASSERT_EQ(f.size(), 3u);
    Vec2 lo{1e9, 1e9}, hi{-1e9, -1e9};
    for (const Vec2 c : f.corners) {
        lo = {std::min(lo.x, c.x), std::min(lo.y, c.y)};
        hi = {std::max(hi.x, c.x), std::max(hi.y, c.y)};
    }
    const RenderLayout L = makeLayout(lo, hi, 800);
    EXPECT_EQ(png.height(), L.height);

    const auto cornersOf = [&](std::size_t p) {
        return std::vector<Vec2>(f.corners.begin() + static_cast<std::ptrdiff_t>(f.cornerStart[p]),
                                 f.corners.begin() + static_cast<std::ptrdiff_t>(f.cornerStart[p + 1]));
    };
    const Rgb8 rest = png.at(L.toPixel({f.x[0], f.y[0]}));
    const Rgb8 fast = png.at(L.toPixel({f.x[1], f.y[1]}));
    const Rgb8 half = png.at(L.toPixel({f.x[2], f.y[2]}));
    EXPECT_TRUE(near(rest, {68, 1, 84})) << rest.r << "," << rest.g << "," << rest.b;         // viridis(0)
    EXPECT_TRUE(near(fast, {253, 231, 37})) << fast.r << "," << fast.g << "," << fast.b;      // viridis(1)
    EXPECT_TRUE(near(half, {33, 145, 140}, 20)) << half.r << "," << half.g << "," << half.b;  // viridis(.5)

    for (std::size_t p = 0; p < f.size(); ++p) {
        ASSERT_TRUE(f.isPolygon(p));
        const std::vector<Vec2> c = cornersOf(p);
        const Vec2 centre{f.x[p], f.y[p]};
        // Just outside each edge's midpoint, still inside the circumcircle: white (true outline,
        // not the bounding circle).
        for (std::size_t k = 0; k < c.size(); ++k) {
            const Vec2 mid = (c[k] + c[(k + 1) % c.size()]) * 0.5;
            const Vec2 out =
                centre + (mid - centre) * (1.0 + 0.35 * (f.radius[p] / norm(mid - centre) - 1.0));
            ASSERT_LT(norm(out - centre), f.radius[p]);
            EXPECT_TRUE(isWhite(png.at(L.toPixel(out)))) << "polygon " << p << " edge " << k;
        }
    }
    // Pixels in the colour of the resting hexagon cover its area, not the circle's (2.6 vs 3.14 R^2).
    const std::vector<Vec2> hexA = cornersOf(0);
    const double hexPixels = polygonArea(hexA) * L.scale * L.scale;
    const double circlePixels = kPi * f.radius[0] * f.radius[0] * L.scale * L.scale;
    int n = 0;
    for (int y = L.headerHeight; y < png.height(); ++y)
        for (int x = 0; x < png.width(); ++x) n += near(png.pixel(x, y), rest, 3);
    EXPECT_GT(n, 0.85 * hexPixels);
    EXPECT_LT(n, 1.02 * hexPixels);
    EXPECT_LT(n, 0.9 * circlePixels);
}

TEST(Render, MissingFolderReturns2) {
    const test::ScratchDir scratch;
    const fs::path dir = scratch.path / "nothing";
    ::testing::internal::CaptureStderr();
    EXPECT_EQ(render(dir, 400), 2);
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("no snapshots.pvd"), std::string::npos) << err;
    EXPECT_NE(err.find("granulab run"), std::string::npos) << err;
}

TEST(Render, LayoutKeepsAspectAndBox) {
    const RenderLayout L = makeLayout({0.0, 0.0}, {1.0, 2.0}, 300);  // tall box
    EXPECT_EQ(L.width, 300);
    const Vec2 lo = L.toPixel({0.0, 0.0}), hi = L.toPixel({1.0, 2.0});
    EXPECT_NEAR((lo.y - hi.y) / (hi.x - lo.x), 2.0, 1e-12);  // equal scale, y up
    EXPECT_GT(lo.x, 0);
    EXPECT_LT(hi.x, L.width);
    EXPECT_GT(hi.y, L.headerHeight);
    EXPECT_LT(lo.y, L.height);
}

Rgb8 toRgb8(render::Rgb c) {
    return {static_cast<int>(std::lround(255 * c.r)), static_cast<int>(std::lround(255 * c.g)),
            static_cast<int>(std::lround(255 * c.b))};
}
std::string str(Rgb8 c) {
    return std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b);
}
bool isBlack(Rgb8 c) {
    return c.r < 40 && c.g < 40 && c.b < 40;
}

/// Two disks on a floor in two frames: frame 0 speeds (0, 1), frame 1 speeds (1, 3).
void writeTwoSpeedFrames(const fs::path& dir) {
    model::WallSet walls;
    walls.addPolyline("floor", {{0.0, 0.05}, {1.0, 0.05}}, false, 0, {});
    io::PvdWriter pvd((dir / "snapshots.pvd").string());
    const double speeds[2][2] = {{0.0, 1.0}, {1.0, 3.0}};
    for (int k = 0; k < 2; ++k) {
        model::ParticleStore s;
        s.add(0, {0.25, 0.2}, {speeds[k][0], 0.0}, kPi / 2, 0.0, kR, 1.0, 1.0, 0);
        s.add(1, {0.75, 0.2}, {0.0, speeds[k][1]}, kPi / 2, 0.0, kR, 1.0, 1.0, 0);
        io::writeSnapshot(dir.string(), k, s, model::ShapePool{}, walls, 0.1 * k, pvd);
    }
}

TEST(Render, ColourScaleIsFixedOverAllFrames) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    writeTwoSpeedFrames(dir);
    ASSERT_EQ(render(dir, 400), 0);
    const Png f0(dir / "png" / "frame_000000.png"), f1(dir / "png" / "frame_000001.png");
    ASSERT_TRUE(f0.ok() && f1.ok());
    const RenderLayout L = makeLayout({0.0, 0.05}, {1.0, 0.2 + kR}, 400);
    ASSERT_EQ(f0.height(), L.height);
    const Vec2 a = L.toPixel({0.25 - 0.5 * kR, 0.2}), b = L.toPixel({0.75 - 0.5 * kR, 0.2});
    // Speed 1 is disk B in frame 0 and disk A in frame 1: the same colour, viridis(1/3) of 0..3.
    EXPECT_TRUE(near(f0.at(b), f1.at(a), 2)) << str(f0.at(b)) << " vs " << str(f1.at(a));
    EXPECT_TRUE(near(f0.at(b), toRgb8(render::viridis(1.0 / 3)), 4)) << str(f0.at(b));
    EXPECT_TRUE(near(f0.at(a), {68, 1, 84})) << str(f0.at(a));     // speed 0: lo of all frames
    EXPECT_TRUE(near(f1.at(b), {253, 231, 37})) << str(f1.at(b));  // speed 3: hi of all frames

    // --range 0:2 replaces the scan: speed 1 is viridis(1/2), speed 3 is clamped to viridis(1).
    ASSERT_EQ(render(dir, 400, [](RenderOptions& o) { o.range = Interval{0.0, 2.0}; }), 0);
    const Png g0(dir / "png" / "frame_000000.png"), g1(dir / "png" / "frame_000001.png");
    EXPECT_TRUE(near(g0.at(b), toRgb8(render::viridis(0.5)), 4)) << str(g0.at(b));
    EXPECT_TRUE(near(g1.at(a), toRgb8(render::viridis(0.5)), 4)) << str(g1.at(a));
    EXPECT_TRUE(near(g1.at(b), {253, 231, 37})) << str(g1.at(b));
}

TEST(Render, ViewZoomsIntoAWindow) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    writeTwoSpeedFrames(dir);
    ASSERT_EQ(render(dir, 400, [](RenderOptions& o) { o.view = ViewBox{{0.1, 0.05}, {0.4, 0.35}}; }), 0);
    const Png png(dir / "png" / "frame_000000.png");
    ASSERT_TRUE(png.ok());
    const RenderLayout L = makeLayout({0.1, 0.05}, {0.4, 0.35}, 400, true);
    EXPECT_EQ(png.height(), L.height);
    EXPECT_NEAR(L.scale, 400 / 0.3, 1e-9);  // the window fills the width exactly
    EXPECT_TRUE(near(png.at(L.toPixel({0.25 - 0.5 * kR, 0.2})), {68, 1, 84}));  // disk A, slow
    EXPECT_TRUE(isWhite(png.at(L.toPixel({0.15, 0.33}))));
    // Disk B (x = 0.75) is outside: no fast colour anywhere in the scene.
    int fast = 0;
    for (int y = L.headerHeight; y < png.height(); ++y)
        for (int x = 0; x < png.width(); ++x)
            fast += near(png.pixel(x, y), toRgb8(render::viridis(1.0 / 3)), 3);
    EXPECT_EQ(fast, 0);
}

/// Disk A at a wall (contact on its right rim), disks C and D touching: contact files 0 and 1.
void writeContactScene(const fs::path& dir, double forceScale1) {
    io::PvdWriter pvd((dir / "snapshots.pvd").string());
    for (int k = 0; k < 2; ++k) {
        model::ParticleStore s;
        s.add(0, {0.3, 0.5}, {0.0, 0.0}, kPi / 2, 0.0, kR, 1.0, 1.0, 0);
        s.add(1, {0.3, 0.8}, {0.0, 0.0}, kPi / 2, 0.0, kR, 1.0, 1.0, 0);
        s.add(2, {0.5, 0.8}, {0.0, 0.0}, kPi / 2, 0.0, kR, 1.0, 1.0, 0);
        io::writeSnapshot(dir.string(), k, s, model::ShapePool{}, model::WallSet{}, 0.1 * k, pvd);
        analysis::ContactFrame c;
        const double f = k == 0 ? 10.0 : 10.0 * forceScale1;
        const auto add = [&c](std::int64_t a, std::int64_t b, std::int32_t wall, Vec2 p, Vec2 n, double fn) {
            c.a.push_back(a), c.b.push_back(b), c.wall.push_back(wall);
            c.px.push_back(p.x), c.py.push_back(p.y), c.nx.push_back(n.x), c.ny.push_back(n.y);
            c.fx.push_back(-fn * n.x), c.fy.push_back(-fn * n.y), c.fn.push_back(fn), c.ft.push_back(0);
            c.depth.push_back(0), c.area.push_back(0), c.length.push_back(0);
        };
        add(0, -1, 0, {0.4, 0.5}, {1, 0}, f);  // grain 0 against wall 0 at its right rim
        add(1, 2, -1, {0.4, 0.8}, {1, 0}, f);  // grains 1 and 2
        io::writeContactsNpy((dir / io::contactFileName(k)).string(), c);
    }
}

TEST(Render, ForceLinesRunFromEachCentroidToTheContactPoint) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    writeContactScene(dir, 0.5);
    ASSERT_EQ(render(dir, 400, [](RenderOptions& o) { o.forces = true; }), 0);
    const Png png(dir / "png" / "frame_000000.png");
    ASSERT_TRUE(png.ok());
    const RenderLayout L = makeLayout({0.3 - kR, 0.5 - kR}, {0.5 + kR, 0.8 + kR}, 400);
    ASSERT_EQ(png.height(), L.height);
    const double r = kR * L.scale;  // [px]
    // Wall contact: drawn from the centroid (0.3, 0.5) to the contact point (0.4, 0.5) only.
    for (const double t : {0.05, 0.3, 0.6, 0.9}) {
        const Vec2 p = L.toPixel({0.3 + t * 0.1, 0.5});
        EXPECT_TRUE(isBlack(png.at(p))) << "t = " << t << ": " << str(png.at(p));
    }
    const Vec2 end = L.toPixel({0.4, 0.5});
    EXPECT_TRUE(isWhite(png.at({end.x + 4, end.y}))) << str(png.at({end.x + 4, end.y}));
    // Left of the centroid: the pale disk, no line.
    EXPECT_FALSE(isBlack(png.at(L.toPixel({0.3 - 0.5 * kR, 0.5}))));
    // Width: the strongest force of all frames (frame 0 here) gets 0.6 radius.
    int dark = 0;
    for (int y = static_cast<int>(end.y - r); y < end.y + r; ++y)
        dark += isBlack(png.pixel(static_cast<int>(end.x - 0.3 * r), y));
    EXPECT_NEAR(dark, 0.6 * r, 2.5);
    // Grain pair: both halves, from each centroid to the common contact point; not beyond D's.
    for (const double x : {0.31, 0.35, 0.39, 0.41, 0.45, 0.49})
        EXPECT_TRUE(isBlack(png.at(L.toPixel({x, 0.8})))) << "x = " << x;
    EXPECT_FALSE(isBlack(png.at(L.toPixel({0.55, 0.8}))));

    // Frame 1 (half the force): half the width, the same scale as frame 0.
    const Png half(dir / "png" / "frame_000001.png");
    int dark1 = 0;
    for (int y = static_cast<int>(end.y - r); y < end.y + r; ++y)
        dark1 += isBlack(half.pixel(static_cast<int>(end.x - 0.3 * r), y));
    EXPECT_NEAR(dark1, 0.3 * r, 2.5);
}

TEST(Render, PressureAndCoordinationFromContacts) {
    // One disk squeezed between two walls along x by F: p = F / (pi r) (compressive > 0), 2 contacts;
    // a pair pressed together by F: each p = F r / (2 pi r^2).
    analysis::GrainFrame g;
    for (const double x : {0.0, 1.0, 1.2}) {
        g.id.push_back(static_cast<std::int64_t>(g.x.size()));
        g.x.push_back(x), g.y.push_back(0), g.radius.push_back(kR);
        g.cornerStart.push_back(0);
    }
    analysis::ContactFrame c;
    const auto add = [&c](std::int64_t a, std::int64_t b, Vec2 p, Vec2 f) {
        c.a.push_back(a), c.b.push_back(b), c.wall.push_back(b < 0 ? 0 : -1);
        c.px.push_back(p.x), c.py.push_back(p.y), c.fx.push_back(f.x), c.fy.push_back(f.y);
    };
    const double F = 3.0;
    add(0, -1, {kR, 0}, {-F, 0});
    add(0, -1, {-kR, 0}, {F, 0});
    add(1, 2, {1.1, 0}, {-F, 0});  // force on 1 points away from 2: repulsive
    const render::GrainContactSums s = render::grainContactSums(g, c, render::GrainIndex(g));
    EXPECT_NEAR(s.pressure[0], F / (kPi * kR), 1e-9);
    EXPECT_NEAR(s.pressure[1], F * kR / (2 * kPi * kR * kR), 1e-9);
    EXPECT_NEAR(s.pressure[2], s.pressure[1], 1e-9);
    EXPECT_EQ(s.coordination[0], 2);
    EXPECT_EQ(s.coordination[1], 1);
    EXPECT_EQ(s.coordination[2], 1);
}

TEST(Render, CoordinationColoursAreIntegers) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    writeContactScene(dir, 1.0);
    ASSERT_EQ(render(dir, 400, [](RenderOptions& o) { o.color = ColorMode::Coordination; }), 0);
    const Png png(dir / "png" / "frame_000000.png");
    const RenderLayout L = makeLayout({0.3 - kR, 0.5 - kR}, {0.5 + kR, 0.8 + kR}, 400);
    // Every grain has one contact: range 1..1, one colour for all three.
    const Rgb8 a = png.at(L.toPixel({0.3, 0.5 + 0.5 * kR})), d = png.at(L.toPixel({0.5, 0.8 + 0.5 * kR}));
    EXPECT_TRUE(near(a, d, 2)) << str(a) << " vs " << str(d);
    EXPECT_FALSE(isWhite(a));
}

TEST(Render, ContactModesWithoutContactFilesFail) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    writeScene(dir);
    for (const char* args : {"--color pressure", "--color coordination", "--forces"}) {
        const test::CommandResult r =
            test::runGranulab(fmt::format("render '{}' --png {}", dir.string(), args), dir);
        EXPECT_EQ(r.status, 2) << args << ": " << r.output;
        EXPECT_NE(r.output.find("needs contact files"), std::string::npos) << r.output;
    }
}

TEST(Render, BadOptionsExit2WithAMessage) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    writeScene(dir);
    const struct {
        const char* args;
        const char* message;
    } cases[] = {{"--range 2:1", "--range '2:1': expected lo:hi"},
                 {"--range 1", "--range '1': expected lo:hi"},
                 {"--range a:b", "expected lo:hi"},
                 {"--range 0:inf", "expected lo:hi"},
                 {"--view 0:1", "--view '0:1': expected x0:x1,y0:y1"},
                 {"--view 0:1,1:0", "expected x0:x1,y0:y1"},
                 {"--view 0:1,0:1,2:3", "expected x0:x1,y0:y1"},
                 {"--color heat", "--color 'heat': choose id, speed"},
                 {"--every 0", "--every"}};
    for (const auto& c : cases) {
        const test::CommandResult r =
            test::runGranulab(fmt::format("render '{}' --png {}", dir.string(), c.args), dir);
        EXPECT_EQ(r.status, 2) << c.args << ": " << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << ": " << r.output;
    }
    EXPECT_TRUE(parseRange("-1.5:2e3").has_value());
    EXPECT_DOUBLE_EQ(parseRange("-1.5:2e3")->lo, -1.5);
    const auto v = parseView("0:0.5,-1:2");
    ASSERT_TRUE(v.has_value());
    EXPECT_DOUBLE_EQ(v->hi.x, 0.5);
    EXPECT_DOUBLE_EQ(v->lo.y, -1.0);
}

TEST(Render, EveryNthFrameAndMovieWithoutFfmpeg) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    writeScene(dir);
    const test::CommandResult r =
        test::runGranulab(fmt::format("render '{}' --png --every 2 --movie --color id", dir.string()), dir);
    // PATH of the test run may or may not hold ffmpeg: either a movie or the hint, never a failure.
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "png" / "frame_000000.png"));
    EXPECT_FALSE(fs::exists(dir / "png" / "frame_000001.png"));  // every 2nd: 0 only
    EXPECT_TRUE(fs::exists(dir / "png" / "movie.mp4") ||
                r.output.find("apt-get install ffmpeg") != std::string::npos)
        << r.output;
    // Without ffmpeg on PATH: the hint on how to get it, exit 0, the frames written.
    const char* oldPath = std::getenv("PATH");
    const std::string saved = oldPath ? oldPath : "";
    ::setenv("PATH", (dir / "no-such-folder").c_str(), 1);
    ::testing::internal::CaptureStdout();
    const int status = render(dir, 200, [](RenderOptions& o) {
        o.movie = true;
        o.quiet = false;
    });
    const std::string out = ::testing::internal::GetCapturedStdout();
    ::setenv("PATH", saved.c_str(), 1);
    EXPECT_EQ(status, 0);
    EXPECT_NE(out.find("apt-get install ffmpeg"), std::string::npos) << out;
}

/// Timing of one 1e5-disk frame with 2e5 contacts (not run by default):
/// build/tests/granulab_tests --gtest_filter='Render.DISABLED_Bench*' --gtest_also_run_disabled_tests
TEST(Render, DISABLED_Bench100kDisks) {
    const test::ScratchDir scratch;
    const fs::path& dir = scratch.path;
    constexpr int kSide = 316;  // 99856 disks, square lattice, touching neighbours
    model::ParticleStore s;
    analysis::ContactFrame c;
    for (int j = 0; j < kSide; ++j)
        for (int i = 0; i < kSide; ++i) {
            const auto id = static_cast<std::int64_t>(j * kSide + i);
            const double v = 0.5 * (1 + std::sin(0.05 * i + 0.07 * j));
            s.add(static_cast<ParticleId>(id), {1e-3 * i, 1e-3 * j}, {v, 0.0}, 0.1 * i, 0.0, 0.49e-3, 1.0,
                  1.0, 0);
            for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
                if (i + di >= kSide || j + dj >= kSide) continue;
                const double f = 1 + std::cos(0.3 * i) * std::cos(0.2 * j);
                c.a.push_back(id), c.b.push_back(id + di + dj * kSide), c.wall.push_back(-1);
                c.px.push_back(1e-3 * (i + 0.5 * di)), c.py.push_back(1e-3 * (j + 0.5 * dj));
                c.nx.push_back(di), c.ny.push_back(dj), c.fx.push_back(-f * di), c.fy.push_back(-f * dj);
                c.fn.push_back(f), c.ft.push_back(0), c.depth.push_back(0), c.area.push_back(0);
                c.length.push_back(0);
            }
        }
    io::PvdWriter pvd((dir / "snapshots.pvd").string());
    io::writeSnapshot(dir.string(), 0, s, model::ShapePool{}, model::WallSet{}, 0.0, pvd);
    io::writeContactsNpy((dir / io::contactFileName(0)).string(), c);
    const struct {
        int width;
        bool forces;
    } runs[] = {{1200, false}, {1200, true}, {2400, false}};
    for (const auto& run : runs) {
        const auto t0 = std::chrono::steady_clock::now();
        RenderOptions o;
        o.outDir = dir.string();
        o.width = run.width;
        o.quiet = true;
        o.forces = run.forces;
        ASSERT_EQ(renderCommand(o), 0);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("1e5 disks%s, width %d: %.3f s (scan, draw, PNG)\n", run.forces ? " + 2e5 forces" : "",
                    run.width, seconds);
    }
}

}  // namespace
}  // namespace granulab::app
