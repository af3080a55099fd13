// SPDX-License-Identifier: MIT
// Overlap-depth kernels (disks only): disk-disk and disk-wall contacts of one bucket, narrow phase
// fused with the law of the bucket's form (cfddem spec section 3: Hooke/Hertz normal, damping,
// Cundall-Strack/Mindlin tangential, rolling Eq. 3.56-3.59). Included by dem/forces.cpp only.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "dem/contact/kernel.hpp"
#include "dem/forces.hpp"
#include "dem/forces_detail.hpp"
#include "geom/segment.hpp"

namespace granulab::dem::detail {
// Internal linkage (an unnamed namespace), as when these functions lived in one .cpp: GCC inlines
// a kernel called once only where no other translation unit can call it.
namespace {

/// Disk-disk contacts of one bucket. n points from i to j; t = perp(n).
/// kRolling: some law of the scene has rolling resistance (LawTable::hasRolling).
/// kCross: a cross bucket (j in another tile): j's share goes to deferred[p - crossBegin] (zero
/// when not touching) instead of j's sums, which belong to another thread.
/// kLog: record every contact in `log` (output steps only). A compile-time switch: the call in the
/// loop, even never taken, cost the disk bed's kernel 16 % (register pressure around it).
template <class N, class D, class T, bool kRolling, bool kCross, bool kLog>
void diskPairs(model::ParticleStore& s, ContactList& list, std::uint32_t begin, std::uint32_t end,
               const LawTable& laws, const DriftVelocities& drift, Real dt, Real overlapGuard,
               bool trialHistory, ForceStats& stats, [[maybe_unused]] ContactLog* log,
               DeferredForce* deferred, std::uint32_t crossBegin) noexcept {
    const std::uint32_t nm = laws.materialCount();
    const ContactLaw* table = laws.laws().data();
    const Real* __restrict x = s.x.data();
    const Real* __restrict y = s.y.data();
    const Real* __restrict vx = s.vx.data();
    const Real* __restrict vy = s.vy.data();
    const Real* __restrict om = s.omega.data();
    const Real* __restrict rad = s.radius.data();
    const Real* __restrict mass = s.mass.data();
    const std::uint32_t* __restrict mat = s.material.data();
    Real* __restrict fx = s.fx.data();
    Real* __restrict fy = s.fy.data();
    Real* __restrict tq = s.torque.data();
    const std::uint32_t* __restrict pi = list.first.data();
    const std::uint32_t* __restrict pj = list.second.data();
    // History is read and written through one pointer: the accepted springs, or (iterating
    // integrators) the trial copy that computeForces refreshed from them.
    Real* __restrict xiHist = trialHistory ? list.xiTrial.data() : list.xi.data();
    constexpr bool rolling = kRolling;  // some law has rolling resistance (a compile-time switch)
    Real* __restrict zetaHist = trialHistory ? list.zetaTrial.data() : list.zeta.data();
    GL_ASSERT(begin <= end && end <= list.size() && list.second.size() == list.size(),
              "bucket inside the list");
    GL_ASSERT(!trialHistory || list.xiTrial.size() == list.size(), "trial springs allocated");
    GL_ASSERT(!kRolling || (trialHistory ? list.zetaTrial : list.zeta).size() == list.size(),
              "rolling history allocated");
    std::uint64_t contacts = 0;
    Real maxRel = stats.maxRelativeOverlap;
    for (std::uint32_t p = begin; p < end; ++p) {
        const std::uint32_t i = pi[p], j = pj[p];
        GL_ASSERT(i < s.size() && j < s.size(), "pair slots in range");
        const Real dx = x[j] - x[i], dy = y[j] - y[i];
        const Real ri = rad[i], rj = rad[j];
        const Real rsum = ri + rj;
        const Real r2 = dx * dx + dy * dy;
        if (r2 >= rsum * rsum) {
            xiHist[p] = 0;
            if (rolling) zetaHist[p] = 0;
            if constexpr (kCross) deferred[p - crossBegin] = {0, 0, 0};
            continue;
        }
        ++contacts;
        const Real r = std::sqrt(r2);
        const Real invR = r > 0 ? 1.0 / r : 0.0;
        const Real nx = r > 0 ? dx * invR : 1.0, ny = r > 0 ? dy * invR : 0.0;
        const Real overlap = rsum - r;
        if (overlapGuard > 0 &&
            overlap > overlapGuard * (ri < rj ? ri : rj)) {  // seed's guard, off by default
            ++stats.guardSkips;  // history kept as it is; the overlap still counts for the diagnosis
            const Real rel = overlap / (ri < rj ? ri : rj);
            maxRel = rel > maxRel ? rel : maxRel;
            if constexpr (kCross) deferred[p - crossBegin] = {0, 0, 0};
            continue;
        }
        // Relative velocity of i's contact point w.r.t. j's: v_i - v_j + (w_i r_i + w_j r_j) perp(n).
        const Real wsum = om[i] * ri + om[j] * rj;
        const Real vrx = vx[i] - vx[j] - wsum * ny;
        const Real vry = vy[i] - vy[j] + wsum * nx;
        const Real mi = mass[i], mj = mass[j];
        ContactKinematics k;
        k.overlap = overlap;
        k.vn = vrx * nx + vry * ny;
        k.vt = -vrx * ny + vry * nx;
        k.meff = mi * mj / (mi + mj);
        // R_eff costs a division: only for laws that use it (kUsesReff: Hertz, Mindlin) and rolling.
        constexpr bool kLawUsesReff = lawUsesReff<N>() || lawUsesReff<D>() || lawUsesReff<T>();
        k.reff = (kLawUsesReff || rolling) ? ri * rj / rsum : 0.0;
        k.dxt = 0;
        if (!std::is_same_v<T, NoFriction> || rolling)
            if (drift.vx) k.dxt = tangentialIncrement(drift, i, j, ri, rj, nx, ny, dt);
        k.vroll = 0;
        k.dxroll = 0;
        Real zeta = 0;
        if (rolling) {  // cfddem Eq. 3.58 along t
            const Real sizeTerm = 0.5 * (rj - ri) / rsum;
            k.vroll = -k.reff * (om[i] - om[j]) - sizeTerm * k.vt;
            if (drift.vx) k.dxroll = -k.reff * (drift.omega[i] - drift.omega[j]) * dt - sizeTerm * k.dxt;
            zeta = zetaHist[p];
        }
        const auto law = resolve<N, D, T>(table[static_cast<std::size_t>(mat[i]) * nm + mat[j]]);
        const ContactForce f = evaluateContact<N, D, T, kRolling>(law, k, xiHist[p], zeta);
        if constexpr (kRolling) {
            zetaHist[p] = zeta;
            tq[i] += f.rollingTorque;
            if constexpr (!kCross) tq[j] -= f.rollingTorque;
        }
        // Force on i: -fn n + ft t.
        const Real fxi = -f.fn * nx - f.ft * ny;
        const Real fyi = -f.fn * ny + f.ft * nx;
        fx[i] += fxi;
        fy[i] += fyi;
        tq[i] += ri * f.ft;  // arm r_i n, force component ft along perp(n)
        if constexpr (kCross) {
            deferred[p - crossBegin] = {-fxi, -fyi, kRolling ? rj * f.ft - f.rollingTorque : rj * f.ft};
        } else {
            fx[j] -= fxi;
            fy[j] -= fyi;
            tq[j] += rj * f.ft;
        }
        if constexpr (kLog)
            log->addDiskPair(s.id[i], s.id[j], {x[i], y[i]}, ri, {x[j], y[j]}, rj, {nx, ny}, {fxi, fyi});
        // Largest overlap / min(r_i, r_j): the division only for a new largest (rarely taken).
        const Real rmin = ri < rj ? ri : rj;
        if (overlap > maxRel * rmin) [[unlikely]] {
            const Real rel = overlap / rmin;
            maxRel = rel > maxRel ? rel : maxRel;
        }
    }
    stats.contacts += contacts;
    stats.maxRelativeOverlap = maxRel;
}

/// Disk-wall contacts of one bucket. n points from the wall to the disk centre.
template <class N, class D, class T>
void diskWalls(model::ParticleStore& s, const model::WallSet& walls, ContactList& list, std::uint32_t begin,
               std::uint32_t end, const LawTable& laws, const DriftVelocities& drift, Real dt,
               bool trialHistory, ForceStats& stats, Vec2* wallForce, ContactLog* log) noexcept {
    const std::uint32_t nm = laws.materialCount();
    const ContactLaw* table = laws.laws().data();
    GL_ASSERT(begin <= end && end <= list.size() && list.second.size() == list.size(),
              "bucket inside the list");
    GL_ASSERT(!trialHistory || list.xiTrial.size() == list.size(), "trial springs allocated");
    std::uint64_t contacts = 0;
    for (std::uint32_t p = begin; p < end; ++p) {
        const std::uint32_t i = list.first[p];
        GL_ASSERT(i < s.size() && list.second[p] < walls.segments.size(), "slot and segment in range");
        const auto& seg = walls.segments[list.second[p]];
        const model::Wall& wall = walls.walls[seg.wall];
        const Vec2 c{s.x[i], s.y[i]};
        const Real r = s.radius[i];
        const auto g = wallContact(walls, seg, c, r);
        Real* xiHist = trialHistory ? list.xiTrial.data() : list.xi.data();
        const bool rolling = laws.hasRolling();
        Real* zetaHist = trialHistory ? list.zetaTrial.data() : list.zeta.data();
        if (!g.touching || g.overlap <= 0) {
            xiHist[p] = 0;
            if (rolling) zetaHist[p] = 0;
            continue;
        }
        ++contacts;
        const Vec2 n = g.normal;
        // Wall point velocity at the contact, plus the belt's tangential surface velocity (gc2d 6.1).
        const Vec2 wallVel =
            walls.velocityAt(seg.wall, g.point) + perp(n) * dot(wall.surfaceVelocity, perp(n));
        // Contact point at -r n from the centre: v_c = v - w r perp(n).
        const Real w = s.omega[i] * r;
        const Vec2 vrel{s.vx[i] + w * n.y - wallVel.x, s.vy[i] - w * n.x - wallVel.y};
        ContactKinematics k;
        k.overlap = g.overlap;
        k.vn = -dot(vrel, n);
        k.vt = dot(vrel, perp(n));
        k.meff = s.mass[i];
        k.reff = r;
        k.dxt = 0;
        if (!std::is_same_v<T, NoFriction> || rolling) {
            if (drift.vx) {
                const Real wh = drift.omega[i] * r;
                const Vec2 vh{drift.vx[i] + wh * n.y - wallVel.x, drift.vy[i] - wh * n.x - wallVel.y};
                k.dxt = dot(vh, perp(n)) * dt;
            }
        }
        k.vroll = 0;
        k.dxroll = 0;
        Real zeta = 0;
        if (rolling) {  // Eq. 3.58 with R_wall -> infinity, in the pair frame of the disk
            k.vroll = -r * s.omega[i] + 0.5 * k.vt;
            if (drift.vx) k.dxroll = -r * drift.omega[i] * dt + 0.5 * k.dxt;
            zeta = zetaHist[p];
        }
        const auto law = resolve<N, D, T>(table[static_cast<std::size_t>(s.material[i]) * nm + seg.material]);
        const ContactForce f = evaluateContact(law, k, xiHist[p], zeta);
        if (rolling) {
            zetaHist[p] = zeta;
            s.torque[i] += f.rollingTorque;
        }
        const Real fxi = f.fn * n.x - f.ft * n.y;
        const Real fyi = f.fn * n.y + f.ft * n.x;
        s.fx[i] += fxi;
        s.fy[i] += fyi;
        s.torque[i] -= r * f.ft;  // arm -r n
        wallForce[seg.wall] -= Vec2{fxi, fyi};
        if (log)
            log->addDiskWall(s.id[i], static_cast<std::int32_t>(seg.wall), c, r, g.overlap, -n, {fxi, fyi});
        stats.maxRelativeOverlap = std::max(stats.maxRelativeOverlap, g.overlap / r);
    }
    stats.wallContacts += contacts;
}

}  // namespace
}  // namespace granulab::dem::detail
