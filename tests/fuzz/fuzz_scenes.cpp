// SPDX-License-Identifier: MIT
// granulab_fuzz: a mutation fuzzer of the scene readers, validation and engine set-up (issue 11).
// Mutates seed scenes (tests/fuzz/mutator.hpp) for --seconds and runs each mutant in process
// (tests/fuzz/fuzz_target.hpp); exceptions other than SceneError, crashes and hangs are saved
// to --findings. --replay runs given files once each (the regression corpus, tests/fuzz/corpus/).
// Exit status: 0 no finding, 1 findings, 2 usage, 124 a hang; a crash ends it by its signal.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/rng.hpp"
#include "core/timer.hpp"
#include "fuzz_guard.hpp"
#include "fuzz_target.hpp"
#include "mutator.hpp"

using namespace granulab;
namespace fs = std::filesystem;

namespace {

struct Seed {
    std::string path;
    std::string text;
};

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Default seeds: every examples/**/*.toml and *.gsi and tests/**/*.toml and *.gsi except the regression
/// corpus (replayed by its own tests) and the benchmark-size scenes (examples/bench/ and the 477,000 spheres
/// of examples/edmd/clustering_3d.toml: seconds to minutes each before the first step, with the same keys as
/// the other examples).
std::vector<std::string> defaultSeeds() {
    std::vector<std::string> paths;
    for (const char* dir : {"examples", "tests"}) {
        const fs::path root = fs::path(GRANULAB_SOURCE_DIR) / dir;
        for (const auto& entry : fs::recursive_directory_iterator(root)) {
            const std::string p = entry.path().string();
            if (entry.path().extension() != ".toml" && entry.path().extension() != ".gsi") continue;
            if (p.find("/fuzz/corpus/") != std::string::npos ||
                p.find("/examples/bench/") != std::string::npos ||
                p.find("/clustering_3d.toml") != std::string::npos)
                continue;
            paths.push_back(p);
        }
    }
    std::sort(paths.begin(), paths.end());
    return paths;
}

int replay(const std::vector<std::string>& files, const std::string& findings,
           const fuzz::RunLimits& limits) {
    int findingCount = 0;
    for (const auto& file : files) {
        const std::string text = readFile(file);
        fuzz::beginInput(text, findings, file);
        const double t0 = wallSeconds();
        const fuzz::RunResult r = fuzz::runScene(text, file, limits);
        fuzz::endInput();
        fuzz::report(fmt::format("replay {}: {} ({:.2f} s){}{}\n", file, fuzz::outcomeName(r.outcome),
                                 wallSeconds() - t0, r.message.empty() ? "" : ": ", r.message));
        findingCount += r.outcome == fuzz::Outcome::Finding;
    }
    return findingCount > 0 ? 1 : 0;
}

int fuzzLoop(const std::vector<Seed>& seeds, double seconds, std::uint64_t seed, std::uint64_t maxMutants,
             const std::string& findings, const fuzz::RunLimits& limits) {
    std::vector<std::string> texts;
    for (const auto& s : seeds) texts.push_back(s.text);
    const fuzz::Mutator mutator(texts);
    fuzz::Counters& c = fuzz::counters();
    std::vector<std::string> saved;
    const double start = wallSeconds();
    double lastNote = start;
    while (wallSeconds() - start < seconds && (maxMutants == 0 || c.mutants < maxMutants)) {
        CounterRng rng(seed, c.mutants);  // mutant k of seed S is reproducible on its own
        const Seed& from = seeds[static_cast<std::size_t>(rng.nextU64() % seeds.size())];
        const std::string text = mutator.mutate(from.text, rng);
        const std::string origin = fmt::format("mutant {} of seed {} from {}", c.mutants, seed, from.path);
        fuzz::beginInput(text, findings, origin);
        // The seed's language: a gsi mutant is read as gsi (app::readSceneText goes by the name).
        const fuzz::RunResult r =
            fuzz::runScene(text, "mutant" + fs::path(from.path).extension().string(), limits);
        fuzz::endInput();
        ++c.mutants;
        switch (r.outcome) {
            case fuzz::Outcome::Ok:
                ++c.ok;
                break;
            case fuzz::Outcome::BadInput:
                ++c.badInput;
                break;
            case fuzz::Outcome::Unstable:
                ++c.unstable;
                break;
            case fuzz::Outcome::Finding: {
                ++c.exceptions;
                const std::string path =
                    fuzz::saveFinding("exception", text, findings, origin + "\n" + r.message);
                saved.push_back(path);
                fuzz::say(fmt::format("fuzz: FINDING {} on {}; saved as {}\n", r.message, origin, path));
                break;
            }
        }
        if (wallSeconds() - lastNote >= 10) {
            lastNote = wallSeconds();
            fuzz::say(fmt::format("fuzz: {:.0f} s, {} mutants, {} findings\n", lastNote - start, c.mutants,
                                  c.exceptions));
        }
    }
    fuzz::report(fmt::format(
        "fuzz: seed {}, {:.0f} s, {} seed scenes: {} mutants: ok {}, bad input {}, unstable {}, findings "
        "{}\n",
        seed, wallSeconds() - start, seeds.size(), c.mutants, c.ok, c.badInput, c.unstable, c.exceptions));
    for (const auto& p : saved) fuzz::report(fmt::format("fuzz: finding saved: {}\n", p));
    fuzz::report(fuzz::summaryLine(0, 0));
    return c.exceptions > 0 ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App cli{"granulab_fuzz - mutation fuzzer of granulab scenes (tests/fuzz/, issue 11)"};
    double seconds = 60;
    std::uint64_t seed = 1, maxMutants = 0;
    std::string findings = "fuzz-findings";
    unsigned hangSeconds = 20;
    bool verbose = false;
    std::vector<std::string> seedFiles, replayFiles;
    fuzz::RunLimits limits;
    cli.add_option("--seconds", seconds, "time budget of the mutation loop [s]");
    cli.add_option("--seed", seed, "random seed: the same seed gives the same mutants");
    cli.add_option("--runs", maxMutants, "stop after this many mutants (0: only --seconds)");
    cli.add_option("--findings", findings, "folder for inputs that crash, hang or throw");
    cli.add_option("--hang-seconds", hangSeconds, "CPU-time limit per input [s] (wall: 4 times as much)")
        ->check(CLI::Range(1u, 3600u));
    cli.add_option("--run-seconds", limits.runSeconds, "CPU time of the bounded advance per input [s]");
    cli.add_option("--max-particles", limits.maxParticles, "larger scenes are built but not run");
    cli.add_option("--seeds", seedFiles, "seed scenes (default: examples/ and tests/ *.toml and *.gsi)");
    cli.add_option("--replay", replayFiles, "run these files once each and report their outcomes");
    cli.add_flag("--verbose", verbose, "leave the engines' stdout and stderr on the terminal");
    CLI11_PARSE(cli, argc, argv);

    try {
        std::vector<Seed> seeds;
        if (replayFiles.empty()) {
            if (seedFiles.empty()) seedFiles = defaultSeeds();
            for (const auto& p : seedFiles) seeds.push_back({p, readFile(p)});
            if (seeds.empty()) throw std::runtime_error("no seed scenes");
        }
        if (!verbose) fuzz::silenceEngines();
        fuzz::installHandlers(hangSeconds);
        if (!replayFiles.empty())
            return replay(replayFiles, "", limits);  // a replayed input is a file already
        return fuzzLoop(seeds, seconds, seed, maxMutants, findings, limits);
    } catch (const std::exception& e) {
        fuzz::say(fmt::format("granulab_fuzz: {}\n", e.what()));
        return 2;
    }
}
