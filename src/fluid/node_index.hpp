// SPDX-License-Identifier: MIT
// A uniform bin grid over scattered field nodes for nearest-node queries in O(1) expected time
// (cfddem spec 10 [R]: "a spatial hash or a grid locator ... instead of O(N_nodes) sorting"; the
// seed sorted a full node-to-particle distance matrix, spec 5.4 Eq. 4.14).
#pragma once
#include <cstdint>
#include <vector>

#include "core/types.hpp"

namespace granulab::fluid {

class NodeIndex {
public:
    NodeIndex() = default;
    /// Bins of edge ~ sqrt(area / n), about one node per bin.
    NodeIndex(const std::vector<Real>& x, const std::vector<Real>& y);

    /// The k nearest nodes of p (k <= kMaxNearest), closest first: node indices in `nodes`,
    /// squared distances [m^2] in `dist2`; returns how many were found (fewer only if the field
    /// has fewer nodes). x, y: the coordinates the index was built from (the index keeps no
    /// pointer to them, so that its owner can be moved).
    static constexpr int kMaxNearest = 64;
    int nearest(const Real* x, const Real* y, Vec2 p, int k, std::uint32_t* nodes,
                Real* dist2) const noexcept;

    std::size_t memoryBytes() const noexcept { return m_binStart.capacity() * 4 + m_binNodes.capacity() * 4; }

private:
    Vec2 m_lo;
    Real m_bin = 1;  ///< [m] bin edge
    std::int64_t m_nx = 1, m_ny = 1;
    std::vector<std::uint32_t> m_binStart;  ///< nx * ny + 1 offsets into m_binNodes
    std::vector<std::uint32_t> m_binNodes;  ///< node indices, by bin

    std::int64_t clampX(Real x) const noexcept;
    std::int64_t clampY(Real y) const noexcept;
};

}  // namespace granulab::fluid
