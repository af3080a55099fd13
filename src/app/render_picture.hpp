// SPDX-License-Identifier: MIT
// One picture of a state as a PostScript file (gc2d spec 9.1 ".ps: a picture of the system"):
// the drawing of `granulab render` (app/render_scene.hpp: grains coloured by id, walls, time and
// scale bar) on cairo's PostScript surface instead of a PNG image.
#pragma once
#include <string>

#include "analysis/dem_frame.hpp"

namespace granulab::app {

/// Writes `path` (PostScript, `widthPoints` wide, 1 pt = 1/72 in) of the grains and wall
/// segments at time `time` [s]. Returns false if cairo cannot write the file.
bool writePicturePs(const std::string& path, const analysis::GrainFrame& grains,
                    const analysis::WallSegments& walls, double time, int widthPoints = 595);

}  // namespace granulab::app
