// SPDX-License-Identifier: MIT
// The flow fields of a scene's [fluid] section (cfddem spec 5.5; docs/scene-format.md "[fluid]"):
// expands the `fields` entries into files (io/flow_field_reader.hpp), reads every file once to
// check it (velocity array present, finite values, usable by the chosen interpolation), resolves
// the time of each field (the seed's even spread over the run, or the files' own times) and
// returns the lazy loader the DEM world calls when the next field is due.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "fluid/field_series.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

struct OpenedFields {
    fluid::FieldSource source;       ///< for dem::makeWorld
    std::vector<std::string> files;  ///< in time order
    std::string timing;              ///< "even", "file" or "uniform"
    std::size_t nodes = 0;           ///< of the first field
    std::string method;              ///< interpolation of the first field
    /// The field that applies at t = 0 (for the coverage check of the set-up; released after it).
    std::shared_ptr<const fluid::FieldInterpolator> first;
};

/// The interpolation options of [fluid].
fluid::InterpolatorOptions interpolatorOptions(const model::FluidDef& def);

/// Problems (missing or malformed files, a missing array, NaN, unusable interpolation, times that
/// are missing or not ascending) go to `diags` at the fields' scene lines. Without [fluid] or
/// without files: a source with no loader (the uniform fluid.velocity).
OpenedFields openFlowFields(const model::SceneDef& scene, Diagnostics& diags);

}  // namespace granulab::io
