// SPDX-License-Identifier: MIT
// `granulab render OUTDIR`: one PNG per snapshot of OUTDIR/snapshots.pvd (cairo): disks and
// polygons as true outlines, coloured by id, speed, pressure, coordination or material on one
// scale for all frames; walls, periodic box outlines, the force network (--forces), a colour
// bar, a scale bar and the time; optionally a movie (ffmpeg).
#pragma once
#include <optional>
#include <string>

#include "core/types.hpp"

namespace granulab::app {

/// What the grain fill colour shows.
enum class ColorMode {
    Id,            ///< creation order (global id), qualitative bands so strata show
    Speed,         ///< [m/s]
    Pressure,      ///< [N/m] per-grain mean normal stress from the contact file, compressive > 0
    Coordination,  ///< contacts per grain from the contact file (integer colours)
    Material,      ///< material index (qualitative)
};

/// "id", "speed", ... -> mode; nullopt for an unknown name.
std::optional<ColorMode> parseColorMode(const std::string& name);
/// True for the modes that read the contact files.
bool needsContacts(ColorMode mode) noexcept;

/// A closed interval lo < hi (colour range, view window axis).
struct Interval {
    double lo = 0, hi = 0;
};

/// "lo:hi" with finite numbers and lo < hi; nullopt otherwise.
std::optional<Interval> parseRange(const std::string& text);

/// World window [m] of --view.
struct ViewBox {
    Vec2 lo, hi;
};
/// "x0:x1,y0:y1" with x0 < x1 and y0 < y1; nullopt otherwise.
std::optional<ViewBox> parseView(const std::string& text);

struct RenderOptions {
    std::string outDir;
    int width = 1200;                    ///< [px] picture width
    int every = 1;                       ///< render every Nth snapshot (the first always)
    ColorMode color = ColorMode::Speed;  ///< grain fill colour
    bool forces = false;                 ///< draw the force network (needs contact files)
    std::optional<Interval> range;       ///< fixed colour range instead of the scan of all frames
    std::optional<ViewBox> view;         ///< world window instead of the box of everything
    bool movie = false;                  ///< assemble png/movie.mp4 with ffmpeg
    int fps = 10;                        ///< movie frame rate
    bool quiet = false;
};

/// World [m] to pixel map of a rendered frame: equal scale in x and y, world y up = image up.
/// The image is a header band (time, scale bar, colour bar) above the scene.
struct RenderLayout {
    int width = 0, height = 0;  ///< [px] whole image
    int headerHeight = 0;       ///< [px] band above the scene
    double fontSize = 12;       ///< [px] header text
    double scale = 1;           ///< [px/m]
    Vec2 lo, hi;                ///< [m] world box shown, margin included
    double originX = 0;         ///< [px] image x of world x = lo.x
    double originY = 0;         ///< [px] image y of world y = hi.y

    /// Pixel position (x right, y down, pixel centres at k + 0.5) of a world point [m].
    Vec2 toPixel(Vec2 world) const noexcept {
        return {originX + (world.x - lo.x) * scale, originY + (hi.y - world.y) * scale};
    }
};

/// Layout of a picture `widthPixels` wide of the world box lo..hi [m] (all disks with their
/// radius, all polygon corners, walls and box outlines): adds a 3 % margin per axis unless
/// `exact` (a --view window) and a few pixels for line widths; the height follows from the aspect
/// ratio of the box (at most 16384 px of scene).
RenderLayout makeLayout(Vec2 lo, Vec2 hi, int widthPixels, bool exact = false);

/// Renders OUTDIR/png/frame_NNNNNN.png for every `every`-th snapshot (NNNNNN = snapshot index of
/// the file). Returns 0 on success, 2 on missing or malformed input (message on stderr; also when
/// the colour mode or --forces needs contact files and the folder has none), 1 when a PNG cannot
/// be written. Prints the frame count and the folder unless `quiet`. --movie without ffmpeg on
/// PATH prints how to get it and still returns 0.
int renderCommand(const RenderOptions& options);

}  // namespace granulab::app
