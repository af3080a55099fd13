// SPDX-License-Identifier: MIT
// The edmd engine's set-up from a scene whose [edmd] Defs io::checkEdmdDef has checked (edmd
// spec sections 2 and 4): the resolved box/count/volume fraction, the engine configuration, the
// initial state (lattice or random placement, Maxwell velocities) and the kinetic-theory scales
// the run reports (t_E, tau, TC default). Problems throw SceneError with file:line.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "edmd/engine.hpp"
#include "edmd/initial_state.hpp"
#include "model/scene_def.hpp"

namespace granulab::edmd {

struct Setup {
    int dim = 3;
    EngineConfig config;      ///< production run (restitution, TC, walls, gravity, growth)
    InitialStateSpec init;    ///< resolved count, box and radii
    Real volumeFraction = 0;  ///< nu of the initial state (Eq. 4.2-4.4; mean particle volume if polydisperse)
    Real tE = 0;              ///< [s] initial Enskog collision time 1/f_E(0) (Eq. 4.33, g from Eq. 4.52)
    Real lambda = 0;          ///< 1 - eps^2 (Eq. 4.7), constant restitution
    Real endTime = 0;         ///< [s] resolved end (run.end_time or edmd.end_tau); +inf with end_collisions
    std::uint64_t endCollisions = 0;  ///< total collisions to run (edmd.end_collisions * N / 2), 0: unused
    std::uint64_t equilibrationCollisions = 0;  ///< elastic pre-run (edmd.equilibrate * N / 2)
    std::vector<std::string> warnings;
};

/// Resolves a checked [edmd] scene; throws SceneError with all problems of the resolved values
/// (count, close packing, run length, box too small for the cells). Does not build the
/// particles (makeGasState does, reporting placement failures with the scene location).
Setup resolveScene(const model::SceneDef& scene);

/// The initial particles of a resolved scene; placement failures become a SceneError at
/// edmd.volume_fraction / edmd.count.
template <int D>
GasState<D> makeGasState(const model::SceneDef& scene, const Setup& setup);

}  // namespace granulab::edmd
