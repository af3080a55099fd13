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
    Real startTime =
        0;  ///< [s] dem: the clock at the start (a gc2d gso restart: TIME t0 t1), a whole number of dt
    Real benchmarkFrom = -1;  ///< [s] report throughput separately from this time on (<0: off)
    int threads =
        0;  ///< dem: threads of the step (N > 0: exactly N; 0: the automatic count, core/thread_governor.hpp)
    bool loadBalance = true;  ///< dem under mpirun: move the slab cuts by contacts (docs/physics/dem-mpi.md)
    std::string title;
    SourceLoc loc;
};

/// gc2d's legacy files (gc2d spec 9.1, 9.5; docs/coming-from-gc2d.md "Legacy outputs"), written
/// into the output folder as <basename>[.NNNN].<ext> when `enabled` (output.gc2d = true; a gsi
/// scene sets it): ggf, gff + gpf at every snapshot, gtf, gpl, the lock .glk and a .ps picture.
struct Gc2dOutputDef {
    bool enabled = false;
    std::string basename = "default";  ///< file stem (gc2d BASENAME; a folder part is dropped)
    std::int64_t nextDataNumber = 1;   ///< NNNN of the first gff/gpf dump (NEXT_DATA_FILENUMBER)
    std::int64_t nextSetupNumber = 1;  ///< NNNN of the first numbered gso/gco (NEXT_SETUP_FILENUMBER)
    Real setupInterval = 0;            ///< [s] numbered gso/gco setup dumps (STEPS_SETUP dt; 0: never)
    Real lineInterval = 0;             ///< [s] gpl lines (STEPS_DUMPLINE dt; 0: never)
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
    Gc2dOutputDef gc2d;  ///< DEM: gc2d's legacy files
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
    /// gc2d restart: the contacts of the gci beside a gsi (io/gci_file.hpp); the dem engine gives
    /// them their tangential spring and last overlap area at the start.
    std::vector<RememberedContactDef> rememberedContacts;
    MachineDefs machines;      ///< drums, sources, inlets, outlets, boundaries, gravity schedule, changes
    FluidDef fluid;            ///< [fluid]: imported flow field, drag, buoyancy (cfddem spec 5)
    AttractionDef attraction;  ///< [attraction]: mutual Newtonian attraction (cfddem spec 5.6)
    OutputDef output;
    EdmdDef edmd;
};

}  // namespace granulab::model
