// SPDX-License-Identifier: MIT
// Plain *Def structs filled by the scene parsers (io/) and read by the engines (DESIGN.md
// "Configuration objects"). Engines never see scene text. SI units throughout; 2D masses are
// per unit depth when the mass model is areal ("disk").
// The engines' own sections are in model/dem_def.hpp and model/edmd_def.hpp.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "model/dem_def.hpp"
#include "model/edmd_def.hpp"
#include "model/fluid_def.hpp"
#include "model/machine_def.hpp"

namespace granulab::model {

struct RunDef {
    std::string engine = "dem";  ///< "dem" | "edmd" (event-driven hard spheres)
    int dimension = 2;           ///< spatial dimension; dem supports 2, edmd 2 and 3
    std::uint64_t seed = 1;      ///< seed of every random draw in scene generation
    Real endTime = 0;  ///< [s] simulated time at which the run stops (edmd: or edmd.end_tau / end_collisions)
    Real benchmarkFrom = -1;  ///< [s] report throughput separately from this time on (<0: off)
    int threads = 0;          ///< dem: threads of the step (0: every core the process may use)
    bool loadBalance = true;  ///< dem under mpirun: move the slab cuts by contacts (docs/physics/dem-mpi.md)
    std::string title;
    SourceLoc loc;
};

struct OutputDef {
    Real snapshotInterval = 0;    ///< [s] VTK snapshot period (0: first and last only)
    Real seriesInterval = 0;      ///< [s] series.csv period (0: 100 rows over the run)
    Real checkpointInterval = 0;  ///< [s] checkpoint period (0: only at the end)
    bool vtk = true;
    /// DEM: the contact file and force-network line set of every snapshot (io/contact_file.hpp)
    bool contacts = true;
    /// DEM: analyses run at every snapshot (the names of `granulab analyze`, analysis/dem_analyses.hpp)
    std::vector<std::string> analyses;
    /// DEM: the cfddem seed's nine per-particle series CSV/r_x.csv ... alpha.csv (spec 6.6) at every
    /// series.csv row
    bool particleSeries = false;
    SourceLoc loc;
};

/// A whole scene: the run and output settings and every engine's sections; the reader fills only
/// the running engine's (io/scene_reader.hpp), the others keep their defaults.
struct SceneDef {
    std::string path;  ///< scene file
    RunDef run;
    DemDef dem;
    std::vector<MaterialDef> materials;
    std::vector<ContactDef> contacts;
    std::vector<ShapeDef> shapes;
    std::vector<ParticleDef> particles;
    std::vector<BlockDef> blocks;
    std::vector<HeapDef> heaps;  ///< generated after the blocks (ids follow theirs)
    std::vector<WallDef> walls;
    std::vector<SpringDef> springs;
    MachineDefs machines;      ///< drums, sources, inlets, outlets, boundaries, gravity schedule, changes
    FluidDef fluid;            ///< [fluid]: imported flow field, drag, buoyancy (cfddem spec 5)
    AttractionDef attraction;  ///< [attraction]: mutual Newtonian attraction (cfddem spec 5.6)
    OutputDef output;
    EdmdDef edmd;
};

}  // namespace granulab::model
