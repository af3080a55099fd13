// SPDX-License-Identifier: MIT
// Flow-field interpolation benchmarks (bench/README.md "Flow-field interpolation"): the cfddem
// target "interpolation costs at most 20 % of a DEM step for 1e5 particles in a 1e6-node
// unstructured field, and memory for that field at most 100 bytes per node". Synthetic fields are
// built in memory (no files) over the square box of the DEM scene (W = 316.5 m):
//   cell      1000 x 1000 nodes, jittered by up to 0.2 spacing (so not a tensor grid), with the
//             999 x 999 quads of the jittered grid as cells (barycentric "cell" interpolation);
//   shepard   the same nodes without cells (Shepard, 4 nearest nodes);
//   bilinear  an exact 1000 x 1000 tensor grid.
// The velocity is a smooth analytic field. Benchmarks:
//   BM_Construct/<variant>        FieldInterpolator construction (the FlowField copy is not timed);
//                                 bytes/node = memoryBytes() / nodes, field_B/node = the FlowField
//                                 handed in (x, y, ux, uy and the cells) per node;
//   BM_Sample/<method>_<order>      1e5 points uniform in the box, in the DEM's spatial order (row-
//                                 major cells of one particle diameter, as CellGrid::spatialOrder)
//                                 or in random order: ns/sample;
//   BM_DemStep                    a settled bed of ~1e5 spheres (mass_model "sphere") stepped
//                                 without and with [fluid] (quadratic drag, the cell field),
//                                 alternately, so that machine load hits both alike: ms per step of
//                                 each, the Forces stage of each, and the fluid share of a step;
//   BM_FluidForces / BM_FluidSampleOnly  addFluidForces alone on that bed, and its interpolation
//                                 alone (sample at every particle), for the share's split.
// Run: build/bench/granulab_bench_fluid (see bench/README.md for filters).
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/dem/dem_engine.hpp"
#include "app/engine_table.hpp"
#include "core/timer.hpp"
#include "dem/fluid_forces.hpp"
#include "dem/setup.hpp"
#include "dem/world.hpp"
#include "fluid/field_interpolator.hpp"
#include "fluid/flow_field.hpp"
#include "io/flow_fields.hpp"

