// SPDX-License-Identifier: MIT
// What the command line hands an engine's factory besides the scene (app/engine_table.hpp).
#pragma once
#include <string>

namespace granulab::app {

struct SimulationOptions {
    std::string scenePath;
    bool quiet = false;  ///< no notes on the terminal (warnings are still shown)
};

}  // namespace granulab::app
