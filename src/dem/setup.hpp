// SPDX-License-Identifier: MIT
// Builds the DEM world from validated *Def structs (DESIGN.md: engines are built from Defs and
// never see scene text), and derives the contact time and the advised time step.
#pragma once
#include <string>
#include <vector>

#include "core/error.hpp"
#include "dem/generate.hpp"
#include "dem/law_table.hpp"
#include "dem/step_clock.hpp"
#include "dem/world.hpp"
#include "model/scene_def.hpp"

namespace granulab::dem {

/// Resolves the [[contact]] entries into a law per material pair; an exact pair overrides a
/// "*" wildcard. Unknown laws, parameters and ranges go to `diags`.
LawTable buildLawTable(const model::SceneDef& scene, Diagnostics& diags);

/// Contact time and time-step limits of the stiffest, lightest contact of the scene.
struct TimeStepAdvice {
    Real contactTime = 0;     ///< [s] duration of a binary collision (damped linear law)
    Real advisedDt = 0;       ///< [s] min(contactTime / 50, stabilityLimit / 10)
    Real stabilityLimit = 0;  ///< [s] 2 / omega_max: velocity Verlet is unstable above it
    std::string pair;         ///< which contact sets the limit, e.g. "grain-grain"
    Real areaAdvisedDt = 0;   ///< [s] gc2d rule (pi/10) sqrt(m_min/E) of the area-law contacts (0: none)
    std::string areaPair;     ///< which area-law contact sets it
    Real faceAdvisedDt =
        0;  ///< [s] (pi/10) sqrt(m/k_face) with the flat-face stiffness of polygons (0: none)
    std::string faceParticle;  ///< which particle sets it
};

/// `usedByWalls[m]` tells which materials walls use; `minMass[m]` [kg] and `minRadius[m]` [m] are
/// the lightest and smallest particle of material m (0: no particle). Nonlinear (Hertz) contacts
/// are analysed for an impact at `speed` [m/s].
TimeStepAdvice adviseTimeStep(const LawTable& laws, const std::vector<std::string>& names,
                              const std::vector<Real>& minMass, const std::vector<Real>& minRadius,
                              const std::vector<bool>& usedByWalls, Real speed);

/// True if some particle or block of the scene uses a polygon [[shape]].
bool hasPolygons(const model::SceneDef& scene);
/// The integrator and broad phase a scene runs with ("auto": gear and sort_and_sweep with
/// polygons, the gc2d defaults; verlet and cell_grid otherwise).
std::string integratorOf(const model::SceneDef& scene);
std::string broadPhaseOf(const model::SceneDef& scene);

/// The gc2d rule assumes round grains; a flat face of length L at lever arm l is stiffer,
/// k = E L / l (two squares face to face: 4 E). Bounds it by k_face = max(E, 2 E L_max / r_in)
/// (L_max the longest edge, l >= r_in / 2 between two grains, r_in the inradius) for every
/// polygon particle and fills advice.faceAdvisedDt with the smallest (pi/10) sqrt(m / k_face).
/// `density` by material index.
void adviseFaceTimeStep(const LawTable& laws, const InitialParticles& initial,
                        const std::vector<Real>& density, TimeStepAdvice& advice);

/// Translates the scene's damping windows etc. into the engine configuration.
WorldConfig makeWorldConfig(const model::SceneDef& scene, Real maxRadius);

/// The world at t = 0 (call initialize() before stepping, or loadState()). `fields`: where the
/// flow fields of [fluid] come from (the app builds it from the field files; ignored without
/// [fluid]; an empty loader means the uniform fluid.velocity).
World makeWorld(const model::SceneDef& scene, const InitialParticles& initial,
                fluid::FieldSource fields = {});

/// The fluid-force parameters of [fluid] (cfddem spec 5).
FluidForceConfig fluidForceConfig(const model::FluidDef& def);

}  // namespace granulab::dem
