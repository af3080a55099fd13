// SPDX-License-Identifier: MIT
// Cell-grid broad phase (counting sort into square cells of size 2 r_max + margin), its pair search
// on threads, and the Morton order of the slots.
#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"
#include "dem/broad_phase.hpp"
#include "geom/segment.hpp"

namespace granulab::dem {

void CellGrid::bin(const model::ParticleStore& s, Real margin) {
    const std::size_t n = s.size();
    Real xmin = 1e300, ymin = 1e300, xmax = -1e300, ymax = -1e300, rmax = 0;
    for (std::size_t i = 0; i < n; ++i) {
        xmin = std::min(xmin, s.x[i]);
        xmax = std::max(xmax, s.x[i]);
        ymin = std::min(ymin, s.y[i]);
        ymax = std::max(ymax, s.y[i]);
        rmax = std::max(rmax, s.radius[i]);
    }
    if (n == 0) xmin = ymin = xmax = ymax = 0;
    m_cell = std::max(2 * rmax + margin, 1e-300);
    // Cap the number of cells at ~4N so a stray particle cannot exhaust memory.
    const Real maxCells = 4.0 * static_cast<Real>(n) + 64.0;
    for (;;) {
        const Real nx = std::floor((xmax - xmin) / m_cell) + 1;
        const Real ny = std::floor((ymax - ymin) / m_cell) + 1;
        if (nx * ny <= maxCells) {
            m_nx = static_cast<std::int64_t>(nx);
            m_ny = static_cast<std::int64_t>(ny);
            break;
        }
        m_cell *= 2;
    }
    m_x0 = xmin;
    m_y0 = ymin;
    const std::size_t cells = static_cast<std::size_t>(m_nx * m_ny);
    m_cellStart.assign(cells + 1, 0);
    m_cellOf.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto cx = std::min<std::int64_t>(static_cast<std::int64_t>((s.x[i] - m_x0) / m_cell), m_nx - 1);
        const auto cy = std::min<std::int64_t>(static_cast<std::int64_t>((s.y[i] - m_y0) / m_cell), m_ny - 1);
        const auto c = static_cast<std::uint32_t>(cy * m_nx + cx);
        m_cellOf[i] = c;
        ++m_cellStart[c + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) m_cellStart[c + 1] += m_cellStart[c];
    m_sorted.resize(n);
    std::vector<std::uint32_t> fill(m_cellStart.begin(), m_cellStart.end() - 1);
    for (std::size_t i = 0; i < n; ++i) m_sorted[fill[m_cellOf[i]]++] = static_cast<std::uint32_t>(i);
}

void CellGrid::findPairs(const model::ParticleStore& s, Real margin, std::vector<std::uint64_t>& out) {
    out.clear();
    bin(s, margin);
    const std::size_t n = s.size();
    const std::size_t blocks = blockCount(m_threads, n);
    if (m_blockPairs.size() < blocks) m_blockPairs.resize(blocks);
    // Each block lists the pairs of its slots i in ascending (i, j): the blocks, concatenated in
    // order, give the sorted list whatever their number.
    parallelBlocks(m_threads, n, [&](std::size_t begin, std::size_t end, std::size_t block) {
        std::vector<std::uint64_t>& found = blocks > 1 ? m_blockPairs[block] : out;
        found.clear();
        std::vector<std::uint32_t> near;
        for (std::size_t i = begin; i < end; ++i) {
            near.clear();
            const std::int64_t c = m_cellOf[i];
            const std::int64_t cx = c % m_nx, cy = c / m_nx;
            const Real xi = s.x[i], yi = s.y[i], ri = s.radius[i];
            for (std::int64_t y = std::max<std::int64_t>(cy - 1, 0); y <= std::min(cy + 1, m_ny - 1); ++y)
                for (std::int64_t x = std::max<std::int64_t>(cx - 1, 0); x <= std::min(cx + 1, m_nx - 1);
                     ++x) {
                    const std::size_t cell = static_cast<std::size_t>(y * m_nx + x);
                    for (std::uint32_t k = m_cellStart[cell]; k < m_cellStart[cell + 1]; ++k) {
                        const std::uint32_t j = m_sorted[k];
                        if (j <= i) continue;
                        const Real dx = s.x[j] - xi, dy = s.y[j] - yi;
                        const Real reach = ri + s.radius[j] + margin;
                        if (dx * dx + dy * dy < reach * reach) near.push_back(j);
                    }
                }
            std::sort(near.begin(), near.end());
            for (std::uint32_t j : near) found.push_back(pairKey(static_cast<std::uint32_t>(i), j));
        }
    });
    if (blocks <= 1) return;
    std::size_t total = 0;
    for (std::size_t b = 0; b < blocks; ++b) total += m_blockPairs[b].size();
    out.reserve(total);
    for (std::size_t b = 0; b < blocks; ++b)
        out.insert(out.end(), m_blockPairs[b].begin(), m_blockPairs[b].end());
}

void CellGrid::findWallPairs(const model::ParticleStore& s, const model::WallSet& walls, Real margin,
                             std::vector<std::uint64_t>& out) {
    out.clear();
    if (walls.segments.empty() || s.size() == 0) return;
    bin(s, margin);
    Real rmax = 0;
    for (Real r : s.radius) rmax = std::max(rmax, r);
    const Real pad = rmax + margin;
    for (std::size_t seg = 0; seg < walls.segments.size(); ++seg) {
        const auto& w = walls.segments[seg];
        const auto cellRange = [&](Real lo, Real hi, Real origin, std::int64_t count) {
            const auto a = static_cast<std::int64_t>(std::floor((lo - origin) / m_cell));
            const auto b = static_cast<std::int64_t>(std::floor((hi - origin) / m_cell));
            return std::pair{std::max<std::int64_t>(a, 0), std::min(b, count - 1)};
        };
        const auto [x0, x1] =
            cellRange(std::min(w.a.x, w.b.x) - pad, std::max(w.a.x, w.b.x) + pad, m_x0, m_nx);
        const auto [y0, y1] =
            cellRange(std::min(w.a.y, w.b.y) - pad, std::max(w.a.y, w.b.y) + pad, m_y0, m_ny);
        for (std::int64_t y = y0; y <= y1; ++y)
            for (std::int64_t x = x0; x <= x1; ++x) {
                const std::size_t cell = static_cast<std::size_t>(y * m_nx + x);
                for (std::uint32_t k = m_cellStart[cell]; k < m_cellStart[cell + 1]; ++k) {
                    const std::uint32_t i = m_sorted[k];
                    const Vec2 c{s.x[i], s.y[i]};
                    const Real t = geom::closestParameter(w.a, w.b, c);
                    const Vec2 q = w.a + (w.b - w.a) * t;
                    const Real reach = s.radius[i] + margin;
                    if (norm2(c - q) < reach * reach)
                        out.push_back(pairKey(i, static_cast<std::uint32_t>(seg)));
                }
            }
    }
    std::sort(out.begin(), out.end());
}

std::uint64_t mortonCode(std::uint32_t x, std::uint32_t y) noexcept {
    const auto spread = [](std::uint64_t v) {
        v &= 0xFFFFFFFFu;
        v = (v | (v << 16)) & 0x0000FFFF0000FFFFull;
        v = (v | (v << 8)) & 0x00FF00FF00FF00FFull;
        v = (v | (v << 4)) & 0x0F0F0F0F0F0F0F0Full;
        v = (v | (v << 2)) & 0x3333333333333333ull;
        v = (v | (v << 1)) & 0x5555555555555555ull;
        return v;
    };
    return spread(x) | (spread(y) << 1);
}

std::vector<std::uint32_t> CellGrid::spatialOrder(const model::ParticleStore& s) {
    bin(s, 0);
    const std::size_t cells = m_cellStart.size() - 1;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> byCode(cells);
    for (std::size_t c = 0; c < cells; ++c)
        byCode[c] = {mortonCode(static_cast<std::uint32_t>(static_cast<std::int64_t>(c) % m_nx),
                                static_cast<std::uint32_t>(static_cast<std::int64_t>(c) / m_nx)),
                     static_cast<std::uint32_t>(c)};
    std::sort(byCode.begin(), byCode.end());
    std::vector<std::uint32_t> order;
    order.reserve(s.size());
    for (const auto& [code, c] : byCode)
        order.insert(order.end(), m_sorted.begin() + m_cellStart[c], m_sorted.begin() + m_cellStart[c + 1]);
    return order;
}

std::size_t CellGrid::memoryBytes() const noexcept {
    return (m_cellStart.capacity() + m_sorted.capacity() + m_cellOf.capacity()) * sizeof(std::uint32_t);
}

}  // namespace granulab::dem
