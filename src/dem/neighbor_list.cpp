// SPDX-License-Identifier: MIT
// Neighbour-list rebuild with history transfer, and the updates for removed and inserted particles.
#include "dem/neighbor_list.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "geom/segment.hpp"

namespace granulab::dem {

bool NeighborList::needsRebuild(const model::ParticleStore& s, Real skin, Real wallTravel) const noexcept {
    if (x0.size() != s.size()) return true;
    const Real half = 0.5 * skin - wallTravel;
    if (half <= 0) return true;
    const Real limit2 = half * half;
    Real max2 = 0;
    const std::size_t n = s.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Real dx = s.x[i] - x0[i], dy = s.y[i] - y0[i];
        max2 = std::max(max2, dx * dx + dy * dy);
    }
    return !(max2 <= limit2);  // NaN-safe: a non-finite position forces a rebuild
}

namespace {

struct OldHistory {
    std::uint64_t key;
    Real xi;
    Real zeta;
    Real areaOld;
    geom::FeatureCache features;
    bool operator<(const OldHistory& o) const noexcept { return key < o.key; }
};

/// History entries of a list with a non-zero spring, keys mapped through oldToNew.
std::vector<OldHistory> collectHistory(const ContactList& list, const std::vector<std::uint32_t>& oldToNew,
                                       bool bothAreSlots) {
    std::vector<OldHistory> out;
    for (std::size_t k = 0; k < list.size(); ++k) {
        const Real xi = list.xi[k];
        Real zeta = list.zeta.empty() ? 0.0 : list.zeta[k];
        const Real areaOld = list.areaOld.empty() ? 0.0 : list.areaOld[k];
        geom::FeatureCache features = list.features.empty() ? geom::FeatureCache{} : list.features[k];
        if (xi == 0 && zeta == 0 && areaOld == 0 && features.state == geom::FeatureCache::Cold) continue;
        std::uint32_t a = list.first[k], b = list.second[k];
        if (!oldToNew.empty()) {
            a = oldToNew[a];
            if (bothAreSlots) {
                b = oldToNew[b];
                // Exchanging the bodies flips n and t and the relative velocity, so v_t and the
                // tangential spring xi are unchanged (forces.cpp: v_t = (v_i - v_j + ...) . t).
                // The rolling velocity (omega_i - omega_j, R_j - R_i) does flip sign.
                if (a > b) {
                    std::swap(a, b);
                    zeta = -zeta;
                    features = features.swapped();
                }
            }
        }
        out.push_back({pairKey(a, b), xi, zeta, areaOld, features});
    }
    std::sort(out.begin(), out.end());
    return out;
}

/// Buckets sorted keys by law form and restores history.
template <class MaterialOfSecond>
void fillList(ContactList& list, const std::vector<std::uint64_t>& keys, const std::vector<OldHistory>& old,
              const model::ParticleStore& s, const LawTable& laws, bool trialHistory,
              MaterialOfSecond materialOfSecond) {
    const std::uint32_t forms = std::max<std::uint32_t>(laws.formCount(), 1);
    list.bucketStart.assign(forms + 1, 0);
    std::vector<std::uint32_t> formOfKey(keys.size());
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const std::uint32_t a = keyFirst(keys[k]);
        const std::uint32_t f =
            laws.formCount() ? laws.formOf(s.material[a], materialOfSecond(keySecond(keys[k]))) : 0;
        formOfKey[k] = f;
        ++list.bucketStart[f + 1];
    }
    for (std::uint32_t f = 0; f < forms; ++f) list.bucketStart[f + 1] += list.bucketStart[f];
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
    std::vector<std::uint32_t> fill(list.bucketStart.begin(), list.bucketStart.end() - 1);
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const std::uint32_t pos = fill[formOfKey[k]]++;
        list.first[pos] = keyFirst(keys[k]);
        list.second[pos] = keySecond(keys[k]);
        auto it = std::lower_bound(old.begin(), old.end(), OldHistory{keys[k], 0, 0, 0, {}});
        if (it != old.end() && it->key == keys[k]) {
            list.xi[pos] = it->xi;
            if (rolling) list.zeta[pos] = it->zeta;
            if (area) {
                list.areaOld[pos] = it->areaOld;
                list.features[pos] = it->features;
            }
        }
    }
}

}  // namespace

namespace {
/// The segment a particle-wall pair is keyed by: a convex body wall is one contact per particle,
/// keyed by the body's first segment (gc2d spec 6.1); a polyline segment is its own.
std::uint32_t pairSegment(const model::WallSet& walls, std::uint32_t seg) noexcept {
    const auto& wall = walls.walls[walls.segments[seg].wall];
    return wall.body ? wall.firstSegment : seg;
}

/// Keeps the entries k with keep[k] of every per-pair column of `l` (columns may be empty).
void compactList(ContactList& l, const std::vector<char>& keep, const std::vector<std::uint32_t>& bucketOf) {
    const std::size_t n = l.size();
    const auto compact = [&](auto& col) {
        if (col.size() != n) return;
        std::size_t w = 0;
        for (std::size_t k = 0; k < n; ++k)
            if (keep[k]) col[w++] = col[k];
        col.resize(w);
    };
    compact(l.first);
    compact(l.second);
    compact(l.xi);
    compact(l.xiTrial);
    compact(l.zeta);
    compact(l.zetaTrial);
    compact(l.areaOld);
    compact(l.areaOldTrial);
    compact(l.features);
    if (l.bucketStart.empty()) return;
    std::vector<std::uint32_t> start(l.bucketStart.size(), 0);
    for (std::size_t k = 0; k < n; ++k)
        if (keep[k]) ++start[bucketOf[k] + 1];
    for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
    l.bucketStart = std::move(start);
}
}  // namespace

