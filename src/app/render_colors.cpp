// SPDX-License-Identifier: MIT
// Colour maps, colour scales and the colour bar of `granulab render` (app/render_colors.hpp).
#include "app/render_colors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace granulab::app::render {

namespace {
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

/// matplotlib's tab10.
constexpr std::array<std::array<int, 3>, 10> kTab10{{{31, 119, 180},
                                                     {255, 127, 14},
                                                     {44, 160, 44},
                                                     {214, 39, 40},
                                                     {148, 103, 189},
                                                     {140, 86, 75},
                                                     {227, 119, 194},
                                                     {127, 127, 127},
                                                     {188, 189, 34},
                                                     {23, 190, 207}}};

/// 1, 2 or 5 times a power of ten, the smallest not below x > 0.
double niceStep(double x) {
    const double p = std::pow(10.0, std::floor(std::log10(x)));
    for (const double m : {1.0, 2.0, 5.0})
        if (m * p >= x * (1 - 1e-9)) return m * p;
    return 10 * p;
}

/// Text extents of `s` at the current font.
cairo_text_extents_t extents(cairo_t* cr, const std::string& s) {
    cairo_text_extents_t te;
    cairo_text_extents(cr, s.c_str(), &te);
    return te;
}

/// Shows `s` horizontally centred at x with its top at y.
void showCentred(cairo_t* cr, const std::string& s, double x, double top) {
    const cairo_text_extents_t te = extents(cr, s);
    cairo_move_to(cr, x - te.x_bearing - 0.5 * te.width, top - te.y_bearing);
    cairo_show_text(cr, s.c_str());
}
}  // namespace

Rgb viridis(double t) {
    t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * (kViridis.size() - 1);
    const int k = std::min(static_cast<int>(t), static_cast<int>(kViridis.size()) - 2);
    const double f = t - k;
    const auto channel = [&](int c) { return ((1 - f) * kViridis[k][c] + f * kViridis[k + 1][c]) / 255.0; };
    return {channel(0), channel(1), channel(2)};
}

Rgb qualitative(long long k) {
    const auto i = static_cast<std::size_t>(((k % 10) + 10) % 10);
    return {kTab10[i][0] / 255.0, kTab10[i][1] / 255.0, kTab10[i][2] / 255.0};
}

Rgb mixWhite(Rgb c, double f) {
    return {c.r + f * (1 - c.r), c.g + f * (1 - c.g), c.b + f * (1 - c.b)};
}

std::string tickLabel(double v) {
    if (std::abs(v) < 1e-300) v = 0;  // no "-0"
    return fmt::format("{:.4g}", v);
}

ColorScale::ColorScale(ColorMode mode, double lo, double hi) : m_mode(mode), m_lo(lo), m_hi(hi) {
    if (!std::isfinite(m_lo) || !std::isfinite(m_hi)) m_lo = m_hi = 0;
    if (mode == ColorMode::Coordination || mode == ColorMode::Material) {
        m_lo = std::round(m_lo);
        m_hi = std::max(m_lo, std::round(m_hi));
    } else if (!(m_hi > m_lo)) {
        m_hi = m_lo + (m_lo == 0 ? 1.0 : 0.1 * std::abs(m_lo));
    }
}

bool ColorScale::discrete() const noexcept {
    return m_mode == ColorMode::Coordination || m_mode == ColorMode::Material || m_mode == ColorMode::Id;
}

int ColorScale::blockCount() const noexcept {
    if (m_mode == ColorMode::Id) return kIdBands;
    return static_cast<int>(std::min(m_hi - m_lo, 4095.0)) + 1;
}

Rgb ColorScale::rawColour(double value) const {
    switch (m_mode) {
        case ColorMode::Speed:
        case ColorMode::Pressure:
            return viridis((value - m_lo) / (m_hi - m_lo));
        case ColorMode::Coordination: {
            const double k = std::clamp(std::round(value), m_lo, m_hi);
            return viridis(m_hi > m_lo ? (k - m_lo) / (m_hi - m_lo) : 0.0);
        }
        case ColorMode::Material:
            return qualitative(std::llround(value));
        case ColorMode::Id: {
            const double band = std::floor((value - m_lo) / (m_hi - m_lo) * kIdBands);
            return qualitative(static_cast<long long>(std::clamp(band, 0.0, kIdBands - 1.0)));
        }
    }
    return kDark;
}

