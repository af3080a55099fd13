// SPDX-License-Identifier: MIT
// `granulab render`: a 3-disk scene with a floor, rendered and inspected pixel by pixel
// (existence, width, disk colours, white background, y axis pointing up).
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include "app/render.hpp"
#include "../support.hpp"
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

bool isWhite(Rgb8 c) { return c.r == 255 && c.g == 255 && c.b == 255; }
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
        io::writeSnapshot(dir.string(), k, s, walls, 0.5 * k, pvd);
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
    EXPECT_TRUE(near(slow, {68, 1, 84})) << slow.r << "," << slow.g << "," << slow.b;    // viridis(0)
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
