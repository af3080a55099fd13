// SPDX-License-Identifier: MIT
// Colour maps and colour scales of `granulab render` (app/render.hpp): viridis for continuous
// and ordered integer quantities, a qualitative palette (matplotlib tab10) for ids and materials,
// and the colour bar with the quantity's name, unit and tick labels.
#pragma once
#include <cairo.h>

#include <string>

#include "app/render.hpp"

namespace granulab::app::render {

struct Rgb {
    double r = 0, g = 0, b = 0;
};

constexpr Rgb kDark{0.12, 0.12, 0.14};  ///< outlines, walls, text
constexpr Rgb kWhite{1, 1, 1};

inline void setColour(cairo_t* cr, Rgb c) {
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
}

/// matplotlib's viridis, t in [0, 1] (clamped; NaN gives viridis(0)).
Rgb viridis(double t);
/// matplotlib's tab10, index k modulo 10.
Rgb qualitative(long long k);
/// c mixed with white: fraction `f` of white (the pale fills under the force network).
Rgb mixWhite(Rgb c, double f);

/// Maps a grain value to its fill colour, fixed for a whole run.
class ColorScale {
public:
    /// `lo`, `hi`: the range (hi > lo is enforced: an empty range is widened).
    ColorScale(ColorMode mode, double lo, double hi);

    Rgb colour(double value) const;
    /// Fill colours are mixed with white by this fraction (also in the colour bar).
    void setPale(double f) { m_pale = f; }

    ColorMode mode() const noexcept { return m_mode; }
    double lo() const noexcept { return m_lo; }
    double hi() const noexcept { return m_hi; }
    /// "speed [m/s]", "coordination (contacts per grain)", ...
    std::string title() const;

    /// Draws the bar (blocks for integer and band scales, a gradient otherwise), its title above
    /// and tick labels below, right-aligned at `right`, between y = top and top + height [px].
    void drawBar(cairo_t* cr, double right, double top, double barWidth, double fontSize) const;

private:
    bool discrete() const noexcept;  ///< integer blocks (coordination, material) or id bands
    int blockCount() const noexcept;
    Rgb rawColour(double value) const;

    ColorMode m_mode;
    double m_lo, m_hi;
    double m_pale = 0;
};

/// Id bands of the id scale: the id range is cut into this many bands, one tab10 colour each.
constexpr int kIdBands = 10;

/// "1.5", "200", "0.002", "1e+06": a short label of a tick value.
std::string tickLabel(double v);

}  // namespace granulab::app::render
