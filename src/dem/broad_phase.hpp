// SPDX-License-Identifier: MIT
// Broad phase behind one interface (DESIGN.md step stage 3): candidate disk pairs and
// disk-wall pairs within a distance margin. Called only when the neighbour list is rebuilt, so
// the virtual call is per rebuild, not per pair. Brute force is the test reference.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

#include "model/particle_store.hpp"
#include "model/walls.hpp"

namespace granulab::dem {

/// Pair key: (first << 32) | second. For particle pairs first < second (slots).
inline std::uint64_t pairKey(std::uint32_t a, std::uint32_t b) noexcept {
    return (static_cast<std::uint64_t>(a) << 32) | b;
}
inline std::uint32_t keyFirst(std::uint64_t k) noexcept {
    return static_cast<std::uint32_t>(k >> 32);
}
inline std::uint32_t keySecond(std::uint64_t k) noexcept {
    return static_cast<std::uint32_t>(k);
}

class BroadPhase {
public:
    virtual ~BroadPhase() = default;
    virtual const char* name() const noexcept = 0;
    /// All slot pairs (i < j) with |x_i - x_j| < r_i + r_j + margin, sorted ascending by key.
    virtual void findPairs(const model::ParticleStore& s, Real margin, std::vector<std::uint64_t>& out) = 0;
    /// All (slot, segment) pairs with distance(centre, segment) < r + margin, sorted by key.
    virtual void findWallPairs(const model::ParticleStore& s, const model::WallSet& walls, Real margin,
                               std::vector<std::uint64_t>& out) = 0;
    /// A slot order that groups nearby particles (for cache locality and compact slot tiles);
    /// empty = keep order. After applying it the caller calls slotsRenumbered.
    virtual std::vector<std::uint32_t> spatialOrder(const model::ParticleStore&) { return {}; }
    /// Bytes held between calls.
    virtual std::size_t memoryBytes() const noexcept { return 0; }
    /// Particles were removed and the slots renumbered: forget state kept by slot.
    virtual void slotsRenumbered() {}
    /// Threads of findPairs (the result does not depend on them).
    void setThreads(int threads) noexcept { m_threads = threads > 1 ? threads : 1; }

protected:
    int m_threads = 1;
};

/// O(N^2) reference.
class BruteForce final : public BroadPhase {
public:
    const char* name() const noexcept override { return "brute_force"; }
    void findPairs(const model::ParticleStore& s, Real margin, std::vector<std::uint64_t>& out) override;
    void findWallPairs(const model::ParticleStore& s, const model::WallSet& walls, Real margin,
                       std::vector<std::uint64_t>& out) override;
};

/// Morton (Z-order) code of the cell (x, y): the bits of x and y interleaved (CellGrid's slot
/// order; the domain decomposition orders its owned particles by it too).
std::uint64_t mortonCode(std::uint32_t x, std::uint32_t y) noexcept;

/// Uniform cell grid with cell size >= 2 r_max + margin, so any size distribution is safe;
/// the grid spans the particles' bounding box, so no particle can leave it. findPairs runs on
/// threads over blocks of slots; spatialOrder lists the cells along a Morton (Z) curve, so that
/// consecutive slots, and hence the slot tiles of the threaded step, are compact patches.
class CellGrid final : public BroadPhase {
public:
    const char* name() const noexcept override { return "cell_grid"; }
    void findPairs(const model::ParticleStore& s, Real margin, std::vector<std::uint64_t>& out) override;
    void findWallPairs(const model::ParticleStore& s, const model::WallSet& walls, Real margin,
                       std::vector<std::uint64_t>& out) override;
    std::vector<std::uint32_t> spatialOrder(const model::ParticleStore& s) override;
    std::size_t memoryBytes() const noexcept override;

private:
    void bin(const model::ParticleStore& s, Real margin);
    Real m_cell = 1, m_x0 = 0, m_y0 = 0;
    std::int64_t m_nx = 1, m_ny = 1;
    std::vector<std::uint32_t> m_cellStart;                ///< size cells + 1
    std::vector<std::uint32_t> m_sorted;                   ///< slots grouped by cell
    std::vector<std::uint32_t> m_cellOf;                   ///< cell of each slot
    std::vector<std::vector<std::uint64_t>> m_blockPairs;  ///< pairs found by each block of slots
};

/// Incremental sort-and-sweep on bounding boxes (gc2d spec section 5.2): endpoint lists kept
/// sorted between calls by insertion sort, overlapping boxes updated by the swap rules, so a
/// call costs O(N) for slowly moving particles; appended particles are inserted without a full
/// re-sort. Walls use a cell grid. See sort_and_sweep.cpp.
class SortAndSweep final : public BroadPhase {
public:
    const char* name() const noexcept override { return "sort_and_sweep"; }
    void findPairs(const model::ParticleStore& s, Real margin, std::vector<std::uint64_t>& out) override;
    void findWallPairs(const model::ParticleStore& s, const model::WallSet& walls, Real margin,
                       std::vector<std::uint64_t>& out) override;
    std::size_t memoryBytes() const noexcept override;
    /// The Morton order of CellGrid: the slot tiles of the threaded step need compact patches.
    /// The World calls slotsRenumbered after it permuted the slots, which restarts the lists.
    std::vector<std::uint32_t> spatialOrder(const model::ParticleStore& s) override {
        return m_wallGrid.spatialOrder(s);
    }
    void slotsRenumbered() override {
        m_xs.clear();
        m_ys.clear();
        m_overlaps.clear();
        m_tracked = 0;
    }

private:
    struct Endpoint {
        Real value;
        std::uint32_t box;
        bool isEnd;
    };
    void updateBoxes(const model::ParticleStore& s, Real margin);
    void sortAxis(int axis);
    bool overlapOn(int axis, std::uint32_t a, std::uint32_t b) const noexcept;

    std::vector<Endpoint> m_xs, m_ys;              ///< sorted endpoint lists
    std::vector<std::array<Real, 4>> m_box;        ///< [bx, ex, by, ey] per slot [m]
    std::unordered_set<std::uint64_t> m_overlaps;  ///< overlapping box pairs (slot keys)
    std::size_t m_tracked = 0;                     ///< slots in the lists
    Real m_margin = -1;
    CellGrid m_wallGrid;
};

std::unique_ptr<BroadPhase> makeBroadPhase(const std::string& name);
/// Names accepted by makeBroadPhase.
std::vector<std::string> broadPhaseNames();

}  // namespace granulab::dem
