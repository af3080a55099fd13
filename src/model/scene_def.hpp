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
    std::string engine = "dem";   ///< "dem" | "edmd" (event-driven hard spheres)
    int dimension = 2;            ///< spatial dimension; dem supports 2, edmd 2 and 3
    std::uint64_t seed = 1;       ///< seed of every random draw in scene generation
    Real endTime = 0;             ///< [s] simulated time at which the run stops (edmd: or edmd.end_tau / end_collisions)
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
    std::string integrator = "auto";      ///< auto (gear with polygons, else verlet) | verlet | euler | pc (cfddem seed) | gear (gc2d)
    Real pcTolerance = 1e-5;              ///< pc: |a^c - a^p| threshold [m/s^2]
    std::int64_t pcIterations = 10;       ///< pc: corrector iterations, 0 = modified explicit Euler
    Real pcCorrector = 0.5;               ///< pc: relaxation factor in (0, 1]
    Real gearC0 = 3.0 / 16.0;             ///< gear: first corrector coefficient
    std::string broadPhase = "auto";      ///< auto (sort_and_sweep with polygons, else cell_grid) | cell_grid | sort_and_sweep | brute_force
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

/// A named grain shape (gc2d spec section 2.3), referenced by particles and blocks through
/// `shape = "name"`. "disk" is built in and needs no [[shape]].
struct ShapeDef {
    std::string name;
    std::string kind;              ///< "polygon" | "regular" | "rectangle" | "ellipse" | "grain"
    std::vector<Vec2> corners;     ///< polygon: [m] corners, counter-clockwise, any frame (re-centred at the centroid)
    std::int64_t cornerCount = 0;  ///< regular, ellipse: number of corners N >= 3; grain: N_E
    Real radius = 0;               ///< regular: [m] circumscribed radius
    Vec2 size;                     ///< rectangle: [m] edge lengths (a, b); ellipse, grain: [m] semi-axes (l_x, l_y)
    Real chamfer = 0;              ///< rectangle: fraction c in [0, 0.5) of each edge cut at each corner (gc2d_rectangle_cut)
    // grain only (gc2d App. B.1.6): random convex polygons inscribed in ellipses
    std::string cornerAngles = "rand1";  ///< regular | rand1 | rand2 | full | special_rectangle
    std::string sizeMode = "const";      ///< const | equal | gauss
    Real sizeVariation = 0;              ///< I in [0, 1): semi-axes drawn in [l (1 - I), l (1 + I)]
    bool fullAxes = false;               ///< size gives full axes instead of semi-axes (spec audit note, erratum 26)
    std::string cornerCountMode = "const";  ///< const | equal | gauss
    std::int64_t cornerVariation = 0;       ///< N_I: corner count drawn in [N_E - N_I, N_E + N_I]
    std::string rotationMode = "const";     ///< const | equal | gauss (applies to every shape kind)
    Real rotation = 0;                      ///< [rad] phi_0, counter-clockwise
    SourceLoc loc;
};

struct ParticleDef {
    std::string shape = "disk";  ///< "disk" or the name of a [[shape]]
    Vec2 position, velocity;  ///< [m], [m/s]
    Real angle = 0;           ///< [rad], counter-clockwise
    Real omega = 0;           ///< [rad/s]
    Real radius = 0;          ///< [m] disks only (polygon sizes come from their [[shape]])
    std::string material;
    SourceLoc loc;
};

