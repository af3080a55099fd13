// SPDX-License-Identifier: MIT
// Dense or sparse binning of particle centres (dem/cell_bins.hpp).
#include "dem/cell_bins.hpp"

#include <algorithm>
#include <cmath>

namespace granulab::dem {

namespace {
constexpr std::int64_t kMaxIndex = (std::int64_t{1} << 31) - 1;  ///< cell indices are clamped to 31 bits
std::int64_t clampIndex(Real f) noexcept {
    return f <= 0 ? 0 : (f >= static_cast<Real>(kMaxIndex) ? kMaxIndex : static_cast<std::int64_t>(f));
}
std::uint64_t keyOf(std::int64_t ix, std::int64_t iy) noexcept {
    return (static_cast<std::uint64_t>(iy) << 32) | static_cast<std::uint64_t>(ix);
}
}  // namespace

void CellBins::build(const model::ParticleStore& s, Real h) {
    const std::size_t n = s.size();
    Real x0 = s.x[0], y0 = s.y[0], x1 = x0, y1 = y0;
    for (std::size_t i = 1; i < n; ++i) {
        x0 = std::min(x0, s.x[i]);
        x1 = std::max(x1, s.x[i]);
        y0 = std::min(y0, s.y[i]);
        y1 = std::max(y1, s.y[i]);
    }
    m_nx = clampIndex(std::floor((x1 - x0) / h)) + 1;
    m_ny = clampIndex(std::floor((y1 - y0) / h)) + 1;
    const auto ixOf = [&](std::size_t i) { return clampIndex(std::floor((s.x[i] - x0) / h)); };
    const auto iyOf = [&](std::size_t i) { return clampIndex(std::floor((s.y[i] - y0) / h)); };
    m_dense = static_cast<double>(m_nx) * static_cast<double>(m_ny) <= 4.0 * static_cast<double>(n) + 4096;
    m_members.resize(n);
    if (m_dense) {  // counting sort over the whole grid
        const std::size_t cells = static_cast<std::size_t>(m_nx * m_ny);
        m_start.assign(cells + 1, 0);
        for (std::size_t i = 0; i < n; ++i) ++m_start[static_cast<std::size_t>(ixOf(i) + m_nx * iyOf(i)) + 1];
        for (std::size_t c = 0; c < cells; ++c) m_start[c + 1] += m_start[c];
        m_cellX.resize(cells);
        m_cellY.resize(cells);
        for (std::size_t c = 0; c < cells; ++c) {
            m_cellX[c] = static_cast<std::int64_t>(c) % m_nx;
            m_cellY[c] = static_cast<std::int64_t>(c) / m_nx;
        }
        m_keys.assign(m_start.begin(), m_start.end() - 1);  // fill pointers, reusing the key storage
        for (std::size_t i = 0; i < n; ++i)
            m_members[m_keys[static_cast<std::size_t>(ixOf(i) + m_nx * iyOf(i))]++] =
                static_cast<std::uint32_t>(i);
        return;
    }
    // Sparse: sort (key, slot) pairs; the slot breaks ties, so the order is deterministic.
    m_scratch.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        m_scratch[i] = {cellKey(s.x[i], s.y[i], x0, y0, h), static_cast<std::uint32_t>(i)};
    std::sort(m_scratch.begin(), m_scratch.end());
    m_keys.clear();
    m_cellX.clear();
    m_cellY.clear();
    m_start.clear();
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint64_t key = m_scratch[k].first;
        if (m_keys.empty() || m_keys.back() != key) {
            m_keys.push_back(key);
            m_cellX.push_back(static_cast<std::int64_t>(key & 0xffffffffu));
            m_cellY.push_back(static_cast<std::int64_t>(key >> 32));
            m_start.push_back(static_cast<std::uint32_t>(k));
        }
        m_members[k] = m_scratch[k].second;
    }
    m_start.push_back(static_cast<std::uint32_t>(n));
}

std::uint64_t CellBins::cellKey(Real x, Real y, Real x0, Real y0, Real h) noexcept {
    return keyOf(clampIndex(std::floor((x - x0) / h)), clampIndex(std::floor((y - y0) / h)));
}

std::size_t CellBins::find(std::int64_t ix, std::int64_t iy) const noexcept {
    if (ix < 0 || iy < 0 || ix >= m_nx || iy >= m_ny) return cellCount();
    if (m_dense) return static_cast<std::size_t>(ix + m_nx * iy);
    const std::uint64_t key = keyOf(ix, iy);
    const auto it = std::lower_bound(m_keys.begin(), m_keys.end(), key);
    return it != m_keys.end() && *it == key ? static_cast<std::size_t>(it - m_keys.begin()) : cellCount();
}

}  // namespace granulab::dem
