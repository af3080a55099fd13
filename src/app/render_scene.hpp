// SPDX-License-Identifier: MIT
// The drawing of one frame of `granulab render` apart from the force network: grains (true disk
// and polygon outlines in their fill colour, orientation tick unless smooth spheres), walls, the
// box outline of edmd gases (periodic sides dashed) and the header band (time, scale bar, colour
// bar). Stroke widths are a few pixels at most whatever the picture width.
#pragma once
#include <cairo.h>

#include <optional>
#include <string>
#include <vector>

#include "analysis/dem_frame.hpp"
#include "app/render.hpp"
#include "app/render_colors.hpp"

namespace granulab::app::render {

/// The simulation box of an edmd run ([0, box] per axis) and which axes are periodic.
struct BoxOutline {
    Vec2 lo, hi;
    bool periodicX = false, periodicY = false;
};

/// Stroke widths of a run [px].
struct StrokeStyle {
    double wall = 2;  ///< wall segments: 0.25 typical grain radius, between 1 and 3 px
};
StrokeStyle makeStrokeStyle(const RenderLayout& L, double typicalRadius);

/// Clips to the scene area (below the header).
void clipToScene(cairo_t* cr, const RenderLayout& L);

/// Grains in the colours `fill[i]`; disk angle marks if `angleMarks` (off under the force network,
/// where a mark would read as a force line) and the file has angles.
void drawGrains(cairo_t* cr, const RenderLayout& L, const analysis::GrainFrame& g,
                const std::vector<Rgb>& fill, bool angleMarks);
void drawWalls(cairo_t* cr, const RenderLayout& L, const analysis::WallSegments& w, const StrokeStyle& s);
void drawBox(cairo_t* cr, const RenderLayout& L, const BoxOutline& box);

/// Header band: the time and a scale bar (a round length in metres) on the left, the colour bar
/// on the right.
void drawHeader(cairo_t* cr, const RenderLayout& L, const std::string& timeText, const ColorScale& scale);

/// The scale bar's length [m]: 1, 2 or 5 times a power of ten, at most `target`.
double roundLength(double target);

}  // namespace granulab::app::render
