// SPDX-License-Identifier: MIT
// Neighbour-list rebuild with history transfer, and the updates for removed and inserted particles.
#include "dem/neighbor_list.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"
#include "geom/segment.hpp"

namespace granulab::dem {

bool NeighborList::needsRebuild(const model::ParticleStore& s, Real skin, Real wallTravel, int threads,
                                const std::vector<std::uint32_t>* cuts) const noexcept {
    if (x0.size() != s.size()) return true;
    const Real half = 0.5 * skin - wallTravel;
    if (half <= 0) return true;
    const Real limit2 = half * half;
    const Real max2 = parallelMax(threads, cuts, s.size(), [&](std::size_t begin, std::size_t end) {
        const Real* __restrict x = s.x.data();
        const Real* __restrict y = s.y.data();
        const Real* __restrict px = x0.data();
        const Real* __restrict py = y0.data();
        Real m = 0;
        Real nanSeen = 0;  // a double flag: an int flag kept the loop scalar (GCC 12)
        // The pragma lets the max reduction vectorize (exact in any order; NaN is tracked apart).
#pragma omp simd reduction(max : m) reduction(max : nanSeen)
        for (std::size_t i = begin; i < end; ++i) {
            const Real dx = x[i] - px[i], dy = y[i] - py[i];
            const Real d2 = dx * dx + dy * dy;
            m = d2 > m ? d2 : m;
            nanSeen = d2 == d2 ? nanSeen : 1.0;
        }
        return nanSeen > 0 ? std::numeric_limits<Real>::quiet_NaN() : m;
    });
    return !(max2 <= limit2);  // NaN-safe: a non-finite position forces a rebuild
}

namespace {

/// The non-empty history of `list`, keys mapped through oldToNew (empty: kept), sorted by key.
std::vector<PairHistory> collectHistory(const ContactList& list, const std::vector<std::uint32_t>& oldToNew,
                                        bool bothAreSlots) {
    std::vector<PairHistory> out = NeighborList::historyOf(list);
    if (!oldToNew.empty())
        for (PairHistory& h : out) {
            std::uint32_t a = oldToNew[keyFirst(h.key)], b = keySecond(h.key);
            if (bothAreSlots) {
                b = oldToNew[b];
                if (a > b) {
                    std::swap(a, b);
                    exchangeBodies(h.zeta, h.features);
                }
            }
            h.key = pairKey(a, b);
        }
    std::sort(out.begin(), out.end());
    return out;
}

/// Where a list entry goes: its tile (that of its first slot), inner or cross (a particle pair
/// whose second slot lies in another tile), and its law form.
struct Layout {
    const NeighborList& list;
    SlotTiles tiles;
    bool particlePairs;
    std::uint32_t bucketCount() const noexcept { return list.bucket(tiles.count, false, 0); }
    std::uint32_t bucketOf(std::uint32_t first, std::uint32_t second, std::uint32_t form) const noexcept {
        const std::uint32_t t = tiles.tileOf(first);
        return list.bucket(t, particlePairs && tiles.tileOf(second) != t, form);
    }
};

/// Stable counting sort: the position of entry k once the entries are grouped by bucketOf[k]
/// (kRemovedSlot: dropped, position kRemovedSlot), keeping their order inside a bucket; `start`
/// receives the buckets + 1 offsets.
std::vector<std::uint32_t> placeInBuckets(const std::vector<std::uint32_t>& bucketOf, std::uint32_t buckets,
                                          std::vector<std::uint32_t>& start) {
    start.assign(buckets + std::size_t{1}, 0);
    for (const std::uint32_t b : bucketOf)
        if (b != kRemovedSlot) ++start[b + 1];
    for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    std::vector<std::uint32_t> pos(bucketOf.size(), kRemovedSlot);
    for (std::size_t k = 0; k < bucketOf.size(); ++k)
        if (bucketOf[k] != kRemovedSlot) pos[k] = fill[bucketOf[k]]++;
    return pos;
}

/// Sorted keys grouped into the buckets of `layout` (stable: (first, second) order inside a
/// bucket), with their history restored from `old`.
template <class MaterialOfSecond>
void fillList(ContactList& list, const std::vector<std::uint64_t>& keys, const std::vector<PairHistory>& old,
              const model::ParticleStore& s, const LawTable& laws, const Layout& layout, bool trialHistory,
              int threads, MaterialOfSecond materialOfSecond) {
    std::vector<std::uint32_t> bucketOf(keys.size());
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const std::uint32_t a = keyFirst(keys[k]), b = keySecond(keys[k]);
        const std::uint32_t f = laws.formCount() ? laws.formOf(s.material[a], materialOfSecond(b)) : 0;
        bucketOf[k] = layout.bucketOf(a, b, f);
    }
    const std::vector<std::uint32_t> pos = placeInBuckets(bucketOf, layout.bucketCount(), list.bucketStart);
    list.first.resize(keys.size());
    list.second.resize(keys.size());
    list.xi.assign(keys.size(), 0.0);
    if (!list.xiTrial.empty() || trialHistory) list.xiTrial.assign(keys.size(), 0.0);
    const bool rolling = laws.hasRolling();
    list.zeta.assign(rolling ? keys.size() : 0, 0.0);
    list.zetaTrial.assign(rolling && trialHistory ? keys.size() : 0, 0.0);
    const bool area = laws.hasArea();
    list.areaOld.assign(area ? keys.size() : 0, 0.0);
    list.areaOldTrial.assign(area && trialHistory ? keys.size() : 0, 0.0);
    list.features.assign(area ? keys.size() : 0, geom::FeatureCache{});
    parallelBlocks(threads, keys.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t p = pos[k];
            list.first[p] = keyFirst(keys[k]);
            list.second[p] = keySecond(keys[k]);
            auto it = std::lower_bound(old.begin(), old.end(), PairHistory{keys[k], 0, 0, 0, {}});
            if (it != old.end() && it->key == keys[k]) {
                list.xi[p] = it->xi;
                if (rolling) list.zeta[p] = it->zeta;
                if (area) {
                    list.areaOld[p] = it->areaOld;
                    list.features[p] = it->features;
                }
            }
        }
    });
}

