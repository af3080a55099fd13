// SPDX-License-Identifier: MIT
// Plain *Def structs of the dem engine's scene sections ([dem], [[material]], [[contact]],
// [[shape]], [[particle]], [[block]], [[heap]], [[wall]], [[spring]]; docs/scene-format.md), filled by
// io/dem_sections.hpp. SI units; 2D masses are per unit depth when the mass model is "disk".
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace granulab::model {

/// Global viscous damping F = -gamma v on every particle while from <= t < to (LAMMPS fix viscous).
struct DampingWindowDef {
    Real gamma = 0;          ///< [kg/s] drag coefficient per particle (areal 2D: [kg/(m s)])
    Real gammaRotation = 0;  ///< [kg m^2/s] rotational drag, torque = -gammaRotation * omega
    Real from = 0;           ///< [s]
    Real to = 1e300;         ///< [s]
    SourceLoc loc;
};

struct DemDef {
    Real dt = 0;  ///< [s] time step (required)
    std::string integrator =
        "auto";  ///< auto (gear with polygons, else verlet) | verlet | euler | pc (cfddem seed) | gear (gc2d)
    Real pcTolerance = 1e-5;          ///< pc: |a^c - a^p| threshold [m/s^2]
    std::int64_t pcIterations = 10;   ///< pc: corrector iterations, 0 = modified explicit Euler
    Real pcCorrector = 0.5;           ///< pc: relaxation factor in (0, 1]
    Real gearC0 = 3.0 / 16.0;         ///< gear: first corrector coefficient
    std::string broadPhase = "auto";  ///< auto (sort_and_sweep with polygons, else cell_grid) | cell_grid |
                                      ///< sort_and_sweep | brute_force
    Real skin = -1;                   ///< [m] neighbour-list skin; <0: 0.2 * largest radius
    std::string massModel =
        "disk";  ///< "disk": m = rho pi r^2, I = m r^2/2; "sphere": m = 4/3 rho pi r^3, I = 2/5 m r^2
    std::int64_t sortEvery = 16;   ///< re-sort slots spatially every k-th rebuild (0: never)
    bool overlapGuard = false;     ///< skip pair contacts deeper than 1 % of the smaller radius (cfddem seed)
    Vec2 gravity{0, 0};            ///< [m/s^2]
    bool weight = true;            ///< m g on every particle (cfddem #Fg); off: g still sets buoyancy
    bool particleContacts = true;  ///< particle-particle contact forces (cfddem #FP)
    bool wallContacts = true;      ///< particle-wall contact forces (cfddem #FB)
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
    Real value = 0;         ///< constant radius
    Real min = 0, max = 0;  ///< uniform bounds, or truncation bounds of the Gaussian
    Real mean = 0, sigma = 0;
    SourceLoc loc;
};

/// A named grain shape (gc2d spec section 2.3), referenced by particles and blocks through
/// `shape = "name"`. "disk" is built in and needs no [[shape]].
struct ShapeDef {
    std::string name;
    std::string kind;  ///< "polygon" | "regular" | "rectangle" | "ellipse" | "grain"
    std::vector<Vec2>
        corners;  ///< polygon: [m] corners, counter-clockwise, any frame (re-centred at the centroid)
    std::int64_t cornerCount = 0;  ///< regular, ellipse: number of corners N >= 3; grain: N_E
    Real radius = 0;               ///< regular: [m] circumscribed radius
    Vec2 size;  ///< rectangle: [m] edge lengths (a, b); ellipse, grain: [m] semi-axes (l_x, l_y)
    Real chamfer =
        0;  ///< rectangle: fraction c in [0, 0.5) of each edge cut at each corner (gc2d_rectangle_cut)
    // grain only (gc2d App. B.1.6): random convex polygons inscribed in ellipses
    std::string cornerAngles = "rand1";  ///< regular | rand1 | rand2 | full | special_rectangle
    std::string sizeMode = "const";      ///< const | equal | gauss
    Real sizeVariation = 0;              ///< I in [0, 1): semi-axes drawn in [l (1 - I), l (1 + I)]
    bool fullAxes = false;  ///< size gives full axes instead of semi-axes (spec audit note, erratum 26)
    std::string cornerCountMode = "const";  ///< const | equal | gauss
    std::int64_t cornerVariation = 0;       ///< N_I: corner count drawn in [N_E - N_I, N_E + N_I]
    std::string rotationMode = "const";     ///< const | equal | gauss (applies to every shape kind)
    Real rotation = 0;                      ///< [rad] phi_0, counter-clockwise
    SourceLoc loc;
};

struct ParticleDef {
    std::string shape = "disk";  ///< "disk" or the name of a [[shape]]
    Vec2 position, velocity;     ///< [m], [m/s]
    Real angle = 0;              ///< [rad], counter-clockwise
    Real omega = 0;              ///< [rad/s]
    Real radius = 0;             ///< [m] disks only (polygon sizes come from their [[shape]])
    std::string material;
    /// gc2d restart (a gso's ACCELERATION, OMEGA_DOT, PC_TRANS3-5, PC_ROT3-5): the Gear
    /// predictor's scaled derivatives r_n = dt^n/n! d^n/dt^n, n = 2..5, of x, y [m] and phi [rad]
    /// (counter-clockwise), kGearValues of them; empty: the integrator starts from the first forces.
    static constexpr std::size_t kGearValues = 12;
    std::vector<Real> gear;
    std::int64_t gc2dId = -1;  ///< gc2d id of a gsi PARTICLE with ID (io/gc2d_ids.hpp); -1: none
    SourceLoc loc;
};

/// A block of generated particles: a lattice filling a region, or random non-overlapping
/// placement of `count` particles in a region.
struct BlockDef {
    enum class Lattice { Hexagonal, Square, Random, Rect, Fcc };
    /// Site displacement of the rect and fcc lattices (gc2d GRID_TYPE *_GAUSS / *_EQUAL).
    enum class Jitter { None, Gauss, Equal };
    Lattice lattice = Lattice::Hexagonal;
    std::string shape = "disk";  ///< "disk" or the name of a [[shape]] (each particle draws its own grain)
    Real xmin = 0, ymin = 0, xmax = 0, ymax = 0;  ///< [m] region, half-open [min, max)
    Real spacing = 0;                             ///< [m] lattice constant (nearest neighbours)
    std::optional<Vec2> origin;                   ///< [m] one lattice site; default region corner + spacing/2
    std::int64_t count = -1;                      ///< random: number to place; lattices: cap (-1 none)
    SizeDistDef radius;
    std::string material;
    Vec2 velocity;         ///< [m/s] common velocity
    Real temperature = 0;  ///< [J] random Gaussian velocities, <m v_x^2> = T, zero net momentum
    // gc2d GENERATE_BLOCK (spec section 6.5; docs/scene-format.md "gc2d lattices and velocity ranges")
    Vec2 grid;  ///< rect, fcc: [m] (dx, dy) spacing along x and between rows (GRID_DISTANCE)
    Jitter jitter = Jitter::None;     ///< rect, fcc: displacement of each site within +-dx/2, +-dy/2
    Real jitterFraction = 1;          ///< scales the jitter interval, (0, 1]
    Vec2 directionRange{0, 2 * kPi};  ///< [rad] velocity direction, uniform in [a1, a2] (ANGLE_RANGE)
    Vec2 speedRange{0, 0};            ///< [m/s] velocity magnitude, uniform in [v1, v2] (VELOCITY_RANGE)
    SourceLoc loc;
};

/// A regular pile (gc2d heap.pm, spec section 6.5 "Perl heap library"): rows of equal grains
/// (disks, plain rectangles, or a named rectangle or regular [[shape]]) stacked on the base
/// y = base between x_range, every centre under the slope lines rising at angle `slope` from both
/// ends (docs/scene-format.md "[[heap]]").
struct HeapDef {
    enum class Stacking { Hexagonal, Rectangular };
    Stacking stacking =
        Stacking::Hexagonal;     ///< hexagonal: rows shifted by half a pitch; rectangular: columns
    Real xLeft = 0, xRight = 0;  ///< [m] ends of the pile (x_l, x_r)
    Real base = 0;               ///< [m] y0: the bottom row stands on y = base
    Real slope = 0;              ///< [rad] psi, angle of the flanks
    Vec2 gap;                    ///< [m] (dx, dy) gaps between row neighbours and between rows
    std::string shape = "disk";  ///< "disk", or the name of a rectangle or regular [[shape]]
    Real radius = 0;             ///< [m] disks
    Vec2 size;                   ///< [m] (a, b) plain rectangles (a along x); (0, 0): not used
    std::string material;
    SourceLoc loc;
};

struct WallDef {
    std::string name;
    std::vector<Vec2> points;       ///< [m] polyline corners (a segment has two), or polygon corners
    bool closed = false;            ///< join the last corner to the first
    std::string kind = "polyline";  ///< polyline (segments, containers) | polygon (a convex body)
    Vec2 offset;                    ///< [m] gc2d OFFSET: translation of the points
    Real angle = 0;                 ///< [rad] rotation of the points about their centroid, counter-clockwise
    std::string material;
    Vec2 velocity;         ///< [m/s] prescribed rigid translation
    Vec2 surfaceVelocity;  ///< [m/s] conveyor belt (gc2d VELOCITY): tangential part only, the wall rests
    // Vibration (gc2d VIB_*, spec 6.4); vibType empty: none.
    std::string vibType;              ///< cosine | sawtooth | tapping | triangle
    Real vibDirection = kPi / 2;      ///< [rad]
    Real vibWidth = 0;                ///< [m] W
    Real vibFrequency = 0;            ///< [1/s]
    Real vibFrom = 0, vibTo = 1e300;  ///< [s]
    // Piston (gc2d PISTON_*, spec 6.3); pistonForce unset: none.
    std::optional<Real> pistonForce;  ///< [N] target force (per unit depth)
    Real pistonDirection = -kPi / 2;  ///< [rad] direction of motion
    Real pistonMaxSpeed = 1;          ///< [m/s] PISTON_V_MAX
    Real pistonGain = 0;              ///< [m/(N s)] 0: pistonMaxSpeed / pistonForce
    Real pistonFrom = 0;              ///< [s]
    // Rotation about a pivot (a truly rotating drum).
    Real omega = 0;             ///< [rad/s]
    std::optional<Vec2> pivot;  ///< [m] default: the centroid of the points
    Real solidUntil = 1e300;    ///< [s] set for an outlet's lid, not a scene key
    std::int64_t gc2dId = -1;   ///< gc2d id of a gsi WALL with ID (io/gc2d_ids.hpp); -1: none
    SourceLoc loc;
};

/// gc2d restart: one COLLISION section of a gci file (gc2d spec 9.4; io/gci_file.hpp), the
/// remembered state of the contact of the objects with gc2d ids id1 and id2 (io/gc2d_ids.hpp).
struct RememberedContactDef {
    std::int64_t id1 = -1, id2 = -1;
    Real friction = 0;  ///< [N] Summ_Friction: the tangential spring force k_t xi
    Real oldArea = 0;   ///< [m^2] Old_Area: the overlap area of the last step
    SourceLoc loc;
};

/// A linear spring pulling a particle (gc2d DRAG_*, spec section 3.8): one end is attached to
/// the particle at a body-frame point (it rotates with the particle, may lie outside it); the
/// free end starts at `pullStart` and moves with `speed` along `direction` while from <= t <= to
/// (it rests before and after). Force k (free end - attachment point), zero rest length, applied
/// at the attachment point (so it also makes a torque).
struct SpringDef {
    std::int64_t particle = -1;  ///< particle id (generation order: [[particle]]s, [[block]]s, [[heap]]s)
    Real stiffness = 0;          ///< [N/m] (gc2d DRAG_K, default 100)
    Vec2 attach;                 ///< [m] attachment point relative to the centroid, body frame
    Vec2 pullStart;              ///< [m] free end at t <= from (world frame)
    Real speed = 0;              ///< [m/s] speed of the free end
    Real direction = 0;          ///< [rad] direction of motion of the free end, counter-clockwise from +x
    Real from = 0, to = 1e300;   ///< [s] time window of the motion
    SourceLoc loc;
};

}  // namespace granulab::model
