// SPDX-License-Identifier: MIT
// `granulab info` (dispatched through the engine table) and the help texts.
#include "app/info.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "app/engine_table.hpp"
#include "app/simulation_options.hpp"
#include "dem/contact/hertz_restitution.hpp"
#include "dem/contact/registry.hpp"
#include "io/scene_override.hpp"

namespace granulab::app {

int infoCommand(const std::string& scenePath, const std::vector<io::Override>& overrides) {
    return io::withOverrideLocations(overrides, [&] {
        const model::SceneDef scene = app::readScene(scenePath, overrides);
        const EngineEntry& engine = engineOf(scene);
        // Everything `run` does before its first step (placement, cells, the engine's own
        // checks), so that info fails exactly where run would; then the report.
        engine.build(scene, {scenePath, true});
        return engine.info(scenePath, scene);
    });
}

std::string helpText(const std::string& topic) {
    if (topic == "restitution") {  // the e <-> D helper of spec/cfddem.md section 3.5
        std::string s =
            "Restitution coefficient e versus damping ratio D (damping = \"lehr\", D_n = D):\n"
            "  linear spring: e = exp(-pi D / sqrt(1 - D^2)) (Eq. 3.78, exact without clipping)\n"
            "  Hertz spring:  e(D) of the Hertz-Lehr collision, computed (depends on D only)\n\n"
            "     D    e linear   e Hertz   e Hertz clipped\n";
        for (const Real d : {0.0, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}) {
            const Real lin = d < 1 ? std::exp(-kPi * d / std::sqrt(1 - d * d)) : 0.0;
            s += fmt::format("  {:4.2f}   {:8.4f}  {:8.4f}  {:8.4f}\n", d, lin, dem::hertzRestitution(d),
                             dem::hertzRestitution(d, true));
        }
        s += "\ndamping = \"restitution\" with e = ... uses the inverse of the matching column.\n";
        return s;
    }
    if (topic == "laws") {
        std::string s = "Contact laws ([[contact]] keys normal, damping, tangential and their parameters):\n";
        for (const auto& e : dem::lawRegistry()) {
            s += fmt::format("\n  {} = \"{}\": {}\n", dem::axisKey(e.axis), e.keyword, e.doc);
            for (const auto& p : e.params)
                s += fmt::format("      {:<10} [{}] {}; allowed {}; default {}\n", p.key, p.unit, p.doc,
                                 p.rangeText(), p.defaultText);
        }
        s += "\n  any law:\n";
        for (const auto& p : dem::commonLawParams())
            s += fmt::format("      {:<16} {}; default {}\n", p.key, p.doc, p.defaultText);
        return s;
    }
    return R"(granulab - granular matter simulation

usage (each command also has --help, with an example):
  granulab run SCENE [--out DIR] [--set key=value]... [--resume DIR] [--overwrite] [--quiet]
      simulate; writes summary.json, series.csv, final.csv, VTK snapshots (snapshots.pvd)
      and checkpoint.bin into DIR (default out/<scene name>). A folder that holds another
      run's output is refused unless --overwrite (removes granulab's own files only);
      --resume DIR continues DIR/checkpoint.bin and appends. Ctrl-C (SIGINT) or SIGTERM stops
      after the current step or event, writes a checkpoint and prints how to resume.
  granulab info SCENE [--set key=value]...
      particles, materials, contact time, advised time step, memory estimate
      (SCENE may also be a folder of the cfddem seed's conditions.txt, boundary.txt and
      startvalue.txt, for run and info alike)
  granulab convert DIR SCENE.toml [--overwrite]
      write the native TOML scene of such a folder
  granulab render DIR --png [--width PIXELS]
      one PNG per snapshot of a finished or running simulation, into DIR/png/
  granulab analyze DIR [--rmax RADII] [--bins N] [--delta D] [--per-bin N] [--quiet]
      measure the final state of an edmd run: g(r), p(v), density, clusters (DIR/analysis/)
  granulab master-equation [--lambda L] [--xi X] [--smax N] [--t-end T] [--points N] [--out PREFIX]
      integrate the cluster-population master equation (PREFIX_moments.csv, ..._distributions.csv)
  granulab help [laws | restitution]
      this text, the table of contact laws and their parameters, or the e <-> D table
  granulab --version

exit status: 0 success, 2 bad input (scene errors are listed with file:line; a damaged
             checkpoint; an output folder of another run), 3 run stopped because it became
             numerically unstable or stalled (watchdog), 130 / 143 stopped by SIGINT /
             SIGTERM (resumable), 1 other failure.
docs: docs/getting-started.md, docs/scene-format.md, docs/physics/contact-laws.md
)";
}

}  // namespace granulab::app
