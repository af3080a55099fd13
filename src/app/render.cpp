// SPDX-License-Identifier: MIT
// PNG renderer. Two passes over the snapshots: the first finds the world box and the largest
// speed of ALL frames (so every frame has the same view and colour scale, ready for a video),
// the second draws; only one frame is held in memory at a time.
#include "app/render.hpp"

#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <vector>

#include "io/vtk_reader.hpp"

namespace granulab::app {

namespace {
namespace fs = std::filesystem;

constexpr int kMinWidth = 64, kMaxWidth = 16384;
constexpr double kMaxSceneHeight = 16384;  // [px] cairo surfaces stay below 32767 px
constexpr double kMargin = 0.03;           // fraction of the box size added on each side

struct Rgb {
    double r, g, b;
};

/// matplotlib's viridis at 9 equally spaced stops; linear in between.
constexpr std::array<std::array<int, 3>, 9> kViridis{{{68, 1, 84},
                                                      {71, 45, 123},
                                                      {59, 82, 139},
                                                      {44, 114, 142},
                                                      {33, 145, 140},
                                                      {40, 174, 128},
                                                      {94, 201, 98},
                                                      {173, 220, 48},
                                                      {253, 231, 37}}};

Rgb viridis(double t) {
    t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * (kViridis.size() - 1);
    const int k = std::min(static_cast<int>(t), static_cast<int>(kViridis.size()) - 2);
    const double f = t - k;
    const auto channel = [&](int c) { return ((1 - f) * kViridis[k][c] + f * kViridis[k + 1][c]) / 255.0; };
    return {channel(0), channel(1), channel(2)};
}

double wallLineWidth(int widthPixels) {
    return std::max(3.0, widthPixels / 250.0);
}  // [px]

/// One snapshot: particle file and (optional) wall file of the same time.
struct Snapshot {
    double time = 0;
    int index = 0;
    fs::path particles, walls;
};

/// Snapshot index from "…_NNNNNN.vtp", else `fallback`.
int indexFromName(const std::string& file, int fallback) {
    const std::string stem = fs::path(file).stem().string();
    const auto us = stem.rfind('_');
    if (us == std::string::npos) return fallback;
    int v = 0;
    const auto r = std::from_chars(stem.data() + us + 1, stem.data() + stem.size(), v);
    return (r.ec == std::errc() && r.ptr == stem.data() + stem.size() && v >= 0) ? v : fallback;
}

std::vector<Snapshot> collectSnapshots(const fs::path& dir, const std::vector<io::PvdEntry>& entries) {
    std::vector<Snapshot> out;
    for (const io::PvdEntry& e : entries) {
        if (e.part != 0) continue;
        Snapshot s{e.time, indexFromName(e.file, static_cast<int>(out.size())), dir / e.file, {}};
        for (const io::PvdEntry& w : entries)
            if (w.part == 1 && w.time == e.time) {
                s.walls = dir / w.file;
                break;
            }
        out.push_back(std::move(s));
    }
    return out;
}

/// World box of everything drawn and the largest speed, over all frames.
struct Extent {
    Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    Vec2 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    double maxSpeed = 0;  // [m/s]

