// SPDX-License-Identifier: MIT
// granulab command line (CLI11): run, info, convert, analyze, render, master-equation, help, --version.
// Maps errors to exit codes (app/exit_codes.hpp): 2 bad input, 3 unstable run, 130/143 a run
// stopped by SIGINT/SIGTERM (app/run_loop.cpp), 1 anything else.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <optional>

#include "app/analyze.hpp"
#include "app/convert.hpp"
#include "app/engine_table.hpp"
#include "app/info.hpp"
#include "app/render.hpp"
#include "app/run.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/gsi_script.hpp"
#ifdef GRANULAB_HAVE_MPI
#include "core/communicator.hpp"
#include "mpi/mpi_communicator.hpp"
#endif

using namespace granulab;

int main(int argc, char** argv) {
#ifdef GRANULAB_HAVE_MPI
    // Under mpirun: MPI for the whole of main (MPI_Finalize when it returns); the world
    // communicator is then the MpiCommunicator. Otherwise one process, no MPI_Init.
    std::optional<mpi::MpiEnvironment> mpiEnvironment;
    if (mpi::MpiEnvironment::launchedByMpirun()) mpiEnvironment.emplace(argc, argv);
#endif
    CLI::App cli{"granulab - granular matter simulation (DEM and event-driven gases). See `granulab help`."};
    cli.set_version_flag("--version", std::string("granulab ") + kVersion);
    cli.require_subcommand(0, 1);

    app::RunOptions runOpt;
    std::vector<std::string> sets;
    auto* run = cli.add_subcommand("run", "run a scene");
    run->add_option(
        "scene", runOpt.scene,
        "scene file (.toml, gc2d's .gsi / .gsi.gz, or a generator script with --allow-script), or "
        "a folder of the cfddem seed's input files");
    std::string gc2dInput;
    run->add_option("-i", gc2dInput,
                    "the scene, as gc2d's -i names its input (instead of the positional scene)");
    bool verbose = false;
    run->add_flag("--verbose,-v", verbose,
                  "describe the scene (as granulab info) before the run (gc2d's -v)");
    bool allowScript = false;
    std::string scriptArgs;
    const auto scriptOptions = [&](CLI::App* sub) {
        sub->add_flag(
            "--allow-script", allowScript,
            "run a generator script scene (.gsi.pl, .gsi.py, an executable) and read its output as gsi");
        sub->add_option("-P", scriptArgs, "arguments of the generator script, as one string (gc2d's -P)");
    };
    scriptOptions(run);
    run->add_option("--out", runOpt.outDir, "output folder (default out/<scene name>)");
    run->add_option("--set", sets, "override a scene key: --set dem.dt=1e-5 (repeatable)")->take_all();
    run->add_option("--resume", runOpt.resumeDir, "continue from DIR/checkpoint.bin (appends to DIR)");
    run->add_flag("--overwrite", runOpt.overwrite,
                  "remove an earlier run's outputs from the output folder first (granulab's files only)");
    run->add_flag(
        "--ignore-lock,-l", runOpt.ignoreLock,
        "output.gc2d: run although the output folder holds the lock file <basename>.glk (gc2d's -l)");
    run->add_flag("--quiet,-q", runOpt.quiet, "no progress output");
    std::string threads;
    run->add_option("--threads,-t", threads,
                    "threads of the DEM step (exactly N; 0: chosen by measurement during the run); the same "
                    "as --set run.threads=N, which it overrides");
    run->footer(
        "example: granulab run examples/disks_in_box.toml --set run.end_time=0.05 --out runs/short\n"
        "Ctrl-C (SIGINT) or SIGTERM stops after the current step or event with a checkpoint; exit\n"
        "status 130 / 143; continue with granulab run SCENE --resume DIR.");

    std::string infoScene;
    auto* info = cli.add_subcommand("info", "describe a scene: particles, advised time step, memory");
    info->add_option("scene", infoScene, "scene file, or a folder of the cfddem seed's input files")
        ->required();
    info->add_option("--set", sets, "override a scene key")->take_all();
    scriptOptions(info);
    info->footer("example: granulab info examples/disks_in_box.toml --set dem.dt=2e-5");

    app::ConvertOptions convertOpt;
    auto* convert = cli.add_subcommand(
        "convert",
        "convert a scene: the cfddem seed's input files (a folder of conditions.txt, boundary.txt, "
        "startvalue.txt) or a gc2d gsi file to native TOML, or a TOML scene to gsi");
    convert
        ->add_option("input", convertOpt.dir,
                     "a folder holding conditions.txt, boundary.txt, startvalue(s).txt; a .gsi (.gsi.gz) "
                     "scene; or a .toml scene")
        ->required();
    convert->add_option("output", convertOpt.out, "scene file to write: .toml, or .gsi from a .toml")
        ->required();
    convert->add_flag("--overwrite", convertOpt.overwrite, "replace an existing scene file");
    scriptOptions(convert);
    convert->add_flag("--quiet,-q", convertOpt.quiet, "no message");
    convert->footer(
        "example: granulab convert examples/cfddem_trio trio.toml && granulab run trio.toml\n"
        "         granulab convert examples/gc2d/piston.gsi piston.toml\n"
        "(granulab run DIR and granulab info DIR read such a folder directly)");

    app::RenderOptions renderOpt;
    bool png = false;
    std::string renderColor = "speed", renderRange, renderView;
    auto* render = cli.add_subcommand("render", "draw the snapshots of an output folder");
    render->add_option("dir", renderOpt.outDir, "output folder of a run")->required();
    render->add_flag("--png", png, "write PNG pictures (DIR/png/frame_NNNNNN.png)");
    render->add_option("--width", renderOpt.width, "picture width in pixels (default 1200)")
        ->check(CLI::Range(64, 16384));
    render->add_option("--every", renderOpt.every, "draw every Nth snapshot")
        ->check(CLI::Range(1, 1000000000));
    render->add_option("--color", renderColor,
                       "grain colour: id | speed | pressure | coordination | material (default speed; "
                       "pressure and coordination need the contact files of a DEM run)");
    render->add_flag("--forces", renderOpt.forces,
                     "draw the force network: centroid to contact point, width ~ |F| (needs contact files)");
    render->add_option("--range", renderRange, "fixed colour range lo:hi (default: all frames' min:max)");
    render->add_option("--view", renderView, "world window x0:x1,y0:y1 [m] (default: everything)");
    render->add_flag("--movie", renderOpt.movie, "assemble DIR/png/movie.mp4 with ffmpeg (if on PATH)");
    render->add_option("--fps", renderOpt.fps, "movie frame rate (default 10)")->check(CLI::Range(1, 240));
    render->add_flag("--quiet,-q", renderOpt.quiet, "no messages");
    render->footer(
        "example: granulab render out/disks_in_box --png --width 800 --color pressure --forces\n"
        "         granulab render out/gas --png --every 10 --range 0:2 --view 0:50,0:50 --movie");

    app::AnalyzeOptions analyzeOpt;
    auto* analyze = cli.add_subcommand("analyze",
                                       "measure an output folder: edmd g(r), p(v), density, clusters, tau_p; "
                                       "dem pressure, forces, coordination, repose, packing, stress, ...");
    analyze->add_option("dir", analyzeOpt.dir, "output folder of a run")->required();
    analyze->add_option("--rmax", analyzeOpt.rMaxRadii, "g(r) range in particle radii")
        ->check(CLI::Range(2.5, 1e6));
    analyze->add_option("--bins", analyzeOpt.bins, "g(r) bins")->check(CLI::Range(4, 1000000));
    analyze->add_option("--delta", analyzeOpt.delta, "cluster criterion delta/2a (edmd Eq. 5.11)")
        ->check(CLI::Range(1e-6, 1.0));
    analyze->add_option("--per-bin", analyzeOpt.particlesPerBin, "particles per density bin")
        ->check(CLI::Range(1.0, 1e9));
    analyze->add_flag("--quiet,-q", analyzeOpt.quiet, "no summary on the terminal");
    analyze->add_option(
        "what", analyzeOpt.what,
        "dem: analyses (pressure forces coordination repose packing stress coarse janssen strain "
        "persistence roughness; default: the first six)");
    analyze->add_option("--at", analyzeOpt.at, "dem: the snapshot nearest this time [s] (default: the last)")
        ->check(CLI::NonNegativeNumber);
    analyze->add_option("--every", analyzeOpt.every, "dem: every Nth snapshot")
        ->check(CLI::Range(1, 1000000));
    analyze->add_option("--window", analyzeOpt.window,
                        "dem: test-area size W[:H] [m] (default: ~150 grains)");
    analyze->add_option("--step", analyzeOpt.step,
                        "dem: test-area step SX[:SY] [m] (default: half the window)");
    analyze->add_option("--wall", analyzeOpt.walls,
                        "dem: walls for pressure, by name or index (default: all)");
    analyze->add_option("--silo", analyzeOpt.silo,
                        "dem janssen: straight:R | stepped:R1,R2,H0 | slanted:A,B | parabolic:A,B [m]");
    analyze->add_option("--surface", analyzeOpt.surface,
                        "dem janssen: free-surface height [m] (default: the highest grain top)");
    analyze->add_option("--depth", analyzeOpt.depth,
                        "dem janssen: fit only depths Z0:Z1 [m] below the surface (default: all)");
    analyze
        ->add_option("--reference", analyzeOpt.reference,
                     "dem strain/persistence: time of the other snapshot [s]")
        ->check(CLI::NonNegativeNumber);
    analyze->add_option("--range", analyzeOpt.ranges,
                        "dem repose/roughness: surface range X0:X1 [m] (repeatable)");
    analyze->add_option("--region", analyzeOpt.region,
                        "dem coordination/persistence: grains in X0:X1,Y0:Y1 [m]");
    analyze->add_option("--kernel", analyzeOpt.kernel, "dem coarse: gauss | lucy")
        ->check(CLI::IsMember({"gauss", "lucy"}));
    analyze
        ->add_option("--kernel-width", analyzeOpt.kernelWidth,
                     "dem coarse: Gaussian w or Lucy c [m] (default d/2 or 2d)")
        ->check(CLI::PositiveNumber);
    analyze
        ->add_option("--half-width", analyzeOpt.halfWidth,
                     "dem pressure: profile window half width b [m] (default 5 d)")
        ->check(CLI::PositiveNumber);
    analyze
        ->add_option("--bin", analyzeOpt.binWidth, "dem repose/roughness: surface bin width [m] (default d)")
        ->check(CLI::PositiveNumber);
    analyze->footer(
        "example: granulab analyze out/sand_heap pressure stress repose --window 0.02\n"
        "         granulab analyze out/cooling_gas_2d --rmax 10 --bins 200 (edmd)");

    app::MasterEquationOptions meOpt;
    auto* master = cli.add_subcommand("master-equation",
                                      "integrate the cluster-population master equation (edmd Eq. 5.31)");
    master->add_option("--smax", meOpt.params.maxSize, "largest cluster size tracked")
        ->check(CLI::Range(2, 100000));
    master->add_option("--dim", meOpt.params.dim, "dimension D in the surface factor")
        ->check(CLI::IsMember({2, 3}));
    master->add_option("--alpha0", meOpt.params.alpha0, "merging prefactor")->check(CLI::PositiveNumber);
    master->add_option("--beta0", meOpt.params.beta0, "fragmentation prefactor")
        ->check(CLI::NonNegativeNumber);
    master->add_option("--lambda", meOpt.params.lambda, "dissipation 1 - eps^2")->check(CLI::PositiveNumber);
    master->add_option("--xi", meOpt.params.xi, "fragment exponent xi")->check(CLI::PositiveNumber);
    master->add_flag("--symmetric", meOpt.params.symmetricGain,
                     "symmetric Smoluchowski form (1/2 in the gain term)");
    master->add_option("--t-end", meOpt.tEnd, "end time [1/alpha0]")->check(CLI::PositiveNumber);
    master->add_option("--points", meOpt.points, "output times (logarithmic)")->check(CLI::Range(2, 100000));
    master->add_option("--out", meOpt.out, "output prefix");
    master->footer("example: granulab master-equation --lambda 4 --xi 2 --smax 50 --t-end 20 --out me");

    std::string helpTopic;
    auto* help = cli.add_subcommand("help", "usage, or `help laws` for the contact-law table");
    help->add_option("topic", helpTopic, "laws | restitution");
    help->footer("example: granulab help laws");

    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = cli.exit(e);
        return code == 0 ? 0 : app::kExitBadInput;
    }
    try {
        std::vector<io::Override> overrides;
        for (const auto& s : sets) overrides.push_back(io::parseOverride(s));
        app::setScriptPolicy({allowScript, io::splitScriptArgs(scriptArgs)});
        if (*run) {
            if (runOpt.scene.empty()) runOpt.scene = gc2dInput;
            if (runOpt.scene.empty() || (!gc2dInput.empty() && gc2dInput != runOpt.scene)) {
                fmt::print(
                    stderr,
                    "granulab run: name one scene, as `granulab run SCENE` or `granulab run -i SCENE`\n");
                return app::kExitBadInput;
            }
            if (!threads.empty()) overrides.push_back(io::parseOverride("run.threads=" + threads));
            runOpt.overrides = overrides;
            if (verbose && !runOpt.quiet) {
                const int described = app::infoCommand(runOpt.scene, overrides);
                if (described != app::kExitOk) return described;
            }
            return app::runCommand(runOpt);
        }
        if (*info) return app::infoCommand(infoScene, overrides);
        if (*convert) return app::convertCommand(convertOpt);
        if (*analyze) return app::analyzeCommand(analyzeOpt);
        if (*master) {
            try {
                return app::masterEquationCommand(meOpt);
            } catch (const std::invalid_argument& e) {
                fmt::print(stderr, "granulab master-equation: {}\n", e.what());
                return app::kExitBadInput;
            }
        }
        if (*render) {
            if (!png) {
                fmt::print(stderr, "granulab render: choose an output format (--png)\n");
                return app::kExitBadInput;
            }
            const auto color = app::parseColorMode(renderColor);
            if (!color) {
                fmt::print(stderr,
                           "granulab render: --color '{}': choose id, speed, pressure, coordination or "
                           "material\n",
                           renderColor);
                return app::kExitBadInput;
            }
            renderOpt.color = *color;
            if (!renderRange.empty()) {
                renderOpt.range = app::parseRange(renderRange);
                if (!renderOpt.range) {
                    fmt::print(stderr,
                               "granulab render: --range '{}': expected lo:hi, two numbers with lo < hi "
                               "(e.g. --range 0:2.5)\n",
                               renderRange);
                    return app::kExitBadInput;
                }
            }
            if (!renderView.empty()) {
                renderOpt.view = app::parseView(renderView);
                if (!renderOpt.view) {
                    fmt::print(stderr,
                               "granulab render: --view '{}': expected x0:x1,y0:y1 in metres with x0 < x1 "
                               "and y0 < y1 (e.g. --view 0:0.5,0:0.3)\n",
                               renderView);
                    return app::kExitBadInput;
                }
            }
            return app::renderCommand(renderOpt);
        }
        if (*help && !helpTopic.empty() && helpTopic != "laws" && helpTopic != "restitution") {
            fmt::print(stderr, "granulab help: unknown topic '{}'; topics: laws, restitution\n", helpTopic);
            return app::kExitBadInput;
        }
        fmt::print("{}", app::helpText(*help ? helpTopic : ""));
        return 0;
    } catch (const SceneError& e) {
        // Under mpirun every rank meets the same scene errors (granulab run makes the root's
        // verdicts collective): printed once.
        if (worldCommunicator().root()) std::fputs(e.what(), stderr);
        return app::kExitBadInput;
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        // One rank's failure must not leave the others waiting in a collective call forever.
        if (worldCommunicator().size() > 1) worldCommunicator().abort(app::kExitFailure);
        return app::kExitFailure;
    }
}