Rgb ColorScale::colour(double value) const {
    const Rgb c = rawColour(value);
    return m_pale > 0 ? mixWhite(c, m_pale) : c;
}

std::string ColorScale::title() const {
    switch (m_mode) {
        case ColorMode::Id:
            return "id (creation order)";
        case ColorMode::Speed:
            return "speed [m/s]";
        case ColorMode::Pressure:
            return "pressure [N/m]";
        case ColorMode::Coordination:
            return "coordination [contacts]";
        case ColorMode::Material:
            return "material [index]";
    }
    return "";
}

void ColorScale::drawBar(cairo_t* cr, double right, double top, double barWidth, double fontSize) const {
    cairo_set_font_size(cr, fontSize);
    // The end tick labels are centred on the bar's ends: keep half a label of room on the right.
    const double endLabel = std::max(extents(cr, tickLabel(m_lo)).width, extents(cr, tickLabel(m_hi)).width);
    right -= 0.5 * endLabel;
    barWidth -= 0.5 * endLabel;
    const double left = right - barWidth;
    const double barTop = top + 1.35 * fontSize, barH = 1.0 * fontSize;
    const double labelTop = barTop + barH + 0.45 * fontSize;
    setColour(cr, kDark);
    showCentred(cr, title(), 0.5 * (left + right), top);

    const int blocks = discrete() ? blockCount() : 0;
    if (blocks > 0) {
        const double w = barWidth / blocks;
        for (int k = 0; k < blocks; ++k) {
            const double v = m_mode == ColorMode::Id ? m_lo + (k + 0.5) * (m_hi - m_lo) / blocks : m_lo + k;
            setColour(cr, colour(v));
            cairo_rectangle(cr, left + k * w, barTop, w + 0.5, barH);  // + 0.5: no seams
            cairo_fill(cr);
        }
    } else {
        cairo_pattern_t* grad = cairo_pattern_create_linear(left, 0, right, 0);
        constexpr int kStops = 32;
        for (int k = 0; k <= kStops; ++k) {
            const double t = static_cast<double>(k) / kStops;
            const Rgb c = colour(m_lo + t * (m_hi - m_lo));
            cairo_pattern_add_color_stop_rgb(grad, t, c.r, c.g, c.b);
        }
        cairo_rectangle(cr, left, barTop, barWidth, barH);
        cairo_set_source(cr, grad);
        cairo_fill(cr);
        cairo_pattern_destroy(grad);
    }
    setColour(cr, kDark);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, std::round(left) + 0.5, std::round(barTop) + 0.5, std::round(barWidth) - 1,
                    std::round(barH));
    cairo_stroke(cr);

    // Tick labels: integer blocks at their centres (thinned to fit), otherwise round values.
    const double labelRoom = extents(cr, tickLabel(m_hi)).x_advance + 0.8 * fontSize;
    const auto tick = [&](double x, double v) {
        cairo_move_to(cr, std::round(x) + 0.5, barTop + barH);
        cairo_line_to(cr, std::round(x) + 0.5, barTop + barH + 0.3 * fontSize);
        cairo_stroke(cr);
        showCentred(cr, tickLabel(v), x, labelTop);
    };
    if (m_mode == ColorMode::Coordination || m_mode == ColorMode::Material) {
        const double w = barWidth / blocks;
        const int stride = std::max(1, static_cast<int>(std::ceil(labelRoom / w)));
        for (int k = 0; k < blocks; k += stride) tick(left + (k + 0.5) * w, m_lo + k);
        return;
    }
    // Round values: the finest 1-2-5 step whose labels fit side by side (at least two ticks).
    const double span = m_hi - m_lo, gap = 0.8 * fontSize;
    std::vector<double> ticks;
    for (double step = niceStep(span / 10);; step = niceStep(step * 1.5)) {
        ticks.clear();
        double room = 0;
        for (double k = std::ceil(m_lo / step - 1e-9); k * step <= m_hi + 1e-9 * step; k += 1) {
            ticks.push_back(std::abs(k) < 0.5 ? 0.0 : k * step);
            room += extents(cr, tickLabel(ticks.back())).x_advance + gap;
        }
        if (room <= barWidth || ticks.size() <= 2) break;
    }
    for (const double v : ticks) tick(left + (v - m_lo) / span * barWidth, v);
}

}  // namespace granulab::app::render
