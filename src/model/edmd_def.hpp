// SPDX-License-Identifier: MIT
// Plain *Def struct of the edmd engine's scene section [edmd] (docs/scene-format.md "[edmd]",
// edmd spec sections 2, 4), filled by io/edmd_sections.hpp.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace granulab::model {

/// The event-driven hard-sphere gas (edmd spec sections 2, 4; docs/scene-format.md "[edmd]").
/// Units: SI, or the thesis' reduced units m = a = T0 = 1 (any consistent set works).
struct EdmdDef {
    std::vector<Real> box;       ///< [m] edge per axis; empty: a cube/square from count and volume_fraction
    std::vector<bool> periodic;  ///< per axis; empty: all periodic. false: hard walls at 0 and box
    std::int64_t count = 0;      ///< particles; 0: from box and volume_fraction
    Real volumeFraction = 0;     ///< nu (edmd Eq. 4.2-4.4); 0: from count and box
    Real radius = 0;             ///< [m] a (lower bound when radius_max is given)
    Real radiusMax = 0;          ///< [m] polydisperse: radii uniform in [radius, radius_max]
    Real mass = 1;               ///< [kg] mass of a particle of radius `radius`; others scale as r^D
    std::string placement = "lattice";  ///< lattice | random
    Real temperature = 1;               ///< [J] T0 = m <v_x^2> of the Maxwell start (k_B = 1)
    Real equilibrate = 100;  ///< collisions per particle of the elastic pre-run (spec 4.2: 100), 0: none
    Real restitution = 1;    ///< eps between particles
    std::string restitutionModel = "constant";  ///< constant | mcnamara_falcon | viscoelastic
    Real restitutionSpeed = 0;                  ///< [m/s] v0 of the speed-dependent models
    Real wallRestitution = 1;                   ///< eps at the walls
    Real tangentialRestitution = -1;            ///< phi in [-1, 1]; -1: smooth spheres, no spin
    Real inertiaFactor = 0;                     ///< z = I/(m a^2); 0: 0.4 (spheres) / 0.5 (disks)
    Real tc = -1;               ///< [s] TC-model contact time; -1: 1e-5 t_E(0) when eps < 1, else off; 0: off
    std::vector<Real> gravity;  ///< [m/s^2] per axis; empty: none
    Real growthRate = 0;        ///< [m/s] u_a, radii grow as a0 + u_a t (periodic boxes)
    Real cellSize = 0;          ///< [m] lower bound of the cell edge; 0: automatic
    /// Target cells per particle C/N (edmd spec 2.4, Fig. 2.3, AT-6); 0: automatic (1.5 in 2D,
    /// 8 in 3D). Fewer where the diameter, cell_size or the box do not allow as many.
    Real cellsPerParticle = 0;
    /// auto | morton | free: every axis' cell count the power of two nearest the target (the
    /// parallel engine's grid, edmd spec 3.1: the same events on any number of ranks) or the
    /// nearest count; auto: free on one process, morton on several MPI ranks.
    std::string cellGrid = "auto";
    std::string queue = "calendar";  ///< calendar | heap | tree
    Real endTau = 0;         ///< stop at this scaled time tau = lambda t/(2 D t_E) (edmd Eq. 4.57), 0: unused
    Real endCollisions = 0;  ///< stop after this many collisions per particle, 0: unused
    std::string series = "linear";    ///< linear | log: spacing of the series.csv rows
    std::int64_t seriesPoints = 100;  ///< rows of series.csv
    Real seriesFirst = 0;             ///< [s] first row time of a log series; 0: t_E(0)/100
    bool clusters = true;             ///< cluster statistics in every series row (union-find, O(N))
    Real clusterDelta = 0.1;          ///< delta/2a of the cluster criterion (edmd Eq. 5.11)
    bool analysisFiles = true;        ///< g(r), p(v), density and cluster-size files at every snapshot
    SourceLoc loc;
};

}  // namespace granulab::model
