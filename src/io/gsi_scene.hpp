// SPDX-License-Identifier: MIT
// gc2d's gsi scenes read natively (gc2d spec 9.2-9.3; docs/coming-from-gc2d.md): the document of
// io/gsi_syntax.hpp becomes a model::SceneDef of the dem engine, the same Defs the native TOML
// scene gives, so the engine's checks name the gsi lines (every Def carries the file:line of its
// object or keyword).
//
// Mapping (one decision per keyword; gc2d's defaults where a keyword is absent; SI units):
//   GENERAL
//     DELTA_T -> dem.dt (1e-4); TIME t0 t1 -> run.start_time = t0 (a restart from a gso; a whole
//     number of steps), run.end_time = t1; integrator "gear", broad phase "sort_and_sweep", mass model
//     "disk" (areal density 5000 kg/m^2, the thesis's, for material "grain"; walls are material
//     "wall"); one [[contact]] ["*", "*"]: normal "area" (E = E_MODUL 1e7, cohesion = COHESION 0),
//     damping "gamma" (GAMMA 0.5), tangential "gc2d" (mu = MUE_STATISCH 0.6; MUE_DYNAMISCH is read
//     and unused, as in gc2d);
//     G g -> gravity (0, -g) (9.81); G g1 g2 -> variable gravity (machines.gravity) with G_TIME,
//     G_PARAMETER, G_TYPE (without a second G value those three are ignored, as gc2d without
//     USE_VARIABLE_G ignores them); HEAT_* -> size scaling (any HEAT_ keyword switches it on,
//     unless HEAT_TIME is inf inf, its default: spec 2.4's audit note, s = 1; HEAT_SLOPE default 10);
//     STEPS_DATA n -> output.series_interval and snapshot_interval n dt (10000);
//     STEPS_CHECKPOINT n -> output.checkpoint_interval n dt (10000); a count of 2^32 - 1 or more
//     (gc2d's infinity) -> only at the end;
//     SEED s1 s2 -> run.seed = s1 2^32 + s2 for whole numbers below 2^32 (else a hash of both
//     numbers' bits); BASENAME -> run.title and output.gc2d_basename (its file name part);
//     output.gc2d on (gc2d's legacy files, app/dem/gc2d_files.hpp): STEPS_SETUP n ->
//     gc2d_setup_interval n dt (numbered gso/gco), STEPS_DUMPLINE n -> gc2d_line_interval n dt (gpl),
//     NEXT_DATA_FILENUMBER / NEXT_SETUP_FILENUMBER -> the first NNNN; EMAIL is read and not used.
//   DISPLAY: gc2d's window (range, size, redraw interval, modes): read and not used (granulab
//     renders afterwards: `granulab render`).
//   WALL k -> [[wall]] "wall<k>": kind "polygon" (an immovable convex body, gc2d's wall), points =
//     CORNERS (absolute), offset OFFSET, angle -ANGLE (gc2d turns clockwise), surface_velocity
//     VELOCITY (a belt); PISTON_FORCE != 0 -> a piston (PISTON_ANGLE direction, counter-clockwise
//     from +x, default 0; PISTON_V_MAX 1); any VIB_ keyword -> vibration (VIB_TYPE COSINUS ->
//     "cosine", ...; VIB_ANGLE pi/2, VIB_WIDTH 1, VIB_FREQUENCE 1, VIB_TIME 0 .. never). ID ->
//     WallDef::gc2dId (the ids of a gci, io/gc2d_ids.hpp).
//   PARTICLE k -> a [[shape]] "particle<k>" (kind "polygon", CORNERS) and a [[particle]] of it at
//     COM (0, 0) or, with POSITION_ABSOLUT, at the corners' centroid; angle -ANGLE, omega -OMEGA,
//     velocity VELOCITY, material "grain". DRAG_* (any of them) -> a [[spring]] on it: k DRAG_K 100,
//     attach DRAG_FIXING_POINT (body frame), pull_start DRAG_PULLING_POINT, speed DRAG_VELOCITY
//     0.1, direction DRAG_ANGLE 0, DRAG_TIME 0 .. 1. The restart state of a gso -> ParticleDef::gear:
//     ACCELERATION, OMEGA_DOT (r2 = dt^2/2 a), PC_TRANS3-5 and PC_ROT3-5 (the scaled r3..r5, rotations
//     clockwise). ID -> ParticleDef::gc2dId (granulab numbers the PARTICLEs first, then the blocks'
//     grains; the id names the grain in a gci).
//   The gci beside the file (foo.gsi -> foo.gci, io/gci_file.hpp), when there is one, gives
//   SceneDef::rememberedContacts; its line 2 must equal the gsi's (else an error at gci:2).
//   GENERATE_BLOCK k -> a [[shape]] "block<k>" (kind "grain": PART_SIZE semi-axes 1 1, as the
//     spec's erratum 26 keeps them, PART_VAR_SIZE 0.5, RANDOM_SIZE, PART_NUM_CORNERS 6,
//     PART_VAR_CORNERS 2, RANDOM_NUM_CORNERS, PART_RANDOM_POS_CORNERS REGULAR, PART_ROT with its
//     sign turned, RANDOM_ROT) and a [[block]]: GRID_TYPE RECT* -> lattice "rect", FCC* -> "fcc",
//     *_GAUSS / *_EQUAL -> jitter "gauss" / "equal"; region X_RANGE x Y_RANGE (0 .. 10 each);
//     grid GRID_DISTANCE (2, 2); direction_range ANGLE_RANGE (0 .. 2 pi), speed_range
//     VELOCITY_RANGE (0, 0); material "grain".
//   DROPSOURCE k -> a [[shape]] "source<k>" (kind "grain" with DROPSOURCE's defaults: PART_SIZE
//     0.01 0.01, PART_VAR_SIZE 0.1, PART_NUM_CORNERS 8, PART_VAR_CORNERS 2) and a [[source]]:
//     position POS (0, 0.01), placement TYPE (ABS), width WIDTH 0, interval DELTA_T 0.1, TIME
//     0 .. 1, material "grain".
#pragma once
#include <string>

#include "io/gsi_syntax.hpp"
#include "model/scene_def.hpp"

namespace granulab::io {

/// True for a path that names a gsi scene (ends in .gsi or .gsi.gz, any case).
bool isGsiPath(const std::string& path);

/// The scene of a parsed gsi document. Throws SceneError listing every problem (file:line).
model::SceneDef gsiToScene(const GsiDocument& doc);

/// Reads and maps a gsi file; a .gz file is decompressed as it is read (gc2d: gunzip first).
/// Throws SceneError (a missing, unreadable or damaged file too).
model::SceneDef readGsiFile(const std::string& path);

}  // namespace granulab::io
