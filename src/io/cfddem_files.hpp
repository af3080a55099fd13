// SPDX-License-Identifier: MIT
// The cfddem seed's three input files read natively (cfddem spec 6.2-6.5; docs/scene-format.md
// "The cfddem seed's input files"): a folder holding conditions.txt, boundary.txt and
// startvalue.txt (or startvalues.txt) becomes a model::SceneDef of the dem engine, the same Defs
// that the native TOML scene would give (`granulab convert DIR scene.toml` writes that scene).
//
// Syntax (spec 6.2). The first line of each file is an info line and is ignored unless it starts
// with a key of that file. A line whose first non-blank characters are `//` is a comment. A data
// line starts with a 3-character, case-sensitive key `#XX` (`#` and two letters or digits; #Fg is
// not #FG) followed by numbers, separated by blanks, tabs, commas or semicolons; `//` ends the
// values. Every number after a key is appended to that key's list, so one line per particle, all
// values on one line and any mix work. Other lines (no `#`, or `#` followed by a blank) are
// skipped; an unknown `#XX` key is an error with a "did you mean" hint (and the file the key
// belongs to, for a key of another of the three files). Decimal commas are not supported.
//
// Mapping (one decision per key; units SI):
//   startvalue(s).txt, Tab. 4.2: one [[particle]] per index k of #RX #RY (required), #VX #VY #PH
//     #OM (optional, 0), #RA #RH #EM #NU (required): position (#RX, #RY) [m], velocity [m/s], angle
//     [rad], omega [rad/s], radius [m]. Every list must have as many values as #RX. Each distinct
//     (rho, E, nu) triple (exact equality) becomes a [[material]] "m1", "m2", ... in first-seen
//     order (the particles first, then the inlets), density [kg/m^3] (mass_model "sphere"),
//     youngs_modulus [Pa], poisson. Both spellings of the file name are accepted; both present is
//     an error.
//   boundary.txt, Tab. 4.4: one [[boundary]] (none when there are no edges): points (#PX, #PY);
//     #PZ, if given, must be 0 for every point (2D); #PB is read and ignored (display only). Edges
//     #E1 #E2 (1-based point indices, made 0-based) and #EB (1 "wall", 2 "outlet", 3 "inlet").
//     Wall edges (any #EB = 1) need #WE, #WN, #WM: a material "wall" (youngs_modulus #WE, poisson
//     #WN, no density: walls have no mass) and the particle-wall friction mu = #WM. Inlet edges
//     (spec 4.2 and its appendix: the new particles' state is in boundary.txt) take #VX #VY
//     (required), #PH #OM (optional, 0), #RA #RH #EM #NU (required), each with one value (shared by
//     every inlet) or one per inlet edge in edge order. When all inlets share one state it becomes
//     the boundary's `inlet` table; when they differ, each inlet edge becomes an [[inlet]] of its own
//     (edge, rate, the state; emission from t = 0, inset as for boundary inlets) and leaves the
//     boundary's edge list, in edge order. The rate is conditions.txt's #PS [1/s] (required with
//     inlets). #PS, #WE, #WN, #WM take one value each.
//   conditions.txt, Tab. 4.5 (one value per key): #DT -> dem.dt [s], #TE -> run.end_time [s] (both
//     required); integrator "pc" with #EP -> pc_tolerance (default 1e-5), #PK -> pc_iterations
//     (whole, default 10; 0 = modified Euler), #CO -> pc_corrector (default 0.5); dem.mass_model
//     "sphere", dem.gravity [0, -9.81], dem.overlap_guard = true (the seed's 1 % guard). Contact
//     laws: [[contact]] ["*", "*"] normal "hertz", damping "lehr" D_n = #Dn, tangential "mindlin"
//     mu = #MU, D_t = #Dt, rolling "spring_dashpot" k_r = #KR (an added key, spec 6.5 [R]), D_r =
//     #Dr; with walls a second [[contact]] ["wall", "*"] with the same laws and mu = #WM (#Dn #Dt
//     #Dr #MU #KR default 0). Flags (0 or 1): #Fg -> dem.weight, #FP -> dem.particle_contacts, #FB
//     -> dem.wall_contacts (default 1 each), #FG -> [attraction] with G = 6.674e-11 (default 0).
//     Fluid: #RF > 0 gives [fluid] density = #RF, drag "quadratic" with cw = 0.47 if #Fw = 1 else
//     "none", buoyancy = #FA (#Fw, #FA default 1), timing "even" (Eq. 4.2: the files spread evenly
//     over run.end_time), fields = the paths after the added key #CF (the CFD files, folder or
//     collection; relative to the folder of the three files; a path may be double-quoted), else
//     still fluid; #RF absent or 0 gives no [fluid] (#CF then is an error). Output: #SC n > 0 ->
//     output.series_interval = n dt and output.particle_series = true (the nine CSV/ files), #SC 0
//     (default) -> default series rows, no particle series; #SV n > 0 -> output.snapshot_interval
//     = n dt, #SV 0 (default) -> output.vtk = false. #PI (live plot) is read and ignored.
//   run.title is conditions.txt's info line; SceneDef::path is DIR/conditions.txt, so that relative
//   paths resolve against the folder. Every Def's location is the file:line of its key, so the
//   engine's checks name the trio's lines.
// Errors (all of the three files together, as a SceneError, exit status 2) name file:line: a
// missing file, a value that is not a number (or not finite, or not whole where a count or index is
// expected), a key with more values than it takes, list lengths that disagree within one table,
// an edge index outside [1, points], an edge type other than 1/2/3, a flag other than 0/1, a
// radius, density or modulus <= 0, a Poisson ratio outside [0, 0.5), missing required keys.
#pragma once
#include <string>

#include "model/scene_def.hpp"

namespace granulab::io {

/// True when `dir` is a directory holding conditions.txt, boundary.txt and startvalue.txt or
/// startvalues.txt.
bool isCfddemFolder(const std::string& dir);

/// True when `dir` is a directory holding at least one of the three files (so that a scene path
/// naming it is meant as cfddem input and a missing file is reported as such).
bool hasCfddemFiles(const std::string& dir);

/// Reads the three files of `dir` into a dem scene (mapping above). Throws SceneError listing every
/// problem with file:line (a folder without any of the three files: one error naming the folder).
model::SceneDef readCfddemFolder(const std::string& dir);

}  // namespace granulab::io
