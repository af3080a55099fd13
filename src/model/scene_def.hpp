// SPDX-License-Identifier: MIT
// Plain *Def structs filled by the scene parsers (io/) and read by the engines (DESIGN.md
// "Configuration objects"). Engines never see scene text. SI units throughout; 2D masses are
// per unit depth when the mass model is areal ("disk").
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace granulab::model {

struct RunDef {
    std::string engine = "dem";   ///< "dem" (edmd and fluid coupling come with later issues)
    int dimension = 2;            ///< spatial dimension; dem supports 2
    std::uint64_t seed = 1;       ///< seed of every random draw in scene generation
    Real endTime = 0;             ///< [s] simulated time at which the run stops
    Real benchmarkFrom = -1;      ///< [s] report throughput separately from this time on (<0: off)
    std::string title;
    SourceLoc loc;
};

/// Global viscous damping F = -gamma v on every particle while from <= t < to (LAMMPS fix viscous).
struct DampingWindowDef {
    Real gamma = 0;       ///< [kg/s] drag coefficient per particle (areal 2D: [kg/(m s)])
    Real gammaRotation = 0;  ///< [kg m^2/s] rotational drag, torque = -gammaRotation * omega
    Real from = 0;        ///< [s]
    Real to = 1e300;      ///< [s]
    SourceLoc loc;
};

struct DemDef {
    Real dt = 0;                          ///< [s] time step (required)
    std::string integrator = "verlet";    ///< verlet | euler | pc (cfddem seed) | gear (gc2d)
    Real pcTolerance = 1e-5;              ///< pc: |a^c - a^p| threshold [m/s^2]
    std::int64_t pcIterations = 10;       ///< pc: corrector iterations, 0 = modified explicit Euler
    Real pcCorrector = 0.5;               ///< pc: relaxation factor in (0, 1]
    Real gearC0 = 3.0 / 16.0;             ///< gear: first corrector coefficient
    std::string broadPhase = "cell_grid"; ///< "cell_grid" | "brute_force"
    Real skin = -1;                       ///< [m] neighbour-list skin; <0: 0.2 * largest radius
    std::string massModel = "disk";       ///< "disk": m = rho pi r^2, I = m r^2/2; "sphere": m = 4/3 rho pi r^3, I = 2/5 m r^2
    std::int64_t sortEvery = 16;          ///< re-sort slots spatially every k-th rebuild (0: never)
    bool overlapGuard = false;            ///< skip pair contacts deeper than 1 % of the smaller radius (cfddem seed)
    Vec2 gravity{0, 0};                   ///< [m/s^2]
    std::vector<DampingWindowDef> damping;
    SourceLoc loc;
};

struct MaterialDef {
    std::string name;
    Real density = 0;        ///< [kg/m^2] areal density (mass model "disk"), [kg/m^3] ("sphere")
    Real youngsModulus = 0;  ///< [Pa] for Hertz/Mindlin laws (0: not set)
    Real poisson = 0;        ///< Poisson ratio, [0, 0.5)
    SourceLoc loc;
};

/// One numeric or boolean parameter of a contact law, with where it was written.
struct LawParamDef {
    Real value = 0;
    bool isBool = false;  ///< written as true/false
    SourceLoc loc;
};

/// Contact law for one pair of materials, decomposed by axis (DESIGN.md "Contact laws").
struct ContactDef {
    std::string materialA, materialB;
    std::string normal = "hooke";
    std::string damping = "none";
    std::string tangential = "none";
    std::string rolling = "none";
    std::map<std::string, LawParamDef> params;  ///< law parameters by key (kn, e, mu, ...)
    SourceLoc loc;
};

/// Size distribution of generated particles (radius for disks) [m].
struct SizeDistDef {
    enum class Kind { Constant, Uniform, Gaussian };
    Kind kind = Kind::Constant;
    Real value = 0;       ///< constant radius
    Real min = 0, max = 0;  ///< uniform bounds, or truncation bounds of the Gaussian
    Real mean = 0, sigma = 0;
    SourceLoc loc;
};

struct ParticleDef {
    std::string shape = "disk";
    Vec2 position, velocity;  ///< [m], [m/s]
    Real angle = 0;           ///< [rad], counter-clockwise
    Real omega = 0;           ///< [rad/s]
    Real radius = 0;          ///< [m]
    std::string material;
    SourceLoc loc;
};

/// A block of generated particles: a lattice filling a region, or random non-overlapping
/// placement of `count` particles in a region.
struct BlockDef {
    enum class Lattice { Hexagonal, Square, Random };
    Lattice lattice = Lattice::Hexagonal;
    std::string shape = "disk";
    Real xmin = 0, ymin = 0, xmax = 0, ymax = 0;  ///< [m] region, half-open [min, max)
    Real spacing = 0;                             ///< [m] lattice constant (nearest neighbours)
    std::optional<Vec2> origin;                   ///< [m] one lattice site; default region corner + spacing/2
    std::int64_t count = -1;                      ///< random: number to place; lattices: cap (-1 none)
    SizeDistDef radius;
    std::string material;
    Vec2 velocity;                                ///< [m/s] common velocity
    Real temperature = 0;  ///< [J] random Gaussian velocities, <m v_x^2> = T, zero net momentum
    SourceLoc loc;
};

struct WallDef {
    std::string name;
    std::vector<Vec2> points;  ///< [m] polyline corners (a segment has two)
    bool closed = false;       ///< join the last corner to the first
    std::string material;
    Vec2 velocity;             ///< [m/s] prescribed rigid translation
    SourceLoc loc;
};

struct OutputDef {
    Real snapshotInterval = 0;    ///< [s] VTK snapshot period (0: first and last only)
    Real seriesInterval = 0;      ///< [s] series.csv period (0: 100 rows over the run)
    Real checkpointInterval = 0;  ///< [s] checkpoint period (0: only at the end)
    bool vtk = true;
    SourceLoc loc;
};

struct SceneDef {
    std::string path;  ///< scene file
    RunDef run;
    DemDef dem;
    std::vector<MaterialDef> materials;
    std::vector<ContactDef> contacts;
    std::vector<ParticleDef> particles;
    std::vector<BlockDef> blocks;
    std::vector<WallDef> walls;
    OutputDef output;
};

}  // namespace granulab::model