namespace {

using namespace granulab;

constexpr std::size_t kSide = 1000;                          ///< nodes per row and per column (1e6 nodes)
constexpr std::size_t kSamples = 100000;                     ///< sample points (the DEM's 1e5 particles)
constexpr std::int64_t kBedColumns = 316;                    ///< 316 x 316 hexagonal bed: ~1e5 disks
constexpr Real kBox = static_cast<Real>(kBedColumns) + 0.5;  ///< [m] box (and field) edge

enum class FieldKind { Cells, Scattered, Tensor };

/// The analytic velocity: a mean upward stream with a smooth cellular perturbation.
Vec2 velocityAt(Real x, Real y) {
    const Real k = 2 * std::numbers::pi / kBox;
    return {0.3 * std::sin(3 * k * x) * std::cos(2 * k * y),
            1.0 + 0.2 * std::cos(2 * k * x) * std::sin(3 * k * y)};
}

/// A kSide x kSide field over [0, kBox]^2. Cells and Scattered: interior nodes jittered by up to
/// 0.2 of the spacing (boundary nodes only along the boundary, so the domain stays the box; quads
/// stay convex); Cells adds the quads of the jittered grid.
fluid::FlowField makeField(FieldKind kind) {
    fluid::FlowField f;
    f.source = "synthetic";
    const std::size_t n = kSide * kSide;
    const Real h = kBox / static_cast<Real>(kSide - 1);
    f.x.resize(n);
    f.y.resize(n);
    f.ux.resize(n);
    f.uy.resize(n);
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<Real> jitter(-0.2 * h, 0.2 * h);
    const bool jittered = kind != FieldKind::Tensor;
    for (std::size_t j = 0; j < kSide; ++j)
        for (std::size_t i = 0; i < kSide; ++i) {
            const std::size_t k = i + kSide * j;
            Real x = static_cast<Real>(i) * h, y = static_cast<Real>(j) * h;
            if (jittered) {
                const Real jx = jitter(rng), jy = jitter(rng);
                if (i > 0 && i + 1 < kSide) x += jx;
                if (j > 0 && j + 1 < kSide) y += jy;
            }
            f.x[k] = x;
            f.y[k] = y;
            const Vec2 u = velocityAt(x, y);
            f.ux[k] = u.x;
            f.uy[k] = u.y;
        }
    if (kind == FieldKind::Cells) {
        const std::size_t cells = (kSide - 1) * (kSide - 1);
        f.cellOffsets.reserve(cells + 1);
        f.cellNodes.reserve(4 * cells);
        f.cellOffsets.push_back(0);
        for (std::size_t j = 0; j + 1 < kSide; ++j)
            for (std::size_t i = 0; i + 1 < kSide; ++i) {
                const auto k = static_cast<std::uint32_t>(i + kSide * j),
                           row = static_cast<std::uint32_t>(kSide);
                f.cellNodes.insert(f.cellNodes.end(), {k, k + 1, k + 1 + row, k + row});  // counter-clockwise
                f.cellOffsets.push_back(static_cast<std::uint32_t>(f.cellNodes.size()));
            }
    }
    return f;
}

const fluid::FlowField& field(FieldKind kind) {
    static std::map<FieldKind, fluid::FlowField> cache;
    auto it = cache.find(kind);
    if (it == cache.end()) it = cache.emplace(kind, makeField(kind)).first;
    return it->second;
}

/// Bytes the FlowField holds (capacity of every array).
double flowFieldBytes(const fluid::FlowField& f) {
    return static_cast<double>(
        (f.x.capacity() + f.y.capacity() + f.ux.capacity() + f.uy.capacity() + f.p.capacity()) *
            sizeof(Real) +
        (f.cellOffsets.capacity() + f.cellNodes.capacity()) * sizeof(std::uint32_t));
}

struct Variant {
    FieldKind kind;
    std::string method;
    fluid::Outside outside = fluid::Outside::Zero;
};

fluid::InterpolatorOptions optionsOf(const Variant& v) {
    fluid::InterpolatorOptions o;
    o.method = v.method;
    o.outside = v.outside;
    return o;
}

const fluid::FieldInterpolator& interpolator(const std::string& method) {
    static std::map<std::string, std::unique_ptr<fluid::FieldInterpolator>> cache;
    auto& p = cache[method];
    if (!p) {
        const FieldKind kind = method == "cell"
                                   ? FieldKind::Cells
                                   : (method == "shepard" ? FieldKind::Scattered : FieldKind::Tensor);
        p = std::make_unique<fluid::FieldInterpolator>(field(kind), optionsOf({kind, method}));
        if (p->methodName() != method)
            throw std::runtime_error("fluid_interpolation: got " + std::string(p->methodName()));
    }
    return *p;
}

void BM_Construct(benchmark::State& state, Variant v) {
    const fluid::FlowField& f = field(v.kind);
    const fluid::InterpolatorOptions o = optionsOf(v);
    std::size_t bytes = 0, nodes = 1;
    std::string name;
    for (auto _ : state) {
        state.PauseTiming();
        fluid::FlowField copy = f;
        state.ResumeTiming();
        fluid::FieldInterpolator interp(std::move(copy), o);
        benchmark::DoNotOptimize(&interp);
        state.PauseTiming();
        bytes = interp.memoryBytes();
        nodes = interp.nodes();
        name = interp.methodName();
        state.ResumeTiming();
    }
    state.SetLabel(name);
    state.counters["nodes"] = static_cast<double>(nodes);
    state.counters["bytes/node"] = static_cast<double>(bytes) / static_cast<double>(nodes);
    state.counters["field_B/node"] = flowFieldBytes(f) / static_cast<double>(f.size());
}
BENCHMARK_CAPTURE(BM_Construct, cell, Variant{FieldKind::Cells, "cell"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_Construct, cell_via_auto, Variant{FieldKind::Cells, "auto"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_Construct, cell_outside_nearest,
                  Variant{FieldKind::Cells, "cell", fluid::Outside::Nearest})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_Construct, shepard, Variant{FieldKind::Scattered, "shepard"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_Construct, shepard_via_auto, Variant{FieldKind::Scattered, "auto"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_Construct, bilinear, Variant{FieldKind::Tensor, "bilinear"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

/// kSamples points uniform in the box; `sorted`: row-major by cells of edge 1 m (one particle
/// diameter, CellGrid::spatialOrder's order), else random.
const std::vector<Vec2>& samplePoints(bool sorted) {
    static std::map<bool, std::vector<Vec2>> cache;
    auto& pts = cache[sorted];
    if (pts.empty()) {
        std::mt19937_64 rng(99);
        std::uniform_real_distribution<Real> u(0, kBox);
        pts.resize(kSamples);
        for (auto& p : pts) p = {u(rng), u(rng)};
        if (sorted) {
            const auto nx = static_cast<std::int64_t>(kBox) + 1;
            const auto key = [&](Vec2 p) {
                return static_cast<std::int64_t>(p.y) * nx + static_cast<std::int64_t>(p.x);
            };
            std::stable_sort(pts.begin(), pts.end(), [&](Vec2 a, Vec2 b) { return key(a) < key(b); });
        }
    }
    return pts;
}

/// Nanoseconds per item of a timed loop (wall time measured by the benchmark itself, so that the
/// counter prints as a plain number).
double nsPer(double seconds, benchmark::State& state, std::size_t items) {
    return 1e9 * seconds / (static_cast<double>(state.iterations()) * static_cast<double>(items));
}

void BM_Sample(benchmark::State& state, std::string method, bool sorted) {
    const fluid::FieldInterpolator& interp = interpolator(method);
    const std::vector<Vec2>& pts = samplePoints(sorted);
    std::size_t inside = 0;
    const double t0 = wallSeconds();
    for (auto _ : state) {
        Real sum = 0;
        inside = 0;
        interp.visit([&](const auto& m) {  // as dem/fluid_forces.cpp: no dispatch per point
            fluid::FluidSample s;
            for (const Vec2 p : pts) {
                m.sample(p, s);
                sum += s.u.x + s.u.y;
                inside += s.inside ? 1 : 0;
            }
        });
        benchmark::DoNotOptimize(sum);
    }
    const double seconds = wallSeconds() - t0;
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
    state.counters["ns/sample"] = nsPer(seconds, state, pts.size());
    state.counters["inside"] = static_cast<double>(inside) / static_cast<double>(pts.size());
    state.counters["bytes/node"] =
        static_cast<double>(interp.memoryBytes()) / static_cast<double>(interp.nodes());
}
BENCHMARK_CAPTURE(BM_Sample, cell_sorted, std::string("cell"), true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sample, cell_random, std::string("cell"), false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sample, shepard_sorted, std::string("shepard"), true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sample, shepard_random, std::string("shepard"), false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sample, bilinear_sorted, std::string("bilinear"), true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sample, bilinear_random, std::string("bilinear"), false)->Unit(benchmark::kMillisecond);

/// The DEM scene: a touching hexagonal packing of 316 x 316 spheres (R = 0.5 m, rho = 1 kg/m^3,
/// mass_model "sphere") on the floor of a kBox x kBox box under g = 10, damped for the first
/// 0.02 s; `fluid`: plus a gas (rho_f = 1e-3) with quadratic drag.
std::string bedScene(bool fluid) {
    const double ymax = static_cast<double>(kBedColumns) * std::sqrt(3.0) / 2;
    std::string text = fmt::format(R"(
[run]
seed = 12345
end_time = 1000.0
[dem]
dt = 1.0e-4
gravity = [0.0, -10.0]
skin = 0.1
mass_model = "sphere"
[[dem.damping]]
gamma = 2.0
from = 0.0
to = 0.02
[[material]]
name = "grain"
density = 1.0
[[contact]]
materials = ["*", "*"]
normal = "hooke"
kn = 2.0e5
damping = "lammps"
gamma_n = 50.0
tangential = "cundall_strack"
mu = 0.5
[[block]]
lattice = "hexagonal"
spacing = 1.0
origin = [0.5, 0.5]
region = [0.1, 0.0, {:.6f}, {:.6f}]
radius = 0.5
material = "grain"
[[wall]]
name = "box"
points = [[0.0, {:.6f}], [0.0, 0.0], [{:.6f}, 0.0], [{:.6f}, {:.6f}]]
material = "grain"
)",
                                   static_cast<double>(kBedColumns) + 0.25, ymax, kBox, kBox, kBox, kBox);
    if (fluid)
        text += R"(
[fluid]
density = 1.0e-3
drag = "quadratic"
cw = 0.47
buoyancy = true
)";
    return text;
}

constexpr int kSettleSteps = 300;

/// Initialized, settled worlds without and with the fluid (the cell field via a FieldSource whose
/// loader hands out the synthetic field, as the app's does with the files' fields).
struct Beds {
    std::unique_ptr<dem::World> dry, wet;
};
Beds& beds() {
    static Beds b;
    if (!b.dry) {
        for (const bool fluid : {false, true}) {
            const model::SceneDef scene = app::readSceneText(bedScene(fluid), "<fluid_interpolation>");
            const dem::PreparedScene prepared = app::checkAndPrepareDem(scene);
            fluid::FieldSource source;
            if (fluid) {
                source.times = {0.0};
                source.options = io::interpolatorOptions(scene.fluid);  // interpolation = "auto" -> cell
                source.load = [](std::size_t) { return field(FieldKind::Cells); };
            }
            auto w = std::make_unique<dem::World>(dem::makeWorld(scene, prepared.initial, std::move(source)));
            w->initialize();
            for (int k = 0; k < kSettleSteps; ++k)
                if (w->step() != dem::kStepOk)
                    throw std::runtime_error("fluid_interpolation: the bed became unstable");
            (fluid ? b.wet : b.dry) = std::move(w);
        }
    }
    return b;
}

void BM_DemStep(benchmark::State& state) {
    Beds& b = beds();
    const double dryForces0 = b.dry->timers().seconds(dem::Stage::Forces);
    const double wetForces0 = b.wet->timers().seconds(dem::Stage::Forces);
    const double wetFluid0 = b.wet->timers().seconds(dem::Stage::Fluid);
    double dry = 0, wet = 0;
    for (auto _ : state) {
        const double t0 = wallSeconds();
        const std::uint32_t s1 = b.dry->step();
        const double t1 = wallSeconds();
        const std::uint32_t s2 = b.wet->step();
        const double t2 = wallSeconds();
        if (s1 != dem::kStepOk || s2 != dem::kStepOk) {
            state.SkipWithError("World::step reported an unstable state");
            break;
        }
        dry += t1 - t0;
        wet += t2 - t1;
        state.SetIterationTime(t2 - t0);
    }
    const double steps = static_cast<double>(state.iterations());
    const double dryForces = (b.dry->timers().seconds(dem::Stage::Forces) - dryForces0) / steps;
    const double wetForces = (b.wet->timers().seconds(dem::Stage::Forces) - wetForces0) / steps;
    const double wetFluid = (b.wet->timers().seconds(dem::Stage::Fluid) - wetFluid0) / steps;
    const auto n = static_cast<double>(b.wet->store().size());
    state.counters["particles"] = n;
    state.counters["dry_ms/step"] = 1e3 * dry / steps;
    state.counters["fluid_ms/step"] = 1e3 * wet / steps;
    state.counters["dry_forces_ms"] = 1e3 * dryForces;
    state.counters["fluid_forces_ms"] = 1e3 * wetForces;
    state.counters["fluid_share_%"] = 100 * (wet - dry) / wet;
    // The fluid stage (drag, buoyancy: interpolation included) of the wet world's own step; the
    // difference above also holds the wet bed's different motion (the stream lifts it).
    state.counters["fluid_stage_ms"] = 1e3 * wetFluid;
    state.counters["fluid_stage_share_%"] = 100 * wetFluid * steps / wet;
    state.counters["outside"] = static_cast<double>(b.wet->fluidStats().outside);
    state.counters["contacts/particle"] = static_cast<double>(b.wet->forceStats().contacts) / n;
    state.counters["field_B/node"] = static_cast<double>(b.wet->field()->memoryBytes()) /
                                     static_cast<double>(b.wet->field()->first().nodes());
    state.SetLabel(b.wet->field()->first().methodName());
}
BENCHMARK(BM_DemStep)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);

/// addFluidForces alone on the settled wet bed (a copy of its store, forces accumulating).
void BM_FluidForces(benchmark::State& state) {
    Beds& b = beds();
    model::ParticleStore store = b.wet->store();
    dem::FluidStats stats;
    dem::VoidageScratch scratch;
    const double t0 = wallSeconds();
    for (auto _ : state) {
        dem::addFluidForces(store, *b.wet->field(), b.wet->config().fluid->forces, Vec2{0.0, -10.0}, stats,
                            scratch);
        benchmark::DoNotOptimize(store.fx.data());
        benchmark::ClobberMemory();
    }
    state.counters["ns/particle"] = nsPer(wallSeconds() - t0, state, store.size());
}
BENCHMARK(BM_FluidForces)->Unit(benchmark::kMillisecond);

/// The interpolation part of BM_FluidForces: one sample per particle, in the store's order.
void BM_FluidSampleOnly(benchmark::State& state) {
    Beds& b = beds();
    const model::ParticleStore& store = b.wet->store();
    const fluid::FieldInterpolator& interp = b.wet->field()->first();
    const double t0 = wallSeconds();
    for (auto _ : state) {
        Real sum = 0;
        interp.visit([&](const auto& m) {
            fluid::FluidSample s;
            for (std::size_t i = 0; i < store.size(); ++i) {
                m.sample(Vec2{store.x[i], store.y[i]}, s);
                sum += s.u.x + s.u.y;
            }
        });
        benchmark::DoNotOptimize(sum);
    }
    state.counters["ns/particle"] = nsPer(wallSeconds() - t0, state, store.size());
}
BENCHMARK(BM_FluidSampleOnly)->Unit(benchmark::kMillisecond);

}  // namespace
