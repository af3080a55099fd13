// SPDX-License-Identifier: MIT
// Reader of the dem engine's scene sections: [dem] with [[dem.damping]], [[material]],
// [[contact]], [[shape]], [[particle]], [[block]], [[wall]], [[spring]] (docs/scene-format.md).
#pragma once
#include "io/scene_reader.hpp"

namespace granulab::io {

/// The dem engine's row of the scene reader: its sections, [dem] required, run.end_time required.
SceneSections demSceneSections();

}  // namespace granulab::io
