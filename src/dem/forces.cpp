// SPDX-License-Identifier: MIT
// The force evaluation (stages 4+6 of the DEM step, DESIGN.md): body forces (gravity, global viscous
// damping, pull springs of gc2d spec section 3.8), then the contact kernels of every bucket of pairs.
// Why this shape: the law form is dispatched once per bucket (std::visit over the three axis
// variants, dem/forces_detail.hpp), the loop body is a template with the law inlined; parameters of
// a material pair are read from the LawTable with the alternative known at compile time. Threads
// take whole slot tiles (dem/slot_tiles.hpp): a tile's grains get their body forces, then the
// pairs of the tile in list order; the share of a cross pair for a grain of another tile is
// deferred and gathered afterwards in a fixed order, so the floating-point summation order is
// the same for any thread count (docs/physics/dem-threads.md). The kernels are headers
// included here only, so that they are compiled and inlined in this translation unit.
#include "dem/forces.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <type_traits>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "dem/forces_area_pairs.hpp"
#include "dem/forces_depth.hpp"
#include "dem/forces_detail.hpp"
#include "geom/rotation.hpp"

namespace granulab::dem {

using detail::kAreaForm;
using detail::kDepthForm;

namespace {

/// Body forces of the slots [begin, end): weight and global viscous damping (overwrites f, torque).
void bodyForces(model::ParticleStore& s, const BodyForces& body, std::uint32_t begin,
                std::uint32_t end) noexcept {
    const Vec2 weightG = body.weight ? body.gravity : Vec2{};
    const Real gamma = body.gamma, gammaRotation = body.gammaRotation;
    const Real* __restrict mass = s.mass.data();
    const Real* __restrict vx = s.vx.data();
    const Real* __restrict vy = s.vy.data();
    const Real* __restrict omega = s.omega.data();
    Real* __restrict fx = s.fx.data();
    Real* __restrict fy = s.fy.data();
    Real* __restrict tq = s.torque.data();
#pragma omp simd
    for (std::uint32_t i = begin; i < end; ++i) {
        fx[i] = mass[i] * weightG.x - gamma * vx[i];
        fy[i] = mass[i] * weightG.y - gamma * vy[i];
        tq[i] = -gammaRotation * omega[i];
    }
}

/// Pull springs (gc2d spec section 3.8) of the particles in the slots [begin, end), in spring order.
void springForces(model::ParticleStore& s, const BodyForces& body, std::uint32_t begin,
                  std::uint32_t end) noexcept {
    if (!body.springs) return;
    for (const PullSpring& sp : *body.springs) {
        const std::uint32_t i = sp.slot;  // kRemovedSlot: another rank's particle (dem/parallel/)
        if (i < begin || i >= end) continue;
        GL_ASSERT(i < s.size(), "spring slot in range");
        const auto [c, sn] = geom::rotationOf(s.angle[i]);
        const Vec2 arm{c * sp.attach.x - sn * sp.attach.y, sn * sp.attach.x + c * sp.attach.y};
        const Vec2 f = (sp.freeEnd(body.time) - (Vec2{s.x[i], s.y[i]} + arm)) * sp.stiffness;
        s.fx[i] += f.x;
        s.fy[i] += f.y;
        s.torque[i] += cross(arm, f);
    }
}

/// Copies the accepted history of the entries [begin, end) to the trial columns.
void startTrial(ContactList& l, std::uint32_t begin, std::uint32_t end) noexcept {
    std::copy(l.xi.begin() + begin, l.xi.begin() + end, l.xiTrial.begin() + begin);
    if (!l.zeta.empty()) std::copy(l.zeta.begin() + begin, l.zeta.begin() + end, l.zetaTrial.begin() + begin);
    if (!l.areaOld.empty())
        std::copy(l.areaOld.begin() + begin, l.areaOld.begin() + end, l.areaOldTrial.begin() + begin);
}

/// Everything tile t adds: body forces and springs of its grains, then its inner pairs, its cross
/// pairs (their second grain's share deferred) and its wall pairs, bucket by bucket.
void tileForces(std::uint32_t t, model::ParticleStore& s, const model::WallSet& walls, NeighborList& list,
                const LawTable& laws, const BodyForces& body, const DriftVelocities& drift, Real dt,
                bool trialHistory, const ShapeContext& shapes, ForceWorkspace& ws, bool logging) noexcept {
    const std::uint32_t first = list.tiles.begin(t), last = list.tiles.end(t);
    bodyForces(s, body, first, last);
    springForces(s, body, first, last);
    ForceStats& stats = ws.counters[t].stats;
    stats = ForceStats{};
    geom::FeatureStats& features = ws.counters[t].features;
    ContactLog* log = logging ? &ws.tileLogs[t] : nullptr;
    if (log) log->records.clear();
    Vec2* wallForce = ws.tileWallForce.data() + t * ws.wallStride;
    std::fill(wallForce, wallForce + walls.walls.size(), Vec2{});
    if (trialHistory) {  // every evaluation of a step starts from the accepted history
        startTrial(list.pairs, list.tileBegin(list.pairs, t), list.tileBegin(list.pairs, t + 1));
        startTrial(list.wallPairs, list.tileBegin(list.wallPairs, t), list.tileBegin(list.wallPairs, t + 1));
    }
    DeferredForce* deferred = ws.deferred.data() + list.crossBase[t];
    const std::uint32_t crossBegin = list.crossBegin(t);
    if (body.particleContacts)
        for (const bool cross : {false, true})
            detail::forEachBucketIn(
                list.pairs, laws, list.bucket(t, cross, 0), list.bucket(t, cross, 0) + list.forms,
                [&](auto* nT, auto* dT, auto* tT, std::uint32_t b, std::uint32_t e) {
                    using N = std::remove_pointer_t<decltype(nT)>;
                    using D = std::remove_pointer_t<decltype(dT)>;
                    using T = std::remove_pointer_t<decltype(tT)>;
                    const auto run = [&](auto crossTag, auto logTag) {
                        constexpr bool kCross = decltype(crossTag)::value, kLog = decltype(logTag)::value;
                        if constexpr (kAreaForm<N, D, T>) {
                            detail::areaPairs<N, D, T, kCross, kLog>(s, list.pairs, b, e, laws, drift, dt,
                                                                     trialHistory, stats, shapes, features,
                                                                     log, deferred, crossBegin);
                        } else if constexpr (kDepthForm<N, D, T>) {
                            if (laws.hasRolling())
                                detail::diskPairs<N, D, T, true, kCross, kLog>(
                                    s, list.pairs, b, e, laws, drift, dt, body.overlapGuard, trialHistory,
                                    stats, log, deferred, crossBegin);
                            else
                                detail::diskPairs<N, D, T, false, kCross, kLog>(
                                    s, list.pairs, b, e, laws, drift, dt, body.overlapGuard, trialHistory,
                                    stats, log, deferred, crossBegin);
                        }
                    };
                    const auto withLog = [&](auto crossTag) {
                        if (log)
                            run(crossTag, std::true_type{});
                        else
                            run(crossTag, std::false_type{});
                    };
                    if (cross)
                        withLog(std::true_type{});
                    else
                        withLog(std::false_type{});
                });
    if (body.wallContacts)
        detail::forEachBucketIn(
            list.wallPairs, laws, list.bucket(t, false, 0), list.bucket(t, false, 0) + list.forms,
            [&](auto* nT, auto* dT, auto* tT, std::uint32_t b, std::uint32_t e) {
                using N = std::remove_pointer_t<decltype(nT)>;
                using D = std::remove_pointer_t<decltype(dT)>;
                using T = std::remove_pointer_t<decltype(tT)>;
                if constexpr (kAreaForm<N, D, T>)
                    detail::areaWalls<N, D, T>(s, walls, list.wallPairs, b, e, laws, drift, dt, trialHistory,
                                               stats, wallForce, shapes, features, log);
                else if constexpr (kDepthForm<N, D, T>)
                    detail::diskWalls<N, D, T>(s, walls, list.wallPairs, b, e, laws, drift, dt, trialHistory,
                                               stats, wallForce, log);
            });
}

/// Adds the deferred shares of the cross pairs to the grains of tile t, in gather order.
void gatherDeferred(std::uint32_t t, model::ParticleStore& s, const NeighborList& list,
                    const ForceWorkspace& ws) noexcept {
    for (std::uint32_t k = list.gatherStart[t]; k < list.gatherStart[t + 1]; ++k) {
        const DeferredForce& d = ws.deferred[list.gatherFrom[k]];
        const std::uint32_t j = list.gatherSlot[k];
        s.fx[j] += d.fx;
        s.fy[j] += d.fy;
        s.torque[j] += d.torque;
    }
}

/// Splits the tiles into ws.threads contiguous runs of about equal work (ws.cuts, and ws.slotCuts
/// in slots). A tile's work is its measured time at the last evaluations (ws.tileSeconds: it knows
/// what no count does, the shapes, the walls, the cache misses); until every tile has been
/// measured, an estimate from its slots, its candidate pairs and the contacts it had at the last
/// evaluation (a touching pair costs several times an apart one). The split changes only the work
/// per thread, never the order in which a grain's forces are added.
void splitTiles(const NeighborList& list, ForceWorkspace& ws) noexcept {
    const std::uint32_t tiles = list.tiles.count;
    const int parts = std::max(1, std::min<int>(ws.threads, static_cast<int>(tiles)));
    ws.cuts.resize(static_cast<std::size_t>(parts) + 1);
    if (parts == 1) {
        ws.cuts[0] = 0;
        ws.cuts[1] = tiles;
        ws.slotCuts.clear();
        ws.tileSeconds.clear();  // stale once the thread count changes back
        return;
    }
    ws.tileWork.resize(tiles);
    if (ws.tileSeconds.size() != tiles) ws.tileSeconds.assign(tiles, 0.0);
    const bool measured =
        std::all_of(ws.tileSeconds.begin(), ws.tileSeconds.end(), [](double s) { return s > 0; });
    for (std::uint32_t t = 0; t < tiles; ++t) {
        if (measured) {
            ws.tileWork[t] = ws.tileSeconds[t];
            continue;
        }
        const auto pairs = list.tileBegin(list.pairs, t + 1) - list.tileBegin(list.pairs, t);
        const auto wallPairs = list.tileBegin(list.wallPairs, t + 1) - list.tileBegin(list.wallPairs, t);
        const ForceStats& last = ws.counters[t].stats;
        ws.tileWork[t] = static_cast<double>(list.tiles.end(t) - list.tiles.begin(t)) +
                         2.0 * static_cast<double>(pairs + wallPairs) +
                         6.0 * static_cast<double>(last.contacts + last.wallContacts);
    }
    splitByWeight(ws.tileWork.data(), tiles, parts, ws.cuts.data());
    ws.slotCuts.resize(ws.cuts.size());
    for (std::size_t k = 0; k < ws.cuts.size(); ++k)
        ws.slotCuts[k] = ws.cuts[k] < tiles ? list.tiles.begin(ws.cuts[k]) : list.tiles.slots;
}

/// Seconds on a monotonic clock (the tiles' times; a few tens of ns a call).
double nowSeconds() noexcept {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

void computeForces(model::ParticleStore& s, const model::WallSet& walls, NeighborList& list,
                   const LawTable& laws, const BodyForces& body, const DriftVelocities& drift, Real dt,
                   bool trialHistory, ForceStats& stats, std::vector<Vec2>& wallForce, ShapeContext& shapes,
                   ContactLog* log, ForceWorkspace* workspace) noexcept {
    GL_ASSERT(wallForce.size() == walls.walls.size(), "one force per wall");
    GL_ASSERT(list.tiles.slots == s.size(), "the list's tiles cover the store");
    ForceWorkspace local;
    ForceWorkspace& ws = workspace ? *workspace : local;
    const std::uint32_t tiles = list.tiles.count;
    const std::size_t nWalls = walls.walls.size();
    // Sized only when the tiles, the walls or the cross pairs grow (no allocation in steady state).
    ws.deferred.resize(list.crossPairs());
    ws.counters.resize(tiles);
    constexpr std::size_t kPerLine = 64 / sizeof(Vec2);
    ws.wallStride = (nWalls + kPerLine - 1) / kPerLine * kPerLine;
    ws.tileWallForce.resize(tiles * ws.wallStride);
    if (log && ws.tileLogs.size() < tiles) ws.tileLogs.resize(tiles);
    shapes.update(s, ws.threads, &ws.slotCuts);
    splitTiles(list, ws);
    // Each thread takes a contiguous run of tiles of about equal work, then gathers the deferred
    // shares of the same tiles after a barrier.
    parallelRanges(
        ws.threads, ws.cuts.data(),
        [&](std::size_t, std::uint32_t begin, std::uint32_t end) {
            if (ws.cuts.size() <= 2) {  // one thread: nothing to balance, no clock
                for (std::uint32_t t = begin; t < end; ++t)
                    tileForces(t, s, walls, list, laws, body, drift, dt, trialHistory, shapes, ws,
                               log != nullptr);
                return;
            }
            double start = nowSeconds();
            for (std::uint32_t t = begin; t < end; ++t) {
                tileForces(t, s, walls, list, laws, body, drift, dt, trialHistory, shapes, ws,
                           log != nullptr);
                const double stop = nowSeconds();
                // Smoothed over about 4 evaluations: a preempted tile does not swing the split.
                const double took = std::max(stop - start, 1e-9);
                double& seconds = ws.tileSeconds[t];
                seconds = seconds > 0 ? 0.75 * seconds + 0.25 * took : took;
                start = stop;
            }
        },
        [&](std::size_t, std::uint32_t begin, std::uint32_t end) {
            if (list.crossPairs() != 0)
                for (std::uint32_t t = begin; t < end; ++t) gatherDeferred(t, s, list, ws);
            // The forces of these tiles' grains are complete: the fused correction (World).
            if (ws.finishSlots && begin < end)
                ws.finishSlots(ws.finishContext, list.tiles.begin(begin), list.tiles.end(end - 1));
        });
    // Sums over tiles in tile order: the same for any thread count.
    stats = ForceStats{};
    for (auto& w : wallForce) w = Vec2{};
    if (log) log->records.clear();
    for (std::uint32_t t = 0; t < tiles; ++t) {
        stats.add(ws.counters[t].stats);
        for (std::size_t w = 0; w < nWalls; ++w) wallForce[w] += ws.tileWallForce[t * ws.wallStride + w];
        geom::FeatureStats& f = ws.counters[t].features;
        shapes.featureStats.evaluations += f.evaluations;
        shapes.featureStats.iterations += f.iterations;
        shapes.featureStats.coldStarts += f.coldStarts;
        shapes.featureStats.fullClips += f.fullClips;
        f = geom::FeatureStats{};
        if (log)
            log->records.insert(log->records.end(), ws.tileLogs[t].records.begin(),
                                ws.tileLogs[t].records.end());
    }
}

}  // namespace granulab::dem
