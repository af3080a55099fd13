// SPDX-License-Identifier: MIT
// The one validation pass (DESIGN.md "one validate(SceneDef)"): every range and consistency
// check, particle generation, start overlaps and the time-step limit; all problems are
// reported together with file:line, key and the allowed range.
#pragma once
#include <string>
#include <vector>

#include "dem/setup.hpp"
#include "model/generate.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

struct ValidatedScene {
    model::InitialParticles initial;
    dem::TimeStepAdvice advice;
    Real impactSpeed = 0;  ///< [m/s] speed used to analyse nonlinear contacts
    std::vector<std::string> warnings;
};

/// Throws SceneError with every problem found; otherwise returns the generated particles.
ValidatedScene validate(const model::SceneDef& scene);

}  // namespace granulab::io
