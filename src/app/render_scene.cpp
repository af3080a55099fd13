// SPDX-License-Identifier: MIT
// Grains, walls, box outlines and the header band of a rendered frame (app/render_scene.hpp).
#include "app/render_scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace granulab::app::render {

namespace {
/// True if the pixel box c +- r misses the scene area (grains outside a --view window).
bool offScene(const RenderLayout& L, Vec2 c, double r) {
    return c.x + r < 0 || c.x - r > L.width || c.y + r < L.headerHeight || c.y - r > L.height;
}

double outlineWidth(double rPixels) {
    return std::clamp(0.08 * rPixels, 0.5, 1.5);
}

/// 8-bit colour as one key (the PNG's resolution: grouping by it loses nothing).
std::uint32_t colourKey(Rgb c) {
    const auto q = [](double v) {
        return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
    };
    return q(c.r) << 16 | q(c.g) << 8 | q(c.b);
}

/// Calls add(i) for the items of `keyed` (key, index) in key order and flush(key) after each run
/// of one key: one cairo path per colour or width (1e5 fills one by one cost ~5x more).
using Keyed = std::vector<std::pair<std::uint64_t, std::size_t>>;
template <class Add, class Flush>
void inBatches(cairo_t* cr, Keyed& keyed, Add&& add, Flush&& flush) {
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t k = 0; k < keyed.size(); ++k) {
        if (k == 0 || keyed[k].first != keyed[k - 1].first) cairo_new_path(cr);
        add(keyed[k].second);
        if (k + 1 == keyed.size() || keyed[k + 1].first != keyed[k].first) flush(keyed[k].first);
    }
}
}  // namespace

StrokeStyle makeStrokeStyle(const RenderLayout& L, double typicalRadius) {
    StrokeStyle s;
    const double r = typicalRadius > 0 ? typicalRadius * L.scale : 8.0;
    s.wall = std::clamp(0.25 * r, 1.0, 3.0);
    return s;
}

void clipToScene(cairo_t* cr, const RenderLayout& L) {
    cairo_rectangle(cr, 0, L.headerHeight, L.width, L.height - L.headerHeight);
    cairo_clip(cr);
}

void drawGrains(cairo_t* cr, const RenderLayout& L, const analysis::GrainFrame& g,
                const std::vector<Rgb>& fill, bool angleMarks) {
    // Batched (one cairo path per colour or width; 1e5 grains drawn one by one cost ~3x more):
    // the dark rims of the disks as one fill (radius r + w/2), the fills grouped by colour
    // (disks with a rim: radius r - w/2), the polygon outlines stroked grouped by width (1/8 px
    // steps), then the angle marks (disks of 3 px radius and more, not smooth spheres).
    // Grains under 2.5 px radius get no outline (it would hide their colour).
    Keyed fills, outlines, marks;
    fills.reserve(g.size());
    std::vector<double> rim(g.size(), 0.0);  // [px] outline width, 0: none
    const auto widthKey = [](double w) { return static_cast<std::uint64_t>(std::lround(8 * w)); };
    for (std::size_t i = 0; i < g.size(); ++i) {
        const Vec2 c = L.toPixel({g.x[i], g.y[i]});
        const double r = g.radius[i] * L.scale;  // [px]
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(r) || offScene(L, c, r)) continue;
        fills.emplace_back(colourKey(fill[i]), i);
        if (r < 2.5) continue;
        rim[i] = outlineWidth(r);
        if (g.isPolygon(i)) outlines.emplace_back(widthKey(rim[i]), i);
        if (r < 3 || g.isPolygon(i) || !g.hasAngle || !angleMarks) continue;
        const Rgb f = fill[i];
        const bool light = 0.3 * f.r + 0.6 * f.g + 0.1 * f.b < 0.35;  // light mark on dark fills
        marks.emplace_back(2 * widthKey(rim[i]) + light, i);
    }
    const auto circle = [&](std::size_t i, double r) {
        const Vec2 c = L.toPixel({g.x[i], g.y[i]});
        cairo_new_sub_path(cr);
        cairo_arc(cr, c.x, c.y, std::max(r, 0.5), 0, 2 * kPi);
        cairo_close_path(cr);
    };
    const auto polygon = [&](std::size_t i) {
        for (std::size_t k = g.cornerStart[i]; k < g.cornerStart[i + 1]; ++k) {
            const Vec2 p = L.toPixel(g.corners[k]);
            if (k == g.cornerStart[i])
                cairo_move_to(cr, p.x, p.y);
            else
                cairo_line_to(cr, p.x, p.y);
        }
        cairo_close_path(cr);
    };
    cairo_new_path(cr);
    for (const auto& [key, i] : fills)
        if (rim[i] > 0 && !g.isPolygon(i)) circle(i, g.radius[i] * L.scale + 0.5 * rim[i]);
    setColour(cr, kDark);
    cairo_fill(cr);
    inBatches(
        cr, fills,
        [&](std::size_t i) {
            if (g.isPolygon(i))
                polygon(i);
            else
                circle(i, g.radius[i] * L.scale - 0.5 * rim[i]);
        },
        [&](std::uint64_t key) {
            cairo_set_source_rgb(cr, ((key >> 16) & 255) / 255.0, ((key >> 8) & 255) / 255.0,
                                 (key & 255) / 255.0);
            cairo_fill(cr);
        });
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    setColour(cr, kDark);
    inBatches(cr, outlines, polygon, [&](std::uint64_t key) {
        cairo_set_line_width(cr, key / 8.0);
        cairo_stroke(cr);
    });
    inBatches(
        cr, marks,
        [&](std::size_t i) {  // centre to rim, counter-clockwise, y flipped
            const Vec2 c = L.toPixel({g.x[i], g.y[i]});
            const double r = g.radius[i] * L.scale - rim[i];
            cairo_move_to(cr, c.x, c.y);
            cairo_line_to(cr, c.x + r * std::cos(g.angle[i]), c.y - r * std::sin(g.angle[i]));
        },
        [&](std::uint64_t key) {
            setColour(cr, key % 2 ? Rgb{0.92, 0.92, 0.92} : kDark);
            cairo_set_line_width(cr, (key / 2) / 8.0);
            cairo_stroke(cr);
        });
}