/// Bucket of every entry of `l` (tiles x 2 x forms buckets, form = bucket mod forms).
std::vector<std::uint32_t> bucketsOfEntries(const ContactList& l) {
    std::vector<std::uint32_t> bucketOf(l.size(), 0);
    for (std::uint32_t b = 0; b + 1 < l.bucketStart.size(); ++b)
        for (std::uint32_t k = l.bucketStart[b]; k < l.bucketStart[b + 1]; ++k) bucketOf[k] = b;
    return bucketOf;
}

/// Entry k of every per-pair column of `l` (columns may be empty) moves to bucket bucketOf[k]
/// (kRemovedSlot: dropped), keeping the order of the entries inside a bucket.
void regroup(ContactList& l, const std::vector<std::uint32_t>& bucketOf, std::uint32_t buckets) {
    const std::size_t n = l.size();
    std::vector<std::uint32_t> start;
    const std::vector<std::uint32_t> dest = placeInBuckets(bucketOf, buckets, start);
    const std::size_t kept = start.back();
    const auto move = [&](auto& col) {
        if (col.size() != n) return;
        std::remove_reference_t<decltype(col)> out(kept);
        for (std::size_t k = 0; k < n; ++k)
            if (dest[k] != kRemovedSlot) out[dest[k]] = col[k];
        col.swap(out);
    };
    move(l.first);
    move(l.second);
    move(l.xi);
    move(l.xiTrial);
    move(l.zeta);
    move(l.zetaTrial);
    move(l.areaOld);
    move(l.areaOldTrial);
    move(l.features);
    l.bucketStart = std::move(start);
}

}  // namespace

namespace {
/// The segment a particle-wall pair is keyed by: a convex body wall is one contact per particle,
/// keyed by the body's first segment (gc2d spec 6.1); a polyline segment is its own.
std::uint32_t pairSegment(const model::WallSet& walls, std::uint32_t seg) noexcept {
    const auto& wall = walls.walls[walls.segments[seg].wall];
    return wall.body ? wall.firstSegment : seg;
}

}  // namespace

void NeighborList::removeSlots(const std::vector<std::uint32_t>& oldToNew) {
    std::size_t kept = 0;
    for (const std::uint32_t k : oldToNew) kept += k != kRemovedSlot ? 1 : 0;
    const SlotTiles newTiles = SlotTiles::forParticles(kept, minTileSlots);
    for (auto* l : {&pairs, &wallPairs}) {
        const bool both = l == &pairs;
        const Layout layout{*this, newTiles, both};
        std::vector<std::uint32_t> bucketOf = bucketsOfEntries(*l);
        for (std::size_t k = 0; k < l->size(); ++k) {
            const std::uint32_t a = oldToNew[l->first[k]];
            const std::uint32_t b = both ? oldToNew[l->second[k]] : l->second[k];
            if (a == kRemovedSlot || b == kRemovedSlot) {
                bucketOf[k] = kRemovedSlot;
                continue;
            }
            l->first[k] = a;
            l->second[k] = b;
            bucketOf[k] = layout.bucketOf(a, b, bucketOf[k] % forms);
        }
        regroup(*l, bucketOf, layout.bucketCount());
    }
    tiles = newTiles;
    std::size_t w = 0;
    for (std::size_t i = 0; i < oldToNew.size() && i < x0.size(); ++i)
        if (oldToNew[i] != kRemovedSlot) {
            x0[w] = x0[i];
            y0[w] = y0[i];
            ++w;
        }
    x0.resize(w);
    y0.resize(w);
    indexCrossPairs();
}

