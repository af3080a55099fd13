// SPDX-License-Identifier: MIT
// Records and history of the DEM domain decomposition (dem/parallel/domain_records.hpp).
#include "dem/parallel/domain_records.hpp"

#include <algorithm>
#include <utility>

namespace granulab::dem {

ParticleRecord recordOf(const model::ParticleStore& s, std::size_t k, int owner) {
    return {s.x[k],          s.y[k],  s.vx[k],       s.vy[k],     s.angle[k], s.omega[k],
            s.fx[k],         s.fy[k], s.torque[k],   s.radius[k], s.mass[k],  s.invMass[k],
            s.invInertia[k], s.id[k], s.material[k], s.shape[k],  owner};
}

/// A store of n particles (every column sized; setRecord fills them).
model::ParticleStore storeOfSize(std::size_t n) {
    model::ParticleStore s;
    s.forEachColumn([&](auto& column) { column.resize(n); });
    return s;
}

void setRecord(model::ParticleStore& s, std::size_t k, const ParticleRecord& r) {
    s.x[k] = r.x;
    s.y[k] = r.y;
    s.vx[k] = r.vx;
    s.vy[k] = r.vy;
    s.angle[k] = r.angle;
    s.omega[k] = r.omega;
    s.fx[k] = r.fx;
    s.fy[k] = r.fy;
    s.torque[k] = r.torque;
    s.radius[k] = r.radius;
    s.mass[k] = r.mass;
    s.invMass[k] = r.invMass;
    s.invInertia[k] = r.invInertia;
    s.material[k] = r.material;
    s.id[k] = r.id;
    s.shape[k] = r.shape;
}

/// Entry k of a particle-pair list in ids, lower id first (exchanging the bodies flips the
/// rolling displacement and the feature roles; the tangential spring is unchanged:
/// neighbor_list.cpp collectHistory).
IdHistory pairHistoryById(const model::ParticleStore& s, const PairHistory& h, bool fromOwnerOfLower,
                          bool& lowerIsFirst) {
    const std::uint32_t first = keyFirst(h.key), second = keySecond(h.key);
    IdHistory r{s.id[first], s.id[second], 0, 0, h.xi, h.zeta, h.areaOld, h.features};
    lowerIsFirst = r.a < r.b;
    if (!lowerIsFirst) {
        std::swap(r.a, r.b);
        exchangeBodies(r.zeta, r.features);
    }
    r.fromOwnerOfA = fromOwnerOfLower ? 1 : 0;
    return r;
}

/// Slot-keyed history (sorted by key) of the pairs whose both ids are in the store, preferring
/// the record of a's owner when two ranks sent the same pair.
std::vector<PairHistory> pairHistoryInSlots(std::vector<IdHistory> records, const SlotOfId& slotOf) {
    std::stable_partition(records.begin(), records.end(),
                          [](const IdHistory& r) { return r.fromOwnerOfA != 0; });
    std::vector<PairHistory> out;
    out.reserve(records.size());
    for (IdHistory& r : records) {
        std::uint32_t sa = slotOf(r.a), sb = slotOf(r.b);
        if (sa == kRemovedSlot || sb == kRemovedSlot) continue;
        if (sa > sb) {
            std::swap(sa, sb);
            exchangeBodies(r.zeta, r.features);
        }
        out.push_back({pairKey(sa, sb), r.xi, r.zeta, r.areaOld, r.features});
    }
    std::stable_sort(out.begin(), out.end());  // by key; the preferred record first among equals
    out.erase(std::unique(out.begin(), out.end(),
                          [](const PairHistory& p, const PairHistory& q) { return p.key == q.key; }),
              out.end());
    return out;
}

std::vector<PairHistory> wallHistoryInSlots(const std::vector<IdHistory>& records, const SlotOfId& slotOf) {
    std::vector<PairHistory> out;
    out.reserve(records.size());
    for (const IdHistory& r : records)
        if (const std::uint32_t slot = slotOf(r.a); slot != kRemovedSlot)
            out.push_back({pairKey(slot, r.b), r.xi, r.zeta, r.areaOld, r.features});
    std::sort(out.begin(), out.end());
    return out;
}

IdHistory wallHistoryById(const model::ParticleStore& s, const PairHistory& h) {
    return {s.id[keyFirst(h.key)], keySecond(h.key), 1, 0, h.xi, h.zeta, h.areaOld, h.features};
}

}  // namespace granulab::dem
