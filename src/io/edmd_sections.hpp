// SPDX-License-Identifier: MIT
// Reader of the edmd engine's scene section [edmd], the event-driven hard-sphere gas
// (docs/scene-format.md "[edmd]"; edmd spec sections 2, 4).
#pragma once
#include "io/scene_reader.hpp"

namespace granulab::io {

/// The edmd engine's row of the scene reader: [edmd] required; the run may end by
/// edmd.end_tau or edmd.end_collisions instead of run.end_time.
SceneSections edmdSceneSections();

}  // namespace granulab::io
