// SPDX-License-Identifier: MIT
// The fuzz target (tests/fuzz/fuzz_target.hpp): engine table -> info -> build -> start ->
// advance in slices over the stops the run loop would make.
#include "fuzz_target.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <typeinfo>

#include "app/engine_table.hpp"
#include "app/trigger.hpp"
#include "core/error.hpp"
#include "fuzz_guard.hpp"

namespace granulab::fuzz {

namespace {

/// CPU time of the process [s] (the slice budget does not depend on the machine's load).
double cpuSeconds() {
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

std::string firstLine(const std::string& s) {
    return s.substr(0, s.find('\n'));
}

/// A count from a schedule point without undefined conversions (NaN and negatives: 0).
std::uint64_t toCount(double x) {
    if (!(x > 0)) return 0;
    if (x >= 1.8e19) return std::numeric_limits<std::uint64_t>::max();
    return static_cast<std::uint64_t>(x);
}

RunResult unstable(app::Simulation& sim, std::uint32_t status) {
    return {Outcome::Unstable, firstLine(sim.diagnose(status))};
}

RunResult runChecked(const std::string& text, const std::string& path, const RunLimits& limits) {
    using app::Schedule;
    setStage("read");
    const model::SceneDef scene = app::readSceneText(text, path);
    const app::EngineEntry& engine = app::engineOf(scene);
    setStage("info");
    engine.info(path, scene);
    setStage("build");
    const std::unique_ptr<app::Simulation> sim = engine.build(scene, {path, true});
    sim->warnings();
    const app::RunPlan plan = sim->plan();
    if (sim->particles() > limits.maxParticles) return {Outcome::Ok, "built, not started (large)"};
    setStage("start");
    sim->start();
    app::Trigger end(plan.end), series(plan.series), snapshots(plan.snapshots), checkpoints(plan.checkpoints),
        progress(plan.progress), benchmark(plan.benchmark);
    app::Trigger* const triggers[] = {&end, &series, &snapshots, &checkpoints, &progress, &benchmark};
    for (app::Trigger* t : triggers) t->seek(sim->time(), sim->count());
    sim->seriesColumns();
    sim->seriesRow();
    if (const std::uint32_t s = sim->health(); s != app::kSimOk) return unstable(*sim, s);
    sim->beginLoop();

    setStage("advance");
    const bool byCount = plan.end.unit == Schedule::Unit::Count;
    const double endPoint = end.next();
    const double t0 = sim->time();
    const std::uint64_t c0 = sim->count();
    const double sliceTime =
        std::isfinite(endPoint) && endPoint > t0 ? (endPoint - t0) * limits.sliceFraction : 1.0;
    const std::uint64_t sliceCount =
        std::isfinite(endPoint)
            ? std::max<std::uint64_t>(1, toCount((endPoint - static_cast<double>(c0)) * limits.sliceFraction))
            : 1000;
    const double cpuStart = cpuSeconds();
    for (int k = 0; k < limits.slices && cpuSeconds() - cpuStart < limits.runSeconds; ++k) {
        app::Stop stop;
        for (const app::Trigger* t : triggers) t->limit(stop);
        if (byCount)
            stop.count = std::min(stop.count, sim->count() + std::min(sliceCount, ~sim->count()));
        else
            stop.time = std::min(stop.time, sim->time() + sliceTime);
        // Every slice is bounded in work too: a valid run of 4e9 s is long, not stuck (a stuck
        // one is the engine watchdog's, which ends a slice with kSimStalled).
        stop.count = std::min(stop.count, sim->count() + std::min(limits.sliceCount, ~sim->count()));
        if (const std::uint32_t s = sim->advance(stop); s != app::kSimOk) return unstable(*sim, s);
        const double t = sim->time();
        const std::uint64_t c = sim->count();
        if (series.reached(t, c) || end.reached(t, c)) {
            sim->seriesRow();
            if (const std::uint32_t s = sim->health(); s != app::kSimOk) return unstable(*sim, s);
        }
        if (end.reached(t, c)) break;
        for (app::Trigger* tr : triggers) tr->pass(t, c);
    }
    return {Outcome::Ok, ""};
}

}  // namespace

RunResult runScene(const std::string& text, const std::string& path, const RunLimits& limits) {
    try {
        return runChecked(text, path, limits);
    } catch (const SceneError& e) {
        return {Outcome::BadInput, firstLine(e.what())};
    } catch (const std::exception& e) {
        return {Outcome::Finding, fmt::format("exception {}: {}", typeid(e).name(), firstLine(e.what()))};
    } catch (...) {
        return {Outcome::Finding, "exception of unknown type"};
    }
}

const char* outcomeName(Outcome outcome) {
    switch (outcome) {
        case Outcome::Ok:
            return "ok";
        case Outcome::BadInput:
            return "bad input";
        case Outcome::Unstable:
            return "unstable";
        default:
            return "FINDING";
    }
}

}  // namespace granulab::fuzz
