// SPDX-License-Identifier: MIT
// Verlet neighbour list with skin and per-pair contact history (DESIGN.md stages 3 and 5).
// Candidate pairs are kept between rebuilds; history (the tangential spring) lives beside each
// pair and is carried over at a rebuild by key, so contacts persist across rebuilds and slot
// reorders. Pairs are grouped by slot tile (dem/slot_tiles.hpp: the tile of the first slot), then
// inner / cross (the second slot in the same tile or another), then law form, and sorted by
// (first, second) inside a bucket. That fixes the force summation order for any thread count:
// a tile's pairs add to its own grains directly; a cross pair's share for its second grain is
// deferred and gathered by that grain's tile in a fixed order (docs/physics/dem-threads.md).
#pragma once
#include <cstdint>
#include <vector>

#include "dem/broad_phase.hpp"
#include "dem/law_table.hpp"
#include "dem/slot_tiles.hpp"
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
    /// Offsets of the buckets, (tile, cross, form) in that order: bucket (2 t + cross) F + f of
    /// NeighborList::bucket; tiles x 2 x forms + 1 entries (the wall list has no cross buckets
    /// filled: its second is a segment).
    std::vector<std::uint32_t> bucketStart;

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

/// The history of one list entry, keyed by pairKey(first, second) (slots; first < second for a
/// particle pair, slot and segment for a wall pair): what a rebuild carries over.
struct PairHistory {
    std::uint64_t key = 0;
    Real xi = 0;       ///< [m] tangential spring
    Real zeta = 0;     ///< [m] rolling displacement (flips sign when the bodies are exchanged)
    Real areaOld = 0;  ///< [m^2]
    geom::FeatureCache features;
    bool operator<(const PairHistory& o) const noexcept { return key < o.key; }
    /// True when nothing is remembered (a pair that has not touched yet).
    bool empty() const noexcept {
        return xi == 0 && zeta == 0 && areaOld == 0 && features.state == geom::FeatureCache::Cold;
    }
};

/// The history of a pair whose two bodies exchange roles (first <-> second): exchanging them flips
/// n and t and the relative velocity, so v_t and the tangential spring xi are unchanged
/// (forces.cpp: v_t = (v_i - v_j + ...) . t), while the rolling velocity (omega_i - omega_j,
/// R_j - R_i) and hence zeta flip sign, and the closest features swap their roles.
inline void exchangeBodies(Real& zeta, geom::FeatureCache& features) noexcept {
    zeta = -zeta;
    features = features.swapped();
}

class NeighborList {
public:
    ContactList pairs;         ///< particle-particle candidates
    ContactList wallPairs;     ///< particle-segment candidates
    std::vector<Real> x0, y0;  ///< [m] positions at the last rebuild
    Real wallTime0 = 0;        ///< [s] time of the last rebuild (for wall motion)
    std::uint64_t builds = 0;
    SlotTiles tiles;          ///< the tiles of the particle count at the last change of the lists
    std::uint32_t forms = 1;  ///< law forms of the buckets (at least 1)
    /// Fewest slots per tile (SlotTiles::forParticles); tests set it to compare tilings.
    std::uint32_t minTileSlots = SlotTiles::kMinSlots;
    /// Slots from ownedEnd on are ghosts of a domain decomposition (dem/parallel/): a rebuild
    /// keeps no pair of two ghosts and no wall pair of a ghost, since their forces are not used.
    std::uint32_t ownedEnd = 0xFFFFFFFFu;
    /// Deferred forces: the cross pair p of tile t writes its second grain's share to entry
    /// crossBase[t] + (p - crossBegin(t)); tiles + 1 entries.
    std::vector<std::uint32_t> crossBase;
    /// Gathering them: tile t adds entries gatherFrom[k] to slots gatherSlot[k] for k in
    /// [gatherStart[t], gatherStart[t + 1]), in that order (by source tile, then pair).
    std::vector<std::uint32_t> gatherStart, gatherFrom, gatherSlot;

