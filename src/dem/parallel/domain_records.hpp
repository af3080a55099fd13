// SPDX-License-Identifier: MIT
// What the DEM domain decomposition sends between ranks (dem/parallel/domain_world.hpp;
// docs/physics/dem-mpi.md): particle records, contact history keyed by particle ids, the byte
// messages that carry them, and their conversion back to slots.
#pragma once
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/communicator.hpp"
#include "dem/neighbor_list.hpp"
#include "model/particle_store.hpp"

namespace granulab::dem {

/// One particle as it travels between ranks: every column of the ParticleStore.
struct ParticleRecord {
    Real x, y, vx, vy, angle, omega, fx, fy, torque, radius, mass, invMass, invInertia;
    ParticleId id;
    std::uint32_t material, shape;
    std::int32_t owner;  ///< the rank that owns it after the exchange
};

/// Contact history keyed by particle ids (slots differ on every rank): a < b for a pair (the
/// roles as in a list whose first slot holds a), id and segment for a wall pair.
struct IdHistory {
    ParticleId a, b;
    std::int32_t fromOwnerOfA;  ///< sent by the owner of a: preferred when two ranks send the pair
    std::int32_t pad = 0;
    Real xi, zeta, areaOld;
    geom::FeatureCache features;
};

/// Byte message: counts, then arrays of plain records.
class MessageWriter {
public:
    template <class T>
    void put(const std::vector<T>& values) {
        const std::uint64_t n = values.size();
        append(&n, sizeof n);
        append(values.data(), values.size() * sizeof(T));
    }
    ByteBuffer take() { return std::move(m_bytes); }

private:
    void append(const void* p, std::size_t n) {
        const std::size_t at = m_bytes.size();
        m_bytes.resize(at + n);
        if (n) std::memcpy(m_bytes.data() + at, p, n);
    }
    ByteBuffer m_bytes;
};

class MessageReader {
public:
    explicit MessageReader(const ByteBuffer& b) : m_bytes(b) {}
    template <class T>
    void appendTo(std::vector<T>& out) {
        std::uint64_t n = 0;
        read(&n, sizeof n);
        const std::size_t at = out.size();
        out.resize(at + n);
        read(out.data() + at, n * sizeof(T));
    }

private:
    void read(void* p, std::size_t n) {
        if (m_at + n > m_bytes.size()) throw std::runtime_error("domain exchange: a truncated message");
        if (n) std::memcpy(p, m_bytes.data() + m_at, n);
        m_at += n;
    }
    const ByteBuffer& m_bytes;
    std::size_t m_at = 0;
};

/// Slots of the particles of a store by id: a dense table (ids are below the next id of the
/// run, so its size follows the particle count).
class SlotOfId {
public:
    explicit SlotOfId(const model::ParticleStore& s) {
        ParticleId top = 0;
        for (const ParticleId id : s.id) top = std::max(top, id);
        m_slot.assign(s.size() ? top + std::size_t{1} : 0, kRemovedSlot);
        for (std::size_t k = 0; k < s.size(); ++k) m_slot[s.id[k]] = static_cast<std::uint32_t>(k);
    }
    std::uint32_t operator()(ParticleId id) const noexcept {
        return id < m_slot.size() ? m_slot[id] : kRemovedSlot;
    }

private:
    std::vector<std::uint32_t> m_slot;
};

/// Slot k of `s` as a record, owned by rank `owner` after the exchange.
ParticleRecord recordOf(const model::ParticleStore& s, std::size_t k, int owner);

/// A store of n particles (every column sized; setRecord fills them).
model::ParticleStore storeOfSize(std::size_t n);

/// Writes `r` into slot k of `s` (every column).
void setRecord(model::ParticleStore& s, std::size_t k, const ParticleRecord& r);

/// Entry k of a particle-pair list in ids, lower id first (exchanging the bodies flips the
/// rolling displacement and the feature roles; the tangential spring is unchanged:
/// neighbor_list.cpp collectHistory).
IdHistory pairHistoryById(const model::ParticleStore& s, const PairHistory& h, bool fromOwnerOfLower,
                          bool& lowerIsFirst);

/// Slot-keyed history (sorted by key) of the pairs whose both ids are in the store, preferring
/// the record of a's owner when two ranks sent the same pair.
std::vector<PairHistory> pairHistoryInSlots(std::vector<IdHistory> records, const SlotOfId& slotOf);

/// Slot-keyed wall history (sorted by key) of the particles in the store.
std::vector<PairHistory> wallHistoryInSlots(const std::vector<IdHistory>& records, const SlotOfId& slotOf);

/// A wall-list entry (slot, segment) in ids: (particle id, segment).
IdHistory wallHistoryById(const model::ParticleStore& s, const PairHistory& h);

}  // namespace granulab::dem
