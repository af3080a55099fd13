// SPDX-License-Identifier: MIT
// `granulab info`: what a scene contains, the contact time and advised time step, and a memory
// estimate, without running it.
#pragma once
#include <string>
#include <vector>

#include "io/scene_reader.hpp"

namespace granulab::app {

int infoCommand(const std::string& scene, const std::vector<io::Override>& overrides);

/// `granulab help [laws]` text.
std::string helpText(const std::string& topic);

}  // namespace granulab::app