    std::uint32_t bucket(std::uint32_t tile, bool cross, std::uint32_t form) const noexcept {
        return (2 * tile + (cross ? 1u : 0u)) * forms + form;
    }
    /// First entry of tile t in `l` (t = tiles.count: the end of the list).
    std::uint32_t tileBegin(const ContactList& l, std::uint32_t tile) const noexcept {
        return l.bucketStart[bucket(tile, false, 0)];
    }
    /// First cross pair of tile t in `pairs`.
    std::uint32_t crossBegin(std::uint32_t tile) const noexcept {
        return pairs.bucketStart[bucket(tile, true, 0)];
    }
    /// Cross pairs in all tiles (entries of the deferred-force buffer).
    std::size_t crossPairs() const noexcept { return crossBase.empty() ? 0 : crossBase.back(); }

    /// True if some particle may have moved into range since the last rebuild: the largest
    /// displacement plus the wall travel exceeds skin/2 (or is not finite).
    /// `threads` and `cuts` as parallelSlots (the result does not depend on them).
    bool needsRebuild(const model::ParticleStore& s, Real skin, Real wallTravel, int threads = 1,
                      const std::vector<std::uint32_t>* cuts = nullptr) const noexcept;
    void commitHistory() noexcept {
        pairs.commitHistory();
        wallPairs.commitHistory();
    }

    /// Rebuilds both lists. `oldToNew` (may be empty) maps old slots to new ones when the store
    /// was just permuted, so that history follows its particles (removal: removeSlots).
    /// `trialHistory` allocates trial springs for integrators with several force evaluations.
    void rebuild(const model::ParticleStore& s, const model::WallSet& walls, Real skin, Real time,
                 BroadPhase& broad, const LawTable& laws, const std::vector<std::uint32_t>& oldToNew,
                 bool trialHistory, int threads = 1);
    /// Rebuilds both lists with the given history (sorted by key, in the slots of `s`; an entry
    /// whose pair is no longer a candidate is dropped).
    void rebuildWith(const model::ParticleStore& s, const model::WallSet& walls, Real skin, Real time,
                     BroadPhase& broad, const LawTable& laws, const std::vector<PairHistory>& pairHistory,
                     const std::vector<PairHistory>& wallHistory, bool trialHistory, int threads = 1);
    /// The non-empty history of `l` (pairs or wallPairs) in list order.
    static std::vector<PairHistory> historyOf(const ContactList& l);
    /// After the lists were read from a checkpoint: the tiles and forms of `particles` and `laws`,
    /// and the cross-pair index. False when the bucket offsets do not fit them (a damaged file).
    bool restoreLayout(std::size_t particles, const LawTable& laws);

    std::size_t memoryBytes() const noexcept {
        return pairs.memoryBytes() + wallPairs.memoryBytes() +
               (x0.capacity() + y0.capacity()) * sizeof(Real) +
               (crossBase.capacity() + gatherStart.capacity() + gatherFrom.capacity() +
                gatherSlot.capacity()) *
                   4;
    }
    /// Particles were removed (ParticleStore::keep): drops their candidates and renumbers the
    /// others through `oldToNew` (kRemovedSlot: removed), then regroups them by the tiles of the
    /// new count (the renumbering keeps the slot order, so buckets stay sorted and the history
    /// stays with its pairs); no broad phase is needed.
    void removeSlots(const std::vector<std::uint32_t>& oldToNew);
    /// Particles were appended from slot `first` on: adds their candidates (particles and wall
    /// segments within r + r' + 2 skin, so that the skin guarantee holds until the next rebuild
    /// although the others have moved since theirs) at the end of their buckets, with empty
    /// history, regrouped by the tiles of the new count; no broad phase. O(N) per new particle.
    void appendParticles(const model::ParticleStore& s, const model::WallSet& walls, std::size_t first,
                         Real skin, const LawTable& laws, bool trialHistory);

private:
    /// Rebuilds crossBase and the gather index from `pairs` and `tiles`.
    void indexCrossPairs();
};

}  // namespace granulab::dem
