// SPDX-License-Identifier: MIT
// `granulab render OUTDIR`: one PNG per snapshot of OUTDIR/snapshots.pvd (cairo), disks and
// polygons (filled outlines of their world corners) coloured by speed (viridis, one scale for
// all frames), walls, a colour bar and the time.
#pragma once
#include <string>

#include "core/types.hpp"

namespace granulab::app {

/// World [m] to pixel map of a rendered frame: equal scale in x and y, world y up = image up.
/// The image is a header band (time stamp, colour bar) above the scene.
struct RenderLayout {
    int width = 0, height = 0;  ///< [px] whole image
    int headerHeight = 0;       ///< [px] band above the scene
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
/// radius, all polygon corners and all walls): adds a 3 % margin per axis and a few pixels for
/// line widths; the height follows from the aspect ratio of the box.
RenderLayout makeLayout(Vec2 lo, Vec2 hi, int widthPixels);

/// Renders OUTDIR/png/frame_NNNNNN.png for every snapshot (NNNNNN = snapshot index of the file).
/// Returns 0 on success, 2 on missing or malformed input (message on stderr), 1 when a PNG
/// cannot be written. Prints the frame count and the folder unless `quiet`.
int renderCommand(const std::string& outDir, int widthPixels, bool quiet);

}  // namespace granulab::app
