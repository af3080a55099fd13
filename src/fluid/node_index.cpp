// SPDX-License-Identifier: MIT
// Nearest-node search on a uniform bin grid (fluid/node_index.hpp): rings of bins around the query
// point until the k-th best distance is closer than any unvisited bin can be.
#include "fluid/node_index.hpp"

#include <algorithm>
#include <cmath>

namespace granulab::fluid {

NodeIndex::NodeIndex(const std::vector<Real>& x, const std::vector<Real>& y) {
    const std::size_t n = x.size();
    if (n == 0) return;
    Vec2 lo{x[0], y[0]}, hi = lo;
    for (std::size_t i = 0; i < n; ++i) {
        lo = {std::min(lo.x, x[i]), std::min(lo.y, y[i])};
        hi = {std::max(hi.x, x[i]), std::max(hi.y, y[i])};
    }
    const Real w = hi.x - lo.x, h = hi.y - lo.y;
    const Real extent = std::max({w, h, 1e-300});
    // About one node per bin; a line of nodes (zero width) gets bins of extent / n.
    Real bin = (w > 0 && h > 0) ? std::sqrt(w * h / static_cast<Real>(n)) : extent / static_cast<Real>(n);
    bin = std::max(bin, extent * 1e-6);
    m_lo = lo;
    m_bin = bin;
    m_nx = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor(w / bin)) + 1);
    m_ny = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor(h / bin)) + 1);
    const std::size_t bins = static_cast<std::size_t>(m_nx * m_ny);
    m_binStart.assign(bins + 1, 0);
    std::vector<std::uint32_t> binOf(n);
    for (std::size_t i = 0; i < n; ++i) {
        binOf[i] = static_cast<std::uint32_t>(clampX(x[i]) + m_nx * clampY(y[i]));
        ++m_binStart[binOf[i] + 1];
    }
    for (std::size_t b = 0; b < bins; ++b) m_binStart[b + 1] += m_binStart[b];
    m_binNodes.resize(n);
    std::vector<std::uint32_t> fill(m_binStart.begin(), m_binStart.end() - 1);
    for (std::size_t i = 0; i < n; ++i) m_binNodes[fill[binOf[i]]++] = static_cast<std::uint32_t>(i);
}

std::int64_t NodeIndex::clampX(Real x) const noexcept {
    const Real f = std::floor((x - m_lo.x) / m_bin);
    return f <= 0 ? 0 : (f >= static_cast<Real>(m_nx - 1) ? m_nx - 1 : static_cast<std::int64_t>(f));
}
std::int64_t NodeIndex::clampY(Real y) const noexcept {
    const Real f = std::floor((y - m_lo.y) / m_bin);
    return f <= 0 ? 0 : (f >= static_cast<Real>(m_ny - 1) ? m_ny - 1 : static_cast<std::int64_t>(f));
}

int NodeIndex::nearest(const Real* xs, const Real* ys, Vec2 p, int k, std::uint32_t* nodes,
                       Real* dist2) const noexcept {
    if (m_binNodes.empty() || k <= 0) return 0;
    k = std::min(k, kMaxNearest);
    const std::int64_t cx = clampX(p.x), cy = clampY(p.y);
    // Distance from p to the boundary of its (clamped) bin block: a bin in ring r + 1 is at least
    // r * bin + `inner` away.
    const Real bx0 = m_lo.x + static_cast<Real>(cx) * m_bin, by0 = m_lo.y + static_cast<Real>(cy) * m_bin;
    const Real inner =
        std::max<Real>(0, std::min({p.x - bx0, bx0 + m_bin - p.x, p.y - by0, by0 + m_bin - p.y}));
    int found = 0;
    const auto consider = [&](std::uint32_t node) {
        const Real dx = xs[node] - p.x, dy = ys[node] - p.y;
        const Real d2 = dx * dx + dy * dy;
        if (found == k && d2 >= dist2[k - 1]) return;
        int pos = found < k ? found++ : k - 1;
        while (pos > 0 && (dist2[pos - 1] > d2 || (dist2[pos - 1] == d2 && nodes[pos - 1] > node))) {
            dist2[pos] = dist2[pos - 1];
            nodes[pos] = nodes[pos - 1];
            --pos;
        }
        dist2[pos] = d2;
        nodes[pos] = node;
    };
    const std::int64_t maxRing = std::max(m_nx, m_ny);
    for (std::int64_t r = 0; r <= maxRing; ++r) {
        for (std::int64_t j = cy - r; j <= cy + r; ++j) {
            if (j < 0 || j >= m_ny) continue;
            const bool edgeRow = (j == cy - r || j == cy + r);
            for (std::int64_t i = cx - r; i <= cx + r; i += (edgeRow || r == 0) ? 1 : 2 * r) {
                if (i < 0 || i >= m_nx) continue;
                const std::size_t b = static_cast<std::size_t>(i + m_nx * j);
                for (std::uint32_t q = m_binStart[b]; q < m_binStart[b + 1]; ++q) consider(m_binNodes[q]);
            }
        }
        if (found == k) {
            const Real reach = static_cast<Real>(r) * m_bin + inner;
            if (dist2[k - 1] <= reach * reach) break;
        }
    }
    return found;
}

}  // namespace granulab::fluid