    void add(Vec2 p, double r) {
        lo = {std::min(lo.x, p.x - r), std::min(lo.y, p.y - r)};
        hi = {std::max(hi.x, p.x + r), std::max(hi.y, p.y + r)};
    }
};

Extent scanExtent(const std::vector<Snapshot>& snaps) {
    Extent ext;
    for (const Snapshot& s : snaps) {
        const io::ParticleFrame f = io::readParticlesVtp(s.particles.string());
        for (std::size_t i = 0; i < f.x.size(); ++i) {
            if (f.isPolygon(i))
                for (std::size_t c = f.cornerStart[i]; c < f.cornerStart[i + 1]; ++c)
                    ext.add(f.corners[c], 0);
            else
                ext.add({f.x[i], f.y[i]}, f.radius[i]);
            if (std::isfinite(f.speed[i])) ext.maxSpeed = std::max(ext.maxSpeed, f.speed[i]);
        }
        if (s.walls.empty()) continue;
        const io::WallFrame w = io::readWallsVtp(s.walls.string());
        for (std::size_t k = 0; k < w.a.size(); ++k) {
            ext.add(w.a[k], 0);
            ext.add(w.b[k], 0);
        }
    }
    return ext;
}

/// Decimals of the time stamp: 3, more if snapshots are closer than 1 ms.
int timeDecimals(const std::vector<Snapshot>& snaps) {
    int decimals = 3;
    for (std::size_t k = 1; k < snaps.size(); ++k) {
        const double dt = std::abs(snaps[k].time - snaps[k - 1].time);
        if (dt > 0) decimals = std::max(decimals, static_cast<int>(std::ceil(-std::log10(dt))));
    }
    return std::min(decimals, 9);
}

void setColour(cairo_t* cr, Rgb c) {
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
}

constexpr Rgb kDark{0.12, 0.12, 0.14};

/// Polygon i of the frame as a filled outline in its speed colour.
void drawPolygon(cairo_t* cr, const RenderLayout& L, const io::ParticleFrame& f, std::size_t i, Rgb fill) {
    cairo_new_path(cr);
    for (std::size_t c = f.cornerStart[i]; c < f.cornerStart[i + 1]; ++c) {
        const Vec2 p = L.toPixel(f.corners[c]);
        if (c == f.cornerStart[i])
            cairo_move_to(cr, p.x, p.y);
        else
            cairo_line_to(cr, p.x, p.y);
    }
    cairo_close_path(cr);
    setColour(cr, fill);
    const double r = f.radius[i] * L.scale;  // [px] circumradius
    if (r < 1.5) {                           // too small for an outline
        cairo_fill(cr);
        return;
    }
    cairo_fill_preserve(cr);
    setColour(cr, kDark);
    cairo_set_line_width(cr, std::clamp(0.08 * r, 0.5, 1.5));
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
    cairo_stroke(cr);
}

/// Disks (circle, outline, angle mark) and polygons (filled outline), coloured by speed.
void drawParticles(cairo_t* cr, const RenderLayout& L, const io::ParticleFrame& f, double maxSpeed) {
    for (std::size_t i = 0; i < f.x.size(); ++i) {
        const Rgb fill = viridis(f.speed[i] / maxSpeed);
        if (f.isPolygon(i)) {
            drawPolygon(cr, L, f, i, fill);
            continue;
        }
        const Vec2 c = L.toPixel({f.x[i], f.y[i]});
        const double r = f.radius[i] * L.scale;  // [px]
        cairo_new_path(cr);
        cairo_arc(cr, c.x, c.y, r, 0, 2 * kPi);
        setColour(cr, fill);
        if (r < 1.5) {  // too small for outline and angle mark
            cairo_fill(cr);
            continue;
        }
        cairo_fill_preserve(cr);
        setColour(cr, kDark);
        cairo_set_line_width(cr, std::clamp(0.08 * r, 0.5, 1.5));
        cairo_stroke(cr);
        if (r < 3) continue;
        // angle mark: light on dark fills
        setColour(cr, 0.3 * fill.r + 0.6 * fill.g + 0.1 * fill.b < 0.35 ? Rgb{0.92, 0.92, 0.92} : kDark);
        cairo_move_to(cr, c.x, c.y);  // centre to rim, counter-clockwise, y flipped
        cairo_line_to(cr, c.x + r * std::cos(f.angle[i]), c.y - r * std::sin(f.angle[i]));
        cairo_stroke(cr);
    }
}

void drawWalls(cairo_t* cr, const RenderLayout& L, const io::WallFrame& w) {
    setColour(cr, kDark);
    cairo_set_line_width(cr, wallLineWidth(L.width));
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    for (std::size_t k = 0; k < w.a.size(); ++k) {
        const Vec2 a = L.toPixel(w.a[k]), b = L.toPixel(w.b[k]);
        cairo_move_to(cr, a.x, a.y);
        cairo_line_to(cr, b.x, b.y);
        cairo_stroke(cr);
    }
}

/// Header band: "t = … s" on the left, colour bar with 0 and max speed on the right.
void drawHeader(cairo_t* cr, const RenderLayout& L, const std::string& timeText, double maxSpeed) {
    const double h = L.headerHeight, pad = 0.3 * h, mid = 0.5 * h;
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 0.4 * h);
    setColour(cr, kDark);
    cairo_text_extents_t te;
    cairo_text_extents(cr, timeText.c_str(), &te);
    cairo_move_to(cr, pad, mid - te.y_bearing - 0.5 * te.height);
    cairo_show_text(cr, timeText.c_str());

    const std::string maxText = fmt::format("{:.3g} m/s", maxSpeed), minText = "speed  0";
    cairo_text_extents_t maxExt, minExt;
    cairo_text_extents(cr, maxText.c_str(), &maxExt);
    cairo_text_extents(cr, minText.c_str(), &minExt);
    const double gap = 0.5 * pad;  // [px] between a label and the bar
    const double barRight = L.width - pad - maxExt.x_advance - gap;
    const double barLeft = barRight - 0.25 * L.width, barH = 0.35 * h;
    cairo_move_to(cr, barLeft - gap - minExt.x_advance, mid - minExt.y_bearing - 0.5 * minExt.height);
    cairo_show_text(cr, minText.c_str());
    cairo_move_to(cr, barRight + gap, mid - maxExt.y_bearing - 0.5 * maxExt.height);
    cairo_show_text(cr, maxText.c_str());

