// SPDX-License-Identifier: MIT
// Particles binned in square cells of edge h for the fluid forces (dem/fluid_forces.cpp: the Di
// Felice voidage, the attraction cutoff): a dense grid over the centres' bounding box when it is
// small, else only the occupied cells (sorted keys, found by binary search), so that one particle
// far away neither allocates a huge grid nor falls back to all pairs. Storage is kept between
// builds (no allocation in the steady state).
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "model/particle_store.hpp"

namespace granulab::dem {

class CellBins {
public:
    /// Bins the particle centres of `s` in cells of edge h [m] (s not empty, h > 0).
    void build(const model::ParticleStore& s, Real h);

    /// Cells in a fixed order: (ix, iy) and the slots of the particles in it.
    std::size_t cellCount() const noexcept { return m_cellX.size(); }
    std::int64_t cellX(std::size_t c) const noexcept { return m_cellX[c]; }
    std::int64_t cellY(std::size_t c) const noexcept { return m_cellY[c]; }
    std::pair<const std::uint32_t*, const std::uint32_t*> members(std::size_t c) const noexcept {
        return {m_members.data() + m_start[c], m_members.data() + m_start[c + 1]};
    }
    /// The cell (ix, iy), or cellCount() if no particle is in it.
    std::size_t find(std::int64_t ix, std::int64_t iy) const noexcept;

    /// Key of the cell holding (x, y) [m] in a grid of edge h [m] laid from (x0, y0): the indices
    /// as build() makes them (clamped to [0, 2^31 - 1]), iy in the high word. Keys sort by row,
    /// then column.
    static std::uint64_t cellKey(Real x, Real y, Real x0, Real y0, Real h) noexcept;

private:
    bool m_dense = true;
    std::int64_t m_nx = 0, m_ny = 0;
    std::vector<std::int64_t> m_cellX, m_cellY;  ///< by cell
    std::vector<std::uint32_t> m_start;          ///< cellCount() + 1 offsets into m_members
    std::vector<std::uint32_t> m_members;        ///< slots by cell
    std::vector<std::uint64_t> m_keys;           ///< sparse: sorted keys of the occupied cells
    std::vector<std::pair<std::uint64_t, std::uint32_t>> m_scratch;  ///< (key, slot) while building
};

}  // namespace granulab::dem
