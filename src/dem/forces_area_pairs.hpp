// SPDX-License-Identifier: MIT
// gc2d area kernels (gc2d spec section 3, Eq. 2.15-2.29): the particle pairs and particle-wall
// pairs of one bucket, geometry (dem/forces_area.hpp) then law, summed in pair order.
// Included by dem/forces.cpp only.
#pragma once
#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "dem/forces.hpp"
#include "dem/forces_area.hpp"
#include "dem/forces_detail.hpp"

namespace granulab::dem::detail {
// Internal linkage (an unnamed namespace), as when these functions lived in one .cpp: GCC inlines
// a kernel called once only where no other translation unit can call it.
namespace {

/// Debug checks of an area-law bucket [begin, end) of `list` (compiled out in Release).
inline void assertAreaBucket([[maybe_unused]] const ContactList& list, [[maybe_unused]] std::uint32_t begin,
                             [[maybe_unused]] std::uint32_t end,
                             [[maybe_unused]] bool trialHistory) noexcept {
    GL_ASSERT(begin <= end && end <= list.size() && list.features.size() == list.size(),
              "bucket inside the list, one feature cache per pair");
    GL_ASSERT((trialHistory ? list.areaOldTrial : list.areaOld).size() == list.size(),
              "area history allocated");
    GL_ASSERT(!trialHistory || list.xiTrial.size() == list.size(), "trial springs allocated");
}

/// gc2d area contacts of one bucket of particle pairs (any shapes); N: AreaNormal or AreaPotentialNormal.
/// kCross: a cross bucket (j in another tile): j's share goes to deferred[p - crossBegin] (zero
/// when not touching) instead of j's sums. `features`: the closest-feature work of this tile.
/// kLog: record every contact in `log` (output steps only; a compile-time switch, as diskPairs').
template <class N, class D, class T, bool kCross, bool kLog>
void areaPairs(model::ParticleStore& s, ContactList& list, std::uint32_t begin, std::uint32_t end,
               const LawTable& laws, const DriftVelocities& drift, Real dt, bool trialHistory,
               ForceStats& stats, const ShapeContext& sc, geom::FeatureStats& features, ContactLog* log,
               DeferredForce* deferred, std::uint32_t crossBegin) noexcept {
    const std::uint32_t nm = laws.materialCount();
    const ContactLaw* table = laws.laws().data();
    Real* xiHist = trialHistory ? list.xiTrial.data() : list.xi.data();
    Real* areaHist = trialHistory ? list.areaOldTrial.data() : list.areaOld.data();
    assertAreaBucket(list, begin, end, trialHistory);
    std::uint64_t contacts = 0;
    Real maxRel = stats.maxRelativeOverlap;
    const Real invDt = 1.0 / dt;
    // Two passes over batches of touching pairs: geometry first, then the law. The law's short,
    // independent iterations let the processor overlap their square roots and divisions; the
    // forces are still summed in pair order (bit-identical to a single pass).
    struct Pending {
        std::uint32_t p, i, j;
        bool normalPending;  ///< g.normal still to be computed (geom::crossings::chainNormal)
        geom::AreaContact g;
    };
    constexpr int kBatch = 32;
    Pending batch[kBatch];
    int pending = 0;
    const auto flush = [&] {
        for (int b = 0; b < pending; ++b) {
            const Pending& q = batch[b];
            const std::uint32_t i = q.i, j = q.j;
            area::AreaPair c;
            c.g = q.g;
            const Vec2 xi{s.x[i], s.y[i]}, xj{s.x[j], s.y[j]};
            if (q.normalPending) geom::crossings::chainNormal(c.g, xi, xj);
            c.ri = c.g.point - xi;
            c.rj = c.g.point - xj;
            c.vi = pointVelocity(s.vx.data(), s.vy.data(), s.omega.data(), i, c.ri);
            c.vj = pointVelocity(s.vx.data(), s.vy.data(), s.omega.data(), j, c.rj);
            if (drift.vx) {
                c.hasDrift = true;
                c.di = pointVelocity(drift.vx, drift.vy, drift.omega, i, c.ri);
                c.dj = pointVelocity(drift.vx, drift.vy, drift.omega, j, c.rj);
            }
            c.invMi = s.invMass[i];
            c.invMj = s.invMass[j];
            c.invIi = s.invInertia[i];
            c.invIj = s.invInertia[j];
            if constexpr (std::is_same_v<N, AreaPotentialNormal>)
                c.invL0 = area::potentialInvL0(s.radius[i], s.radius[j]);
            const ContactLaw& law = table[static_cast<std::size_t>(s.material[i]) * nm + s.material[j]];
            const area::AreaForce f =
                area::areaLaw(*std::get_if<N>(&law.normal), *std::get_if<D>(&law.damping),
                              *std::get_if<T>(&law.tangential), c, dt, invDt, xiHist[q.p], areaHist[q.p]);
            s.fx[i] += f.onI.x;
            s.fy[i] += f.onI.y;
            constexpr bool kCouple = std::is_same_v<N, AreaPotentialNormal>;
            s.torque[i] += kCouple ? cross(c.ri, f.onI) + f.couple : cross(c.ri, f.onI);
            const Real torqueJ = kCouple ? cross(c.rj, f.onI) + f.couple : cross(c.rj, f.onI);
            if constexpr (kCross) {
                deferred[q.p - crossBegin] = {-f.onI.x, -f.onI.y, -torqueJ};
            } else {
                s.fx[j] -= f.onI.x;
                s.fy[j] -= f.onI.y;
                s.torque[j] -= torqueJ;
            }
            if constexpr (kLog)  // normal from i toward j: the geometry's normal pushes i away from j
                log->addArea(s.id[i], s.id[j], -1, c.g.point, -c.g.normal, f.onI, f.overlapDepth, c.g.area,
                             norm(c.g.c2 - c.g.c1));
            const Real rMin = std::min(s.radius[i], s.radius[j]);
            if (f.overlapDepth > maxRel * rMin)
                maxRel = f.overlapDepth / rMin;  // divide only for a new maximum
        }
        pending = 0;
    };
    for (std::uint32_t p = begin; p < end; ++p) {
        const std::uint32_t i = list.first[p], j = list.second[p];
        GL_ASSERT(i < s.size() && j < s.size(), "pair slots in range");
        const Real dx = s.x[j] - s.x[i], dy = s.y[j] - s.y[i], rsum = s.radius[i] + s.radius[j];
        if (dx * dx + dy * dy >= rsum * rsum) {  // bounding circles apart: no contact possible
            xiHist[p] = 0;
            areaHist[p] = 0;
            if constexpr (kCross) deferred[p - crossBegin] = {0, 0, 0};
            continue;
        }
        Pending& q = batch[pending];
        q.normalPending = area::pairGeometryInto<true>(s, sc, i, j, list.features[p], features, q.g);
        if (!q.g.touching) {
            xiHist[p] = 0;
            areaHist[p] = 0;
            if constexpr (kCross) deferred[p - crossBegin] = {0, 0, 0};
            continue;
        }
        ++contacts;
        q.p = p;
        q.i = i;
        q.j = j;
        if (++pending == kBatch) flush();
    }
    flush();
    stats.contacts += contacts;
    stats.maxRelativeOverlap = maxRel;
}

/// gc2d area contacts of particles with wall segments (the wall: an immovable body).
template <class N, class D, class T>
void areaWalls(model::ParticleStore& s, const model::WallSet& walls, ContactList& list, std::uint32_t begin,
               std::uint32_t end, const LawTable& laws, const DriftVelocities& drift, Real dt,
               bool trialHistory, ForceStats& stats, Vec2* wallForce, const ShapeContext& sc,
               geom::FeatureStats& features, ContactLog* log) noexcept {
    const std::uint32_t nm = laws.materialCount();
    const ContactLaw* table = laws.laws().data();
    Real* xiHist = trialHistory ? list.xiTrial.data() : list.xi.data();
    Real* areaHist = trialHistory ? list.areaOldTrial.data() : list.areaOld.data();
    assertAreaBucket(list, begin, end, trialHistory);
    std::uint64_t contacts = 0;
    for (std::uint32_t p = begin; p < end; ++p) {
        const std::uint32_t i = list.first[p];
        GL_ASSERT(i < s.size() && list.second[p] < walls.segments.size(), "slot and segment in range");
        const auto& seg = walls.segments[list.second[p]];
        const Vec2 xi{s.x[i], s.y[i]};
        area::AreaPair c;
        c.wall = true;
        c.g = area::wallGeometry(s, sc, walls, i, list.second[p], list.features[p], features);
        if (!c.g.touching) {
            xiHist[p] = 0;
            areaHist[p] = 0;
            continue;
        }
        ++contacts;
        // Wall point velocity, plus the belt's surface velocity (tangential only, gc2d 6.1).
        const Vec2 t = perp(c.g.normal);
        const Vec2 wallVel =
            walls.velocityAt(seg.wall, c.g.point) + t * dot(walls.walls[seg.wall].surfaceVelocity, t);
        c.ri = c.g.point - xi;
        if (walls.walls[seg.wall].body) {
            c.wallBody = true;
            c.rj = c.g.point - walls.bodyCentroid[seg.wall];
        }
        c.vi = pointVelocity(s.vx.data(), s.vy.data(), s.omega.data(), i, c.ri);
        c.vj = wallVel;
        if (drift.vx) {
            c.hasDrift = true;
            c.di = pointVelocity(drift.vx, drift.vy, drift.omega, i, c.ri);
            c.dj = wallVel;
        }
        c.invMi = s.invMass[i];
        c.invIi = s.invInertia[i];
        c.invL0 = 1.0 / s.radius[i];  // area_potential: l0 = R_i (read by that law only)
        const ContactLaw& law = table[static_cast<std::size_t>(s.material[i]) * nm + seg.material];
        const area::AreaForce f =
            area::areaLaw(*std::get_if<N>(&law.normal), *std::get_if<D>(&law.damping),
                          *std::get_if<T>(&law.tangential), c, dt, 1.0 / dt, xiHist[p], areaHist[p]);
        s.fx[i] += f.onI.x;
        s.fy[i] += f.onI.y;
        s.torque[i] += cross(c.ri, f.onI) + f.couple;  // couple: 0 but for area_potential
        wallForce[seg.wall] -= f.onI;
        if (log)
            log->addArea(s.id[i], 0, static_cast<std::int32_t>(seg.wall), c.g.point, -c.g.normal, f.onI,
                         f.overlapDepth, c.g.area, norm(c.g.c2 - c.g.c1));
        stats.maxRelativeOverlap = std::max(stats.maxRelativeOverlap, f.overlapDepth / s.radius[i]);
    }
    stats.wallContacts += contacts;
}

}  // namespace
}  // namespace granulab::dem::detail