/// A block of generated particles: a lattice filling a region, or random non-overlapping
/// placement of `count` particles in a region.
struct BlockDef {
    enum class Lattice { Hexagonal, Square, Random };
    Lattice lattice = Lattice::Hexagonal;
    std::string shape = "disk";  ///< "disk" or the name of a [[shape]] (each particle draws its own grain)
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

/// A linear spring pulling a particle (gc2d DRAG_*, spec section 3.8): one end is attached to
/// the particle at a body-frame point (it rotates with the particle, may lie outside it); the
/// free end starts at `pullStart` and moves with `speed` along `direction` while from <= t <= to
/// (it rests before and after). Force k (free end - attachment point), zero rest length, applied
/// at the attachment point (so it also makes a torque).
struct SpringDef {
    std::int64_t particle = -1;  ///< particle id (generation order: [[particle]]s, then [[block]]s)
    Real stiffness = 0;          ///< [N/m] (gc2d DRAG_K, default 100)
    Vec2 attach;                 ///< [m] attachment point relative to the centroid, body frame
    Vec2 pullStart;              ///< [m] free end at t <= from (world frame)
    Real speed = 0;              ///< [m/s] speed of the free end
    Real direction = 0;          ///< [rad] direction of motion of the free end, counter-clockwise from +x
    Real from = 0, to = 1e300;   ///< [s] time window of the motion
    SourceLoc loc;
};

struct OutputDef {
    Real snapshotInterval = 0;    ///< [s] VTK snapshot period (0: first and last only)
    Real seriesInterval = 0;      ///< [s] series.csv period (0: 100 rows over the run)
    Real checkpointInterval = 0;  ///< [s] checkpoint period (0: only at the end)
    bool vtk = true;
    SourceLoc loc;
};

/// The event-driven hard-sphere gas (edmd spec sections 2, 4; docs/scene-format.md "[edmd]").
/// Units: SI, or the thesis' reduced units m = a = T0 = 1 (any consistent set works).
struct EdmdDef {
    std::vector<Real> box;             ///< [m] edge per axis; empty: a cube/square from count and volume_fraction
    std::vector<bool> periodic;        ///< per axis; empty: all periodic. false: hard walls at 0 and box
    std::int64_t count = 0;            ///< particles; 0: from box and volume_fraction
    Real volumeFraction = 0;           ///< nu (edmd Eq. 4.2-4.4); 0: from count and box
    Real radius = 0;                   ///< [m] a (lower bound when radius_max is given)
    Real radiusMax = 0;                ///< [m] polydisperse: radii uniform in [radius, radius_max]
    Real mass = 1;                     ///< [kg] mass of a particle of radius `radius`; others scale as r^D
    std::string placement = "lattice"; ///< lattice | random
    Real temperature = 1;              ///< [J] T0 = m <v_x^2> of the Maxwell start (k_B = 1)
    Real equilibrate = 100;            ///< collisions per particle of the elastic pre-run (spec 4.2: 100), 0: none
    Real restitution = 1;              ///< eps between particles
    std::string restitutionModel = "constant";  ///< constant | mcnamara_falcon | viscoelastic
    Real restitutionSpeed = 0;         ///< [m/s] v0 of the speed-dependent models
    Real wallRestitution = 1;          ///< eps at the walls
    Real tangentialRestitution = -1;   ///< phi in [-1, 1]; -1: smooth spheres, no spin
    Real inertiaFactor = 0;            ///< z = I/(m a^2); 0: 0.4 (spheres) / 0.5 (disks)
    Real tc = -1;                      ///< [s] TC-model contact time; -1: 1e-5 t_E(0) when eps < 1, else off; 0: off
    std::vector<Real> gravity;         ///< [m/s^2] per axis; empty: none
    Real growthRate = 0;               ///< [m/s] u_a, radii grow as a0 + u_a t (periodic boxes)
    Real cellSize = 0;                 ///< [m] lower bound of the cell edge; 0: automatic
    std::string queue = "calendar";    ///< calendar | heap | tree
    Real endTau = 0;                   ///< stop at this scaled time tau = lambda t/(2 D t_E) (edmd Eq. 4.57), 0: unused
    Real endCollisions = 0;            ///< stop after this many collisions per particle, 0: unused
    std::string series = "linear";     ///< linear | log: spacing of the series.csv rows
    std::int64_t seriesPoints = 100;   ///< rows of series.csv
    Real seriesFirst = 0;              ///< [s] first row time of a log series; 0: t_E(0)/100
    bool clusters = true;              ///< cluster statistics in every series row (union-find, O(N))
    Real clusterDelta = 0.1;           ///< delta/2a of the cluster criterion (edmd Eq. 5.11)
    bool analysisFiles = true;         ///< g(r), p(v), density and cluster-size files at every snapshot
    SourceLoc loc;
};

struct SceneDef {
    std::string path;  ///< scene file
    RunDef run;
    DemDef dem;
    std::vector<MaterialDef> materials;
    std::vector<ContactDef> contacts;
    std::vector<ShapeDef> shapes;
    std::vector<ParticleDef> particles;
    std::vector<BlockDef> blocks;
    std::vector<WallDef> walls;
    std::vector<SpringDef> springs;
    OutputDef output;
    EdmdDef edmd;
    bool hasEdmd = false;  ///< an [edmd] section was given
    bool hasDem = false;   ///< a [dem] section was given
};

}  // namespace granulab::model
