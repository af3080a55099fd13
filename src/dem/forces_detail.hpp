// SPDX-License-Identifier: MIT
// Helpers shared by the force kernels and the contact energy (internal to dem/): the one dispatch
// per bucket of pairs (std::visit over the law form, DESIGN.md "Contact laws"), the resolved law
// of a material pair, the form traits and the contact-point velocities. Included by .cpp files of
// dem/ only.
#pragma once
#include <cstdint>
#include <type_traits>
#include <utility>
#include <variant>

#include "core/error.hpp"
#include "dem/contact/kernel.hpp"
#include "dem/forces.hpp"
#include "geom/segment.hpp"

namespace granulab::dem::detail {
// Internal linkage (an unnamed namespace), as when these functions lived in one .cpp: GCC inlines
// a kernel called once only where no other translation unit can call it.
namespace {

/// The law of one material pair with the alternatives of its bucket's form known at compile time.
template <class N, class D, class T>
ResolvedLaw<N, D, T> resolve(const ContactLaw& law) noexcept {
    return {*std::get_if<N>(&law.normal), *std::get_if<D>(&law.damping), *std::get_if<T>(&law.tangential),
            law.clipAttraction, rollingSettings(law.rolling)};
}

/// Visits the form of a bucket with its concrete axis types.
template <class Fn>
void visitForm(const ContactLaw& rep, Fn&& fn) {
    std::visit(
        [&](const auto& n, const auto& d, const auto& t) {
            using N = std::decay_t<decltype(n)>;
            using D = std::decay_t<decltype(d)>;
            using T = std::decay_t<decltype(t)>;
            fn(static_cast<N*>(nullptr), static_cast<D*>(nullptr), static_cast<T*>(nullptr));
        },
        rep.normal, rep.damping, rep.tangential);
}

/// Calls fn(N*, D*, T*, begin, end) for every non-empty bucket in [firstBucket, endBucket) of
/// `list` with the concrete axis types of the bucket's law form (bucket mod forms): the one
/// dispatch per bucket.
template <class Fn>
void forEachBucketIn(const ContactList& list, const LawTable& laws, std::uint32_t firstBucket,
                     std::uint32_t endBucket, Fn&& fn) {
    const std::uint32_t forms = laws.formCount() > 0 ? laws.formCount() : 1;
    GL_ASSERT(list.bucketStart.empty() || (list.bucketStart.size() - 1) % (2 * forms) == 0,
              "tiles x 2 x forms buckets");
    GL_ASSERT(list.bucketStart.empty() || list.bucketStart.back() == list.size(), "buckets cover the list");
    GL_ASSERT(endBucket < list.bucketStart.size() || firstBucket == endBucket, "buckets inside the list");
    for (std::uint32_t k = firstBucket; k < endBucket; ++k) {
        const auto b = list.bucketStart[k], e = list.bucketStart[k + 1];
        if (b == e) continue;
        GL_ASSERT(b < e, "bucket offsets ascending");
        visitForm(laws.formRepresentative(k % forms),
                  [&](auto* nT, auto* dT, auto* tT) { fn(nT, dT, tT, b, e); });
    }
}

/// forEachBucketIn over all buckets of `list`.
template <class Fn>
void forEachBucket(const ContactList& list, const LawTable& laws, Fn&& fn) {
    if (list.bucketStart.size() < 2) return;
    forEachBucketIn(list, laws, 0, static_cast<std::uint32_t>(list.bucketStart.size() - 1),
                    std::forward<Fn>(fn));
}

template <class D>
constexpr bool kAreaDamping = std::is_same_v<D, NoDamping> || std::is_same_v<D, AreaDamping>;
template <class T>
constexpr bool kAreaTangential = std::is_same_v<T, NoFriction> || std::is_same_v<T, AreaFriction>;
/// True for the normal laws of the area kernel: gc2d's E A / l and the energy-conserving potential.
template <class N>
constexpr bool kAreaNormal = std::is_same_v<N, AreaNormal> || std::is_same_v<N, AreaPotentialNormal>;
/// True for the law forms of the overlap-depth kernels (disks only).
template <class N, class D, class T>
constexpr bool kDepthForm =
    !kAreaNormal<N> && !std::is_same_v<D, AreaDamping> && !std::is_same_v<T, AreaFriction>;
/// True for the forms of the gc2d area kernel (validation rejects mixed forms).
template <class N, class D, class T>
constexpr bool kAreaForm = kAreaNormal<N>&& kAreaDamping<D>&& kAreaTangential<T>;

/// Tangential displacement [m] of the contact points of the disks i and j during the step, from
/// the drift velocities; n points from i to j.
[[gnu::always_inline]] inline Real tangentialIncrement(const DriftVelocities& d, std::uint32_t i,
                                                       std::uint32_t j, Real ri, Real rj, Real nx, Real ny,
                                                       Real dt) noexcept {
    const Real wsum = d.omega[i] * ri + d.omega[j] * rj;
    const Real vrx = d.vx[i] - d.vx[j] - wsum * ny;
    const Real vry = d.vy[i] - d.vy[j] + wsum * nx;
    return (-vrx * ny + vry * nx) * dt;
}

/// Velocity of the material point of slot i at lever arm r, v + omega z x r (actual or drift
/// velocities, whichever columns are passed) [m/s].
inline Vec2 pointVelocity(const Real* vx, const Real* vy, const Real* om, std::uint32_t i, Vec2 r) noexcept {
    return Vec2{vx[i], vy[i]} + perp(r) * om[i];
}

/// Geometry of a disk against the wall of `seg`: the whole convex body for a body wall (the list
/// holds one pair per body), the segment otherwise; nothing for a wall that is not solid (yet).
inline geom::SegmentContact wallContact(const model::WallSet& walls, const model::WallSegment& seg, Vec2 c,
                                        Real r) noexcept {
    const model::Wall& wall = walls.walls[seg.wall];
    if (!wall.solid) return {};
    if (wall.body)
        return geom::diskConvexContact(c, r, walls.corners.data() + wall.firstSegment,
                                       static_cast<int>(wall.segmentCount));
    return geom::diskSegmentContact(c, r, seg.a, seg.b, seg.startShared, seg.endShared, seg.prevDirection);
}

}  // namespace
}  // namespace granulab::dem::detail
