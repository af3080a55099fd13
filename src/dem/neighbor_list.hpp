// SPDX-License-Identifier: MIT
// Verlet neighbour list with skin and per-pair contact history (DESIGN.md stages 3 and 5).
// Candidate pairs are kept between rebuilds; history (the tangential spring) lives beside each
// pair and is carried over at a rebuild by key, so contacts persist across rebuilds and slot
// reorders. Pairs are bucketed by law form and sorted by (first, second) inside a bucket, which
// fixes the force summation order (deterministic).
#pragma once
#include <cstdint>
#include <vector>

#include "dem/broad_phase.hpp"
#include "dem/law_table.hpp"
#include "geom/convex_contact.hpp"
#include "model/particle_store.hpp"
#include "model/walls.hpp"

namespace granulab::dem {

struct ContactList {
    std::vector<std::uint32_t> first, second;  ///< slots (pairs) or slot + segment (walls)
    std::vector<Real> xi;                      ///< [m] tangential spring, along t = perp(n) (accepted)
    std::vector<Real> xiTrial;                 ///< [m] trial springs of an iterating integrator
    std::vector<Real> zeta, zetaTrial;         ///< [m] rolling displacement (only with rolling laws)
    // gc2d area contacts only (empty otherwise):
    std::vector<Real> areaOld, areaOldTrial;   ///< [m^2] overlap area of the last step (Old_Area, Eq. 2.22)
    std::vector<geom::FeatureCache> features;  ///< closest features / crossings of the last evaluation
    std::vector<std::uint32_t> bucketStart;    ///< formCount + 1 offsets

    /// Accepts the trial springs of the step (iterating integrators only).
    void commitHistory() noexcept {
        xi.swap(xiTrial);
        zeta.swap(zetaTrial);
        areaOld.swap(areaOldTrial);
    }

    std::size_t size() const noexcept { return first.size(); }
    std::size_t memoryBytes() const noexcept {
        return first.capacity() * 4 + second.capacity() * 4 +
               (xi.capacity() + xiTrial.capacity() + zeta.capacity() + zetaTrial.capacity() +
                areaOld.capacity() + areaOldTrial.capacity()) *
                   sizeof(Real) +
               features.capacity() * sizeof(geom::FeatureCache) + bucketStart.capacity() * 4;
    }
};

/// oldToNew entry of a removed particle.
inline constexpr std::uint32_t kRemovedSlot = 0xFFFFFFFFu;

class NeighborList {
public:
    ContactList pairs;         ///< particle-particle candidates
    ContactList wallPairs;     ///< particle-segment candidates
    std::vector<Real> x0, y0;  ///< [m] positions at the last rebuild
    Real wallTime0 = 0;        ///< [s] time of the last rebuild (for wall motion)
    std::uint64_t builds = 0;

    /// True if some particle may have moved into range since the last rebuild: the largest
    /// displacement plus the wall travel exceeds skin/2 (or is not finite).
    bool needsRebuild(const model::ParticleStore& s, Real skin, Real wallTravel) const noexcept;
    void commitHistory() noexcept {
        pairs.commitHistory();
        wallPairs.commitHistory();
    }

    /// Rebuilds both lists. `oldToNew` (may be empty) maps old slots to new ones when the store
    /// was just permuted, so that history follows its particles (removal: removeSlots).
    /// `trialHistory` allocates trial springs for integrators with several force evaluations.
    void rebuild(const model::ParticleStore& s, const model::WallSet& walls, Real skin, Real time,
                 BroadPhase& broad, const LawTable& laws, const std::vector<std::uint32_t>& oldToNew,
                 bool trialHistory);

    std::size_t memoryBytes() const noexcept {
        return pairs.memoryBytes() + wallPairs.memoryBytes() + (x0.capacity() + y0.capacity()) * sizeof(Real);
    }
    /// Particles were removed (ParticleStore::keep): drops their candidates and renumbers the
    /// others through `oldToNew` (kRemovedSlot: removed). The renumbering keeps the slot order,
    /// so buckets stay sorted and the history stays with its pairs; no broad phase is needed.
    void removeSlots(const std::vector<std::uint32_t>& oldToNew);
    /// Particles were appended from slot `first` on: adds their candidates (particles and wall
    /// segments within r + r' + 2 skin, so that the skin guarantee holds until the next rebuild
    /// although the others have moved since theirs) at the end of their law-form buckets, with
    /// empty history; no broad phase. O(N) per new particle.
    void appendParticles(const model::ParticleStore& s, const model::WallSet& walls, std::size_t first,
                         Real skin, const LawTable& laws, bool trialHistory);
};

}  // namespace granulab::dem
