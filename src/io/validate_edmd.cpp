// SPDX-License-Identifier: MIT
// Def-level checks of an event-driven gas scene ([edmd], edmd spec 2.4-2.8, 4.1-4.2): ranges of
// every key, the box/count/volume-fraction triangle, output intervals. The resolution of the
// box, count and run length and the kinetic scales are edmd::resolveScene (edmd/scene_setup).
#include "io/validate_edmd.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "io/range_checks.hpp"

namespace granulab::io {

void checkEdmdDef(const model::SceneDef& sc, Diagnostics& d) {
    const model::EdmdDef& e = sc.edmd;
    const SourceLoc& loc = e.loc.file.empty() ? sc.run.loc : e.loc;
    auto positive = [&](const char* key, Real v, const char* unit) { checkPositive(d, loc, key, v, unit); };
    auto inRange = [&](const char* key, Real v, Real lo, Real hi, const char* what) {
        if (!(v >= lo && v <= hi))
            d.error(loc, key, fmt::format("must be in [{}, {}] ({}), got {}", lo, hi, what, v));
    };
    if (sc.run.dimension != 2 && sc.run.dimension != 3)
        d.error(sc.run.loc, "run.dimension",
                fmt::format("the edmd engine simulates disks (2) or spheres (3); got {}", sc.run.dimension));
    const int D = sc.run.dimension == 2 ? 2 : 3;
    positive("edmd.radius", e.radius, "m");
    if (e.radiusMax != 0 && !(e.radiusMax >= e.radius))
        d.error(loc, "edmd.radius_max",
                fmt::format("must be >= edmd.radius = {} m (radii uniform in [radius, radius_max]), got {}",
                            e.radius, e.radiusMax));
    positive("edmd.mass", e.mass, "kg");
    positive("edmd.temperature", e.temperature, "J");
    if (!(e.equilibrate >= 0))
        d.error(loc, "edmd.equilibrate",
                fmt::format("must be >= 0 collisions per particle, got {}", e.equilibrate));
    inRange("edmd.restitution", e.restitution, 0, 1, "normal restitution eps");
    inRange("edmd.wall_restitution", e.wallRestitution, 0, 1, "normal restitution at the walls");
    inRange("edmd.tangential_restitution", e.tangentialRestitution, -1, 1,
            "phi: -1 smooth, +1 perfectly rough");
    if (e.inertiaFactor != 0)
        inRange("edmd.inertia_factor", e.inertiaFactor, 1e-6, 1,
                "z = I/(m a^2): 0.4 solid sphere, 0.5 solid disk");
    if (e.restitutionModel != "constant") positive("edmd.restitution_speed", e.restitutionSpeed, "m/s");
    if (!(e.tc == -1 || e.tc >= 0))
        d.error(loc, "edmd.tc", fmt::format("must be >= 0 [s] (0: off) or -1 (automatic), got {}", e.tc));
    if (!(e.cellSize >= 0))
        d.error(loc, "edmd.cell_size", fmt::format("must be >= 0 [m] (0: automatic), got {}", e.cellSize));
    // Cells per particle C/N (edmd spec 2.4, AT-6): 0 or (0, 1e4].
    if (!(e.cellsPerParticle >= 0 && e.cellsPerParticle <= 1e4))
        d.error(loc, "edmd.cells_per_particle",
                fmt::format("must be in (0, 10000] (target cells per particle C/N; 1.5 in 2D, 8 in 3D at "
                            "low density) or 0 (automatic), got {}",
                            e.cellsPerParticle));
    if (e.seriesPoints < 2 || e.seriesPoints > 1000000)
        d.error(loc, "edmd.series_points", fmt::format("must be in [2, 1000000], got {}", e.seriesPoints));
    if (!(e.seriesFirst >= 0))
        d.error(loc, "edmd.series_first", fmt::format("must be >= 0 [s], got {}", e.seriesFirst));
    if (!(e.clusterDelta > 0 && e.clusterDelta <= 1))
        d.error(loc, "edmd.cluster_delta",
                fmt::format("must be in (0, 1] (delta/2a; thesis: 0.1), got {}", e.clusterDelta));
    if (!e.box.empty() && e.box.size() != static_cast<std::size_t>(D))
        d.error(loc, "edmd.box",
                fmt::format("has {} edges; run.dimension = {} needs {}", e.box.size(), D, D));
    for (std::size_t k = 0; k < e.box.size(); ++k) positive("edmd.box", e.box[k], "m");
    if (!e.periodic.empty() && e.periodic.size() != static_cast<std::size_t>(D))
        d.error(loc, "edmd.periodic",
                fmt::format("has {} entries; run.dimension = {} needs {}", e.periodic.size(), D, D));
    if (!e.gravity.empty() && e.gravity.size() != static_cast<std::size_t>(D))
        d.error(loc, "edmd.gravity",
                fmt::format("has {} components; run.dimension = {} needs {}", e.gravity.size(), D, D));
    const std::pair<const char*, Real> intervals[] = {
        {"output.snapshot_interval", sc.output.snapshotInterval},
        {"output.series_interval", sc.output.seriesInterval},
        {"output.checkpoint_interval", sc.output.checkpointInterval}};
    for (const auto& [key, value] : intervals)
        if (!(value >= 0)) d.error(sc.output.loc, key, fmt::format("must be >= 0 [s], got {}", value));
    if (!sc.output.analyses.empty())
        d.error(sc.output.loc, "output.analyses",
                "is for dem runs; an edmd run writes its gas analyses at every snapshot with "
                "edmd.analysis_files = true");
    if (sc.output.gc2d.enabled)
        d.error(sc.output.loc, "output.gc2d",
                "is for dem runs (gc2d's ggf, gff, gpf, gtf and gpl files of polygon grains); an edmd run "
                "writes its particles in the snapshots and final.csv");
    if (sc.output.particleSeries)
        d.error(
            sc.output.loc, "output.particle_series",
            "is for dem runs (the cfddem seed's per-particle CSV series); an edmd run writes its particles "
            "in the snapshots and final.csv");
    // The box / count / volume-fraction triangle: exactly two of the three.
    const int given = (!e.box.empty() ? 1 : 0) + (e.count > 0 ? 1 : 0) + (e.volumeFraction > 0 ? 1 : 0);
    if (e.count < 0) d.error(loc, "edmd.count", fmt::format("must be > 0, got {}", e.count));
    if (e.volumeFraction < 0 || e.volumeFraction >= (D == 2 ? 0.9069 : 0.7405))
        d.error(loc, "edmd.volume_fraction",
                fmt::format("must be in (0, {}) (close packing), got {}", D == 2 ? 0.9069 : 0.7405,
                            e.volumeFraction));
    if (given != 2)
        d.error(loc, "edmd",
                fmt::format("give exactly two of box, count and volume_fraction (the third follows); got {}",
                            given));
}

}  // namespace granulab::io
