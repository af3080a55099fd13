// SPDX-License-Identifier: MIT
// The dem engine's set-up from a scene whose Defs io::checkDemDef has checked: contact laws,
// particles (generated deterministically from the seed), start overlaps and the time-step
// advice; every problem is reported with file:line through Diagnostics.
#pragma once
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dem/generate.hpp"
#include "dem/setup.hpp"
#include "fluid/field_series.hpp"
#include "model/particle_store.hpp"
#include "model/scene_def.hpp"

namespace granulab::dem {

struct PreparedScene {
    InitialParticles initial;
    TimeStepAdvice advice;
    Real impactSpeed = 0;  ///< [m/s] speed used to analyse nonlinear contacts
    std::vector<std::string> warnings;
    /// [fluid]: where the flow fields come from (filled by the app from io's field files; no
    /// loader: the uniform fluid.velocity).
    fluid::FieldSource fields;
    std::string fieldsNote;  ///< e.g. "12 files (file times), bilinear on 3721 nodes"
};

/// Engine memory per disk [bytes], estimate: particle store + Verlet half-step velocities (24 B)
/// + neighbour-list reference positions (16 B) + cell grid (12 B) + ~3 candidate pairs per disk
/// (16 B each, history included). `granulab info` prints it; the validation checks it fits.
inline const double kDiskBytesPerParticle =
    static_cast<double>(model::ParticleStore::kBytesPerParticle) + 24 + 16 + 12 + 3 * 16;

/// The estimate for the particles of `init` (polygons add their state and corners) [bytes].
double bytesPerParticleEstimate(const InitialParticles& init);

/// Adds the engine's checks to `diags` (which may already hold the Def-level problems) and
/// throws SceneError listing all of them if any; otherwise returns the particles and advice.
PreparedScene prepareScene(const model::SceneDef& scene, Diagnostics& diags);

}  // namespace granulab::dem