    cairo_pattern_t* grad = cairo_pattern_create_linear(barLeft, 0, barRight, 0);
    for (std::size_t k = 0; k < kViridis.size(); ++k) {
        const Rgb c = viridis(static_cast<double>(k) / (kViridis.size() - 1));
        cairo_pattern_add_color_stop_rgb(grad, static_cast<double>(k) / (kViridis.size() - 1), c.r, c.g, c.b);
    }
    cairo_rectangle(cr, barLeft, mid - 0.5 * barH, barRight - barLeft, barH);
    cairo_set_source(cr, grad);
    cairo_fill_preserve(cr);
    cairo_pattern_destroy(grad);
    setColour(cr, kDark);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
}

/// Draws one frame and writes it; false if the PNG cannot be written.
bool renderFrame(const RenderLayout& L, const Snapshot& s, double maxSpeed, int decimals,
                 const fs::path& png) {
    const io::ParticleFrame f = io::readParticlesVtp(s.particles.string());
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, L.width, L.height);
    cairo_t* cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    drawParticles(cr, L, f, maxSpeed > 0 ? maxSpeed : 1.0);
    if (!s.walls.empty()) drawWalls(cr, L, io::readWallsVtp(s.walls.string()));
    drawHeader(cr, L, fmt::format("t = {:.{}f} s", s.time, decimals), maxSpeed);
    cairo_destroy(cr);
    const bool ok = cairo_surface_write_to_png(surface, png.c_str()) == CAIRO_STATUS_SUCCESS;
    cairo_surface_destroy(surface);
    return ok;
}
}  // namespace

RenderLayout makeLayout(Vec2 lo, Vec2 hi, int widthPixels) {
    if (!(hi.x >= lo.x && hi.y >= lo.y)) {  // nothing to show
        lo = {0, 0};
        hi = {1, 1};
    }
    const double span = std::max(hi.x - lo.x, hi.y - lo.y);
    const double big = span > 0 ? span : 1.0;
    const auto widen = [big](double& a, double& b) {  // a degenerate axis gets 10 % of the other
        if (b - a >= 1e-6 * big) return;
        const double c = 0.5 * (a + b);
        a = c - 0.05 * big;
        b = c + 0.05 * big;
    };
    widen(lo.x, hi.x);
    widen(lo.y, hi.y);
    const Vec2 margin{kMargin * (hi.x - lo.x), kMargin * (hi.y - lo.y)};
    RenderLayout L;
    L.lo = lo - margin;
    L.hi = hi + margin;
    L.width = widthPixels;
    L.headerHeight = static_cast<int>(std::clamp(std::lround(0.06 * widthPixels), 24L, 96L));
    const double pad = std::ceil(0.5 * wallLineWidth(widthPixels)) + 2;  // [px] room for strokes
    const double w = L.hi.x - L.lo.x, h = L.hi.y - L.lo.y;
    L.scale = std::min((widthPixels - 2 * pad) / w, kMaxSceneHeight / h);
    L.height = L.headerHeight + static_cast<int>(std::ceil(h * L.scale + 2 * pad));
    L.originX = 0.5 * (widthPixels - w * L.scale);
    L.originY = L.headerHeight + pad;
    return L;
}

int renderCommand(const std::string& outDir, int widthPixels, bool quiet) {
    const fs::path dir(outDir), pvd = dir / "snapshots.pvd";
    if (widthPixels < kMinWidth || widthPixels > kMaxWidth) {
        fmt::print(stderr, "granulab render: width must be in [{}, {}] pixels, got {}\n", kMinWidth,
                   kMaxWidth, widthPixels);
        return 2;
    }
    std::error_code ec;
    if (!fs::is_regular_file(pvd, ec)) {
        fmt::print(stderr, "granulab render: no snapshots.pvd in {}; run `granulab run` first\n", outDir);
        return 2;
    }
    const fs::path pngDir = dir / "png";
    try {
        const std::vector<Snapshot> snaps = collectSnapshots(dir, io::readPvd(pvd.string()));
        if (snaps.empty()) {
            fmt::print(stderr, "granulab render: {} lists no particle snapshots\n", pvd.string());
            return 2;
        }
        const Extent ext = scanExtent(snaps);
        const RenderLayout layout = makeLayout(ext.lo, ext.hi, widthPixels);
        const int decimals = timeDecimals(snaps);
        fs::create_directories(pngDir, ec);
        for (const Snapshot& s : snaps) {
            const fs::path png = pngDir / fmt::format("frame_{:06d}.png", s.index);
            if (!renderFrame(layout, s, ext.maxSpeed, decimals, png)) {
                fmt::print(stderr, "granulab render: cannot write {}\n", png.string());
                return 1;
            }
        }
        if (!quiet)
            fmt::print("granulab render: {} frames ({} x {} px) in {}\n", snaps.size(), layout.width,
                       layout.height, pngDir.string());
    } catch (const std::exception& e) {
        fmt::print(stderr, "granulab render: {}\n", e.what());
        return 2;
    }
    return 0;
}

}  // namespace granulab::app
