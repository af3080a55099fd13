// SPDX-License-Identifier: MIT
// `granulab render`: a 3-disk scene with a floor, rendered and inspected pixel by pixel
// (existence, width, disk colours, white background, y axis pointing up); a polygon scene
// (filled true outlines in the speed colour).
#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "../support.hpp"
#include "app/render.hpp"
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
    ASSERT_EQ(renderCommand(dir.string(), 400, true), 0);
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
    ASSERT_EQ(renderCommand(dir.string(), 800, true), 0);
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
    EXPECT_EQ(renderCommand(dir.string(), 400, true), 2);
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

}  // namespace
}  // namespace granulab::app