namespace {
/// Appends `added` (form, first, second) with empty history to `l` and regroups every entry by
/// `layout` (the new particles' entries at the end of their buckets).
void appendAndRegroup(ContactList& l, const std::vector<std::array<std::uint32_t, 3>>& added,
                      const Layout& layout, std::uint32_t forms, bool rolling, bool area, bool trialHistory) {
    std::vector<std::uint32_t> bucketOf = bucketsOfEntries(l);
    for (std::size_t k = 0; k < l.size(); ++k)
        bucketOf[k] = layout.bucketOf(l.first[k], l.second[k], bucketOf[k] % forms);
    const std::size_t m = l.size() + added.size();
    for (const auto& a : added) {
        l.first.push_back(a[1]);
        l.second.push_back(a[2]);
        bucketOf.push_back(layout.bucketOf(a[1], a[2], a[0]));
    }
    l.xi.resize(m, 0.0);
    if (rolling) l.zeta.resize(m, 0.0);
    if (area) {
        l.areaOld.resize(m, 0.0);
        l.features.resize(m, geom::FeatureCache{});
    }
    // Trial columns are scratch refreshed from the accepted ones at every evaluation.
    if (!l.xiTrial.empty() || trialHistory) l.xiTrial.resize(m, 0.0);
    if (!l.zetaTrial.empty()) l.zetaTrial.resize(m, 0.0);
    if (!l.areaOldTrial.empty()) l.areaOldTrial.resize(m, 0.0);
    regroup(l, bucketOf, layout.bucketCount());
}
}  // namespace

void NeighborList::appendParticles(const model::ParticleStore& s, const model::WallSet& walls,
                                   std::size_t first, Real skin, const LawTable& laws, bool trialHistory) {
    const auto formOf = [&](std::uint32_t ma, std::uint32_t mb) {
        return laws.formCount() ? laws.formOf(ma, mb) : 0u;
    };
    std::vector<std::array<std::uint32_t, 3>> pairAdds, wallAdds;
    const Real margin = 2 * skin;
    for (std::size_t k = first; k < s.size(); ++k) {
        const auto kk = static_cast<std::uint32_t>(k);
        for (std::uint32_t j = 0; j < kk; ++j) {  // j < k: the pair key (j, k)
            const Real reach = s.radius[j] + s.radius[k] + margin;
            const Real dx = s.x[j] - s.x[k], dy = s.y[j] - s.y[k];
            if (dx * dx + dy * dy < reach * reach)
                pairAdds.push_back({formOf(s.material[j], s.material[k]), j, kk});
        }
        std::uint32_t lastKey = 0xFFFFFFFFu;  // a body's segments are consecutive: one pair per body
        for (std::uint32_t g = 0; g < walls.segments.size(); ++g) {
            const auto& seg = walls.segments[g];
            const Vec2 c{s.x[k], s.y[k]};
            const Vec2 q = seg.a + (seg.b - seg.a) * geom::closestParameter(seg.a, seg.b, c);
            const Real reach = s.radius[k] + margin;
            const std::uint32_t key = pairSegment(walls, g);
            if (norm2(c - q) >= reach * reach || key == lastKey) continue;
            lastKey = key;
            wallAdds.push_back({formOf(s.material[k], seg.material), kk, key});
        }
    }
    const SlotTiles newTiles = SlotTiles::forParticles(s.size(), minTileSlots);
    appendAndRegroup(pairs, pairAdds, Layout{*this, newTiles, true}, forms, laws.hasRolling(), laws.hasArea(),
                     trialHistory);
    appendAndRegroup(wallPairs, wallAdds, Layout{*this, newTiles, false}, forms, laws.hasRolling(),
                     laws.hasArea(), trialHistory);
    tiles = newTiles;
    for (std::size_t k = first; k < s.size(); ++k) {
        x0.push_back(s.x[k]);
        y0.push_back(s.y[k]);
    }
    indexCrossPairs();
}

void NeighborList::rebuild(const model::ParticleStore& s, const model::WallSet& walls, Real skin, Real time,
                           BroadPhase& broad, const LawTable& laws,
                           const std::vector<std::uint32_t>& oldToNew, bool trialHistory, int threads) {
    rebuildWith(s, walls, skin, time, broad, laws, collectHistory(pairs, oldToNew, true),
                collectHistory(wallPairs, oldToNew, false), trialHistory, threads);
}