void NeighborList::removeSlots(const std::vector<std::uint32_t>& oldToNew) {
    for (auto* l : {&pairs, &wallPairs}) {
        const bool both = l == &pairs;
        const std::size_t n = l->size();
        std::vector<char> keep(n, 0);
        std::vector<std::uint32_t> bucketOf(n, 0);
        for (std::uint32_t b = 0; b + 1 < l->bucketStart.size(); ++b)
            for (std::uint32_t k = l->bucketStart[b]; k < l->bucketStart[b + 1]; ++k) bucketOf[k] = b;
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint32_t a = oldToNew[l->first[k]];
            const std::uint32_t b = both ? oldToNew[l->second[k]] : l->second[k];
            keep[k] = a != kRemovedSlot && b != kRemovedSlot;
            if (!keep[k]) continue;
            l->first[k] = a;
            l->second[k] = b;
        }
        compactList(*l, keep, bucketOf);
    }
    std::size_t w = 0;
    for (std::size_t i = 0; i < oldToNew.size() && i < x0.size(); ++i)
        if (oldToNew[i] != kRemovedSlot) {
            x0[w] = x0[i];
            y0[w] = y0[i];
            ++w;
        }
    x0.resize(w);
    y0.resize(w);
}

namespace {
/// Inserts `added` (form, first, second), in order, at the end of their buckets of `l`.
void appendToBuckets(ContactList& l, const std::vector<std::array<std::uint32_t, 3>>& added,
                     std::uint32_t forms, bool rolling, bool area, bool trialHistory) {
    if (added.empty()) return;
    if (l.bucketStart.empty()) l.bucketStart.assign(forms + 1, 0);
    const std::size_t n = l.size(), m = n + added.size();
    ContactList out;
    out.first.reserve(m);
    out.second.reserve(m);
    out.bucketStart.assign(l.bucketStart.size(), 0);
    const auto copyRange = [&](std::size_t b, std::size_t e) {
        for (std::size_t k = b; k < e; ++k) {
            out.first.push_back(l.first[k]);
            out.second.push_back(l.second[k]);
            out.xi.push_back(l.xi[k]);
            if (!l.zeta.empty()) out.zeta.push_back(l.zeta[k]);
            if (!l.areaOld.empty()) out.areaOld.push_back(l.areaOld[k]);
            if (!l.features.empty()) out.features.push_back(l.features[k]);
        }
    };
    for (std::uint32_t f = 0; f + 1 < l.bucketStart.size(); ++f) {
        out.bucketStart[f] = static_cast<std::uint32_t>(out.first.size());
        copyRange(l.bucketStart[f], l.bucketStart[f + 1]);
        for (const auto& a : added) {
            if (a[0] != f) continue;
            out.first.push_back(a[1]);
            out.second.push_back(a[2]);
            out.xi.push_back(0);
            if (rolling) out.zeta.push_back(0);
            if (area) {
                out.areaOld.push_back(0);
                out.features.push_back(geom::FeatureCache{});
            }
        }
    }
    out.bucketStart.back() = static_cast<std::uint32_t>(out.first.size());
    // Trial columns are scratch refreshed from the accepted ones at every evaluation.
    if (!l.xiTrial.empty() || trialHistory) out.xiTrial.assign(m, 0.0);
    if (!l.zetaTrial.empty()) out.zetaTrial.assign(m, 0.0);
    if (!l.areaOldTrial.empty()) out.areaOldTrial.assign(m, 0.0);
    l = std::move(out);
}
}  // namespace

void NeighborList::appendParticles(const model::ParticleStore& s, const model::WallSet& walls,
                                   std::size_t first, Real skin, const LawTable& laws, bool trialHistory) {
    const std::uint32_t forms = std::max<std::uint32_t>(laws.formCount(), 1);
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
    appendToBuckets(pairs, pairAdds, forms, laws.hasRolling(), laws.hasArea(), trialHistory);
    appendToBuckets(wallPairs, wallAdds, forms, laws.hasRolling(), laws.hasArea(), trialHistory);
    for (std::size_t k = first; k < s.size(); ++k) {
        x0.push_back(s.x[k]);
        y0.push_back(s.y[k]);
    }
}

void NeighborList::rebuild(const model::ParticleStore& s, const model::WallSet& walls, Real skin, Real time,
                           BroadPhase& broad, const LawTable& laws,
                           const std::vector<std::uint32_t>& oldToNew, bool trialHistory) {
    const auto oldPairs = collectHistory(pairs, oldToNew, true);
    const auto oldWall = collectHistory(wallPairs, oldToNew, false);
    std::vector<std::uint64_t> keys;
    broad.findPairs(s, skin, keys);
    fillList(pairs, keys, oldPairs, s, laws, trialHistory, [&](std::uint32_t j) { return s.material[j]; });
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
    fillList(wallPairs, keys, oldWall, s, laws, trialHistory,
             [&](std::uint32_t seg) { return walls.segments[seg].material; });
    x0 = s.x;
    y0 = s.y;
    wallTime0 = time;
    ++builds;
}

}  // namespace granulab::dem
