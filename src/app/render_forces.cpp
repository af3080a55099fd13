// SPDX-License-Identifier: MIT
// Per-grain pressure and coordination from a contact file and the force network drawing of
// `granulab render` (app/render_forces.hpp).
#include "app/render_forces.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace granulab::app::render {

GrainIndex::GrainIndex(const analysis::GrainFrame& g) {
    const std::size_t n = g.size();
    bool dense = true;
    for (std::size_t i = 0; i < n && dense; ++i)
        dense = g.id[i] >= 0 && static_cast<std::size_t>(g.id[i]) < 2 * n + 16;
    if (dense) {
        m_dense.assign(2 * n + 16, kNone);
        for (std::size_t i = 0; i < n; ++i) m_dense[static_cast<std::size_t>(g.id[i])] = i;
        return;
    }
    m_sparse.reserve(n);
    for (std::size_t i = 0; i < n; ++i) m_sparse.emplace(g.id[i], i);
}

std::size_t GrainIndex::find(std::int64_t id) const noexcept {
    if (!m_dense.empty())
        return id >= 0 && static_cast<std::size_t>(id) < m_dense.size() ? m_dense[id] : kNone;
    const auto it = m_sparse.find(id);
    return it == m_sparse.end() ? kNone : it->second;
}

GrainContactSums grainContactSums(const analysis::GrainFrame& g, const analysis::ContactFrame& c,
                                  const GrainIndex& index) {
    GrainContactSums s;
    s.pressure.assign(g.size(), 0.0);
    s.coordination.assign(g.size(), 0);
    std::vector<double> trace(g.size(), 0.0);  // sum over contacts of (x_c - x_i) . F on i
    for (std::size_t k = 0; k < c.size(); ++k) {
        const Vec2 p{c.px[k], c.py[k]}, f{c.fx[k], c.fy[k]};
        const std::size_t a = index.find(c.a[k]);
        if (a != GrainIndex::kNone) {
            trace[a] += dot(p - Vec2{g.x[a], g.y[a]}, f);
            ++s.coordination[a];
        }
        if (c.b[k] < 0) continue;
        const std::size_t b = index.find(c.b[k]);
        if (b == GrainIndex::kNone) continue;
        trace[b] -= dot(p - Vec2{g.x[b], g.y[b]}, f);  // b gets -F
        ++s.coordination[b];
    }
    for (std::size_t i = 0; i < g.size(); ++i) {
        const double area = g.area(i);
        if (area > 0) s.pressure[i] = -0.5 * trace[i] / area;
    }
    return s;
}

double maxForce(const analysis::ContactFrame& c) {
    double m = 0;
    for (std::size_t k = 0; k < c.size(); ++k) {
        const double f = std::hypot(c.fx[k], c.fy[k]);
        if (std::isfinite(f)) m = std::max(m, f);
    }
    return m;
}

void drawForces(cairo_t* cr, const RenderLayout& L, const analysis::GrainFrame& g,
                const analysis::ContactFrame& c, const GrainIndex& index, const ForceStyle& style) {
    if (!(style.maxForce > 0)) return;
    // Widths are quantised to kLevels steps: one cairo path per step is stroked at once (1e5
    // strokes one by one cost ~10x more).
    constexpr int kLevels = 32;
    std::array<bool, kLevels> used{};
    const double step = std::max(style.maxWidth - style.minWidth, 0.0) / (kLevels - 1);
    std::vector<int> level(c.size(), -1);
    for (std::size_t k = 0; k < c.size(); ++k) {
        const double f = std::hypot(c.fx[k], c.fy[k]) / style.maxForce;
        if (!(f >= style.skipBelow)) continue;
        const double w = std::max(style.minWidth, std::min(f, 1.0) * style.maxWidth);
        level[k] =
            step > 0 ? std::clamp(static_cast<int>(std::lround((w - style.minWidth) / step)), 0, kLevels - 1)
                     : 0;
        used[static_cast<std::size_t>(level[k])] = true;
    }
    cairo_save(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_BEVEL);  // no miter spikes at the contact point
    const auto centroid = [&](std::int64_t id, Vec2& out) {
        const std::size_t i = index.find(id);
        if (i == GrainIndex::kNone) return false;
        out = L.toPixel({g.x[i], g.y[i]});
        return true;
    };
    for (int lv = 0; lv < kLevels; ++lv) {
        if (!used[static_cast<std::size_t>(lv)]) continue;
        cairo_new_path(cr);
        for (std::size_t k = 0; k < c.size(); ++k) {
            if (level[k] != lv) continue;
            const Vec2 p = L.toPixel({c.px[k], c.py[k]});
            Vec2 a, b;
            const bool hasA = centroid(c.a[k], a), hasB = c.b[k] >= 0 && centroid(c.b[k], b);
            if (hasA) {  // a pair is one polyline a -> contact point -> b (same width both halves)
                cairo_move_to(cr, a.x, a.y);
                cairo_line_to(cr, p.x, p.y);
                if (hasB) cairo_line_to(cr, b.x, b.y);
            } else if (hasB) {
                cairo_move_to(cr, b.x, b.y);
                cairo_line_to(cr, p.x, p.y);
            }
        }
        cairo_set_line_width(cr, style.minWidth + lv * step);
        cairo_stroke(cr);
    }
    cairo_restore(cr);
}

}  // namespace granulab::app::render