void drawWalls(cairo_t* cr, const RenderLayout& L, const analysis::WallSegments& w, const StrokeStyle& s) {
    setColour(cr, kDark);
    cairo_set_line_width(cr, s.wall);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_new_path(cr);
    for (std::size_t k = 0; k < w.a.size(); ++k) {
        const Vec2 a = L.toPixel(w.a[k]), b = L.toPixel(w.b[k]);
        cairo_move_to(cr, a.x, a.y);
        cairo_line_to(cr, b.x, b.y);
    }
    cairo_stroke(cr);
}

void drawBox(cairo_t* cr, const RenderLayout& L, const BoxOutline& box) {
    const Vec2 a = L.toPixel(box.lo), b = L.toPixel(box.hi);  // a: bottom left, b: top right
    const auto side = [&](Vec2 p, Vec2 q, bool periodic) {
        const double dash[] = {6.0, 4.0};
        cairo_set_dash(cr, dash, periodic ? 2 : 0, 0);
        if (periodic)
            cairo_set_source_rgb(cr, 0.45, 0.45, 0.5);
        else
            setColour(cr, kDark);
        cairo_move_to(cr, p.x, p.y);
        cairo_line_to(cr, q.x, q.y);
        cairo_stroke(cr);
    };
    cairo_save(cr);
    cairo_set_line_width(cr, 1.5);
    side({a.x, a.y}, {b.x, a.y}, box.periodicY);  // bottom and top: the y sides
    side({a.x, b.y}, {b.x, b.y}, box.periodicY);
    side({a.x, a.y}, {a.x, b.y}, box.periodicX);  // left and right
    side({b.x, a.y}, {b.x, b.y}, box.periodicX);
    cairo_restore(cr);
}

double roundLength(double target) {
    if (!(target > 0) || !std::isfinite(target)) return 1;
    const double p = std::pow(10.0, std::floor(std::log10(target)));
    for (const double m : {5.0, 2.0, 1.0})
        if (m * p <= target * (1 + 1e-9)) return m * p;
    return p;
}

void drawHeader(cairo_t* cr, const RenderLayout& L, const std::string& timeText, const ColorScale& scale) {
    const double fs = L.fontSize, pad = 0.7 * fs;
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    setColour(cr, kDark);
    cairo_set_font_size(cr, 1.15 * fs);
    cairo_text_extents_t te;
    cairo_text_extents(cr, timeText.c_str(), &te);
    cairo_move_to(cr, pad - te.x_bearing, 0.4 * fs - te.y_bearing);
    cairo_show_text(cr, timeText.c_str());

    // Scale bar under the time: ~15 % of the scene width, end ticks, label on its right.
    const double barWidth = std::min(0.32 * L.width, 30 * fs);
    const double length = roundLength(0.15 * L.width / L.scale);  // [m]
    const double px = length * L.scale, y = std::round(2.9 * fs) + 0.5, tickH = 0.35 * fs;
    cairo_set_line_width(cr, std::max(1.0, std::round(0.12 * fs)));
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    cairo_move_to(cr, pad, y - tickH);
    cairo_line_to(cr, pad, y);
    cairo_line_to(cr, pad + px, y);
    cairo_line_to(cr, pad + px, y - tickH);
    cairo_stroke(cr);
    const std::string label = fmt::format("{:g} m", length);
    cairo_set_font_size(cr, fs);
    cairo_text_extents(cr, label.c_str(), &te);
    cairo_move_to(cr, pad + px + 0.5 * fs - te.x_bearing, y - te.y_bearing - te.height);
    cairo_show_text(cr, label.c_str());

    scale.drawBar(cr, L.width - pad, 0.35 * fs, barWidth, fs);
}

}  // namespace granulab::app::render