std::vector<PairHistory> NeighborList::historyOf(const ContactList& l) {
    std::vector<PairHistory> out;
    for (std::size_t k = 0; k < l.size(); ++k) {
        const PairHistory h{pairKey(l.first[k], l.second[k]), l.xi[k], l.zeta.empty() ? 0.0 : l.zeta[k],
                            l.areaOld.empty() ? 0.0 : l.areaOld[k],
                            l.features.empty() ? geom::FeatureCache{} : l.features[k]};
        if (!h.empty()) out.push_back(h);
    }
    return out;
}

void NeighborList::rebuildWith(const model::ParticleStore& s, const model::WallSet& walls, Real skin,
                               Real time, BroadPhase& broad, const LawTable& laws,
                               const std::vector<PairHistory>& oldPairs,
                               const std::vector<PairHistory>& oldWall, bool trialHistory, int threads) {
    const auto dropGhosts = [&](std::vector<std::uint64_t>& keys) {  // keys sorted: first < second
        if (ownedEnd >= s.size()) return;
        keys.erase(std::remove_if(keys.begin(), keys.end(),
                                  [&](std::uint64_t key) { return keyFirst(key) >= ownedEnd; }),
                   keys.end());
    };
    tiles = SlotTiles::forParticles(s.size(), minTileSlots);
    forms = std::max<std::uint32_t>(laws.formCount(), 1);
    std::vector<std::uint64_t> keys;
    broad.findPairs(s, skin, keys);
    dropGhosts(keys);
    fillList(pairs, keys, oldPairs, s, laws, Layout{*this, tiles, true}, trialHistory, threads,
             [&](std::uint32_t j) { return s.material[j]; });
    broad.findWallPairs(s, walls, skin, keys);
    // A body wall's segment candidates become one pair per particle (pairSegment).
    bool anyBody = false;
    for (auto& key : keys) {
        const std::uint32_t seg = pairSegment(walls, keySecond(key));
        anyBody = anyBody || seg != keySecond(key);
        key = pairKey(keyFirst(key), seg);
    }
    if (anyBody) {
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    }
    dropGhosts(keys);
    fillList(wallPairs, keys, oldWall, s, laws, Layout{*this, tiles, false}, trialHistory, threads,
             [&](std::uint32_t seg) { return walls.segments[seg].material; });
    x0 = s.x;
    y0 = s.y;
    wallTime0 = time;
    ++builds;
    indexCrossPairs();
}

bool NeighborList::restoreLayout(std::size_t particles, const LawTable& laws) {
    tiles = SlotTiles::forParticles(particles, minTileSlots);
    forms = std::max<std::uint32_t>(laws.formCount(), 1);
    const std::size_t offsets = bucket(tiles.count, false, 0) + std::size_t{1};
    for (const ContactList* l : {&pairs, &wallPairs}) {
        if (l->bucketStart.size() != offsets || l->bucketStart.front() != 0 ||
            l->bucketStart.back() != l->size() ||
            !std::is_sorted(l->bucketStart.begin(), l->bucketStart.end()))
            return false;
        for (std::uint32_t t = 0; t < tiles.count; ++t)
            for (std::uint32_t k = tileBegin(*l, t); k < tileBegin(*l, t + 1); ++k) {
                const std::uint32_t a = l->first[k], b = l->second[k];
                const bool cross = k >= l->bucketStart[bucket(t, true, 0)];
                if (tiles.tileOf(a) != t || (l == &pairs && (a >= b || cross != (tiles.tileOf(b) != t))) ||
                    (l == &wallPairs && cross))
                    return false;
            }
    }
    indexCrossPairs();
    return true;
}

void NeighborList::indexCrossPairs() {
    const std::uint32_t count = tiles.count;
    crossBase.assign(count + std::size_t{1}, 0);
    gatherStart.assign(count + std::size_t{1}, 0);
    for (std::uint32_t t = 0; t < count; ++t) {
        crossBase[t + 1] = crossBase[t] + (tileBegin(pairs, t + 1) - crossBegin(t));
        for (std::uint32_t p = crossBegin(t); p < tileBegin(pairs, t + 1); ++p)
            ++gatherStart[tiles.tileOf(pairs.second[p]) + 1];
    }
    for (std::uint32_t t = 0; t < count; ++t) gatherStart[t + 1] += gatherStart[t];
    gatherFrom.resize(crossPairs());
    gatherSlot.resize(crossPairs());
    std::vector<std::uint32_t> fill(gatherStart.begin(), gatherStart.end() - 1);
    for (std::uint32_t t = 0; t < count; ++t)
        for (std::uint32_t p = crossBegin(t); p < tileBegin(pairs, t + 1); ++p) {
            const std::uint32_t j = pairs.second[p];
            const std::uint32_t e = fill[tiles.tileOf(j)]++;
            gatherFrom[e] = crossBase[t] + (p - crossBegin(t));
            gatherSlot[e] = j;
        }
}

}  // namespace granulab::dem
