// SPDX-License-Identifier: MIT
// Shared DEM test scenes.
#pragma once
#include <string>

namespace granulab::test {

/// A dense, polydisperse bed of ~1500 disks (12 slot tiles) with rolling resistance, frictional
/// walls and a damped start, so that contacts, cross-tile pairs and wall forces all occur within a
/// few hundred steps (gravity 500 m/s^2 compacts it).
inline const std::string kRollingDiskBed = R"(
[run]
seed = 7
end_time = 1.0
[dem]
dt = 1.0e-4
gravity = [0.0, -500.0]    # compacts the bed within ~200 steps
skin = 0.1
[[dem.damping]]
gamma = 0.5
from = 0.0
to = 0.02
[[material]]
name = "g"
density = 1.0
[[contact]]
materials = ["*", "*"]
normal = "hooke"
kn = 2.0e5
damping = "lammps"
gamma_n = 50.0
tangential = "cundall_strack"
mu = 0.5
rolling = "spring_dashpot"
k_r = 50.0
D_r = 0.3
[[block]]
lattice = "hexagonal"
spacing = 1.1
origin = [0.6, 0.6]
region = [0.1, 0.1, 40.0, 40.0]
radius = { distribution = "uniform", min = 0.45, max = 0.55 }
material = "g"
temperature = 50.0
[[wall]]
points = [[0.0, 60.0], [0.0, 0.0], [40.6, 0.0], [40.6, 60.0]]
material = "g"
)";

}  // namespace granulab::test
