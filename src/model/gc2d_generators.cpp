// SPDX-License-Identifier: MIT
// gc2d generator geometry (model/gc2d_generators.hpp; gc2d spec section 6.5).
#include "model/gc2d_generators.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granulab::model {

Real nearestSiteDistance(const BlockDef& b) noexcept {
    using L = BlockDef::Lattice;
    switch (b.lattice) {
        case L::Hexagonal:
        case L::Square:
            return b.spacing > 0 ? b.spacing : 0;
        case L::Rect:
            return b.grid.x > 0 && b.grid.y > 0 ? std::min(b.grid.x, b.grid.y) : 0;
        case L::Fcc:
            return b.grid.x > 0 && b.grid.y > 0
                       ? std::min({b.grid.x, 2 * b.grid.y, std::hypot(0.5 * b.grid.x, b.grid.y)})
                       : 0;
        case L::Random:
            return 0;
    }
    return 0;
}

std::optional<HeapGrain> heapGrain(const HeapDef& h, const std::vector<ShapeDef>& shapes) {
    HeapGrain g;
    if (h.size.x != 0 || h.size.y != 0) {  // plain rectangles a x b
        if (!(h.size.x > 0 && h.size.y > 0 && std::isfinite(h.size.x) && std::isfinite(h.size.y)))
            return std::nullopt;
        g.diskLike = false;
        g.width = h.size.x;
        g.height = h.size.y;
        return g;
    }
    if (h.shape == "disk") {
        if (!(h.radius > 0 && std::isfinite(h.radius))) return std::nullopt;
        g.width = g.height = 2 * h.radius;
        return g;
    }
    const auto it =
        std::find_if(shapes.begin(), shapes.end(), [&](const ShapeDef& s) { return s.name == h.shape; });
    if (it == shapes.end()) return std::nullopt;
    g.shape = &*it;
    if (it->kind == "rectangle") {
        if (!(it->size.x > 0 && it->size.y > 0 && std::isfinite(it->size.x) && std::isfinite(it->size.y)))
            return std::nullopt;
        g.diskLike = false;
        g.width = it->size.x;
        g.height = it->size.y;
        return g;
    }
    if (it->kind == "regular") {
        if (!(it->radius > 0 && std::isfinite(it->radius))) return std::nullopt;
        g.width = g.height = 2 * it->radius;
        return g;
    }
    return std::nullopt;
}

HeapPitch heapPitch(const HeapDef& h, const HeapGrain& g) noexcept {
    HeapPitch p;
    p.along = g.width + h.gap.x;
    p.rows = g.height + h.gap.y;
    if (h.stacking == HeapDef::Stacking::Hexagonal && g.diskLike) {
        const Real contact = g.width + h.gap.y;  // 2 r + gap y
        const Real q2 = contact * contact - 0.25 * p.along * p.along;
        p.rows = q2 > 0 ? std::sqrt(q2) : 0;
    }
    return p;
}

Real heapMaxSlope(const HeapDef& h, const HeapGrain& g) noexcept {
    return h.stacking == HeapDef::Stacking::Hexagonal ? std::atan(2 * g.height / g.width) : 0.5 * kPi;
}

Real heapMaxGapX(const HeapDef& h, const HeapGrain& g) noexcept {
    if (h.stacking == HeapDef::Stacking::Rectangular) return std::numeric_limits<Real>::infinity();
    if (!g.diskLike) return g.width;
    const Real r = 0.5 * g.width;
    const Real contact = 2 * r + h.gap.y;
    return 2 * std::sqrt(std::max<Real>(contact * contact - r * r, 0)) - 2 * r;
}

double heapSiteEstimate(const HeapDef& h, const std::vector<ShapeDef>& shapes) noexcept {
    const auto g = heapGrain(h, shapes);
    if (!g || !(h.xRight > h.xLeft) || !(h.slope > 0 && h.slope < 0.5 * kPi) || !(h.gap.x >= 0) ||
        !(h.gap.y >= 0))
        return 0;
    const HeapPitch p = heapPitch(h, *g);
    if (!(p.along > 0 && p.rows > 0)) return 0;
    const double length = h.xRight - h.xLeft;
    const double top = 0.5 * length * std::tan(h.slope);  // height of the slope lines' apex
    const double rows = std::max(0.0, std::floor(top / p.rows)) + 1;
    return rows * (length / p.along + 2);
}

}  // namespace granulab::model
