// SPDX-License-Identifier: MIT
// Regular piles of gc2d's Perl heap library (heap.pm, spec section 6.5 and 8.4): hexagonal or
// rectangular stacks of equal grains between x_left and x_right on the base y0 with flanks of
// slope psi. No random draws: a heap is the same for every seed.
//
// Why a support rule besides the slope lines: the slope lines alone let the end grain of a
// shifted (hexagonal) row stick out beyond the row below when psi is close to the limit
// arctan(2 height / width), and disks are stacked closer than their width (rows
// sqrt((2r + gap)^2 - pitch^2/4) apart), so for them the slope test alone overhangs above
// arctan(sqrt 3). Requiring both grains below keeps every pile free of overhangs; below that
// slope it never removes a grain.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dem/generate.hpp"
#include "geom/polygon.hpp"
#include "model/grain_shapes.hpp"

namespace granulab::dem {

using model::HeapDef;
using model::HeapGrain;

std::vector<Vec2> heapSites(const HeapDef& h, const HeapGrain& g) {
    std::vector<Vec2> sites;
    const model::HeapPitch p = model::heapPitch(h, g);
    if (!(p.along > 0 && p.rows > 0 && h.xRight > h.xLeft && h.slope > 0 && h.slope < 0.5 * kPi) ||
        !std::isfinite(h.base))
        return sites;
    const bool hex = h.stacking == HeapDef::Stacking::Hexagonal;
    const Real middle = 0.5 * (h.xLeft + h.xRight);
    const Real halfLength = 0.5 * (h.xRight - h.xLeft);
    const Real tanSlope = std::tan(h.slope);
    const Real tol = 1e-9 * std::max(p.along, p.rows);
    long lo = 0, hi = -1;  // filled indices of the row below
    for (long k = 0;; ++k) {
        const Real y = h.base + 0.5 * g.height + static_cast<Real>(k) * p.rows;
        const Real reach = halfLength - (y - h.base) / tanSlope;  // allowed |x - middle| of a centre
        if (reach < -tol) break;
        const Real shift = hex && (k % 2 != 0) ? 0.5 : 0.0;  // x = middle + (i + shift) * along
        long first = static_cast<long>(std::ceil(-(reach + tol) / p.along - shift));
        long last = static_cast<long>(std::floor((reach + tol) / p.along - shift));
        if (k > 0) {
            if (!hex) {  // the grain directly below
                first = std::max(first, lo);
                last = std::min(last, hi);
            } else if (shift > 0) {  // between grains i and i + 1 of the row below
                first = std::max(first, lo);
                last = std::min(last, hi - 1);
            } else {  // between grains i - 1 and i of the row below
                first = std::max(first, lo + 1);
                last = std::min(last, hi);
            }
        }
        if (first > last) break;
        for (long i = first; i <= last; ++i)
            sites.push_back({middle + (static_cast<Real>(i) + shift) * p.along, y});
        lo = first;
        hi = last;
    }
    return sites;
}

void generateHeaps(const model::SceneDef& scene, const std::vector<std::string>& materialNames,
                   InitialParticles& out, Diagnostics& diags) {
    for (std::size_t k = 0; k < scene.heaps.size(); ++k) {
        const HeapDef& h = scene.heaps[k];
        const auto grain = model::heapGrain(h, scene.shapes);
        const double estimate = model::heapSiteEstimate(h, scene.shapes);
        if (!grain || estimate == 0) continue;  // invalid: reported by validate()
        const std::string key = fmt::format("heap[{}]", k);
        if (estimate > 2e9) {
            diags.error(h.loc, key,
                        fmt::format("heap would create about {:.3g} grains (limit 2e9); check x_range, slope "
                                    "and the grain size",
                                    estimate));
            continue;
        }
        const std::vector<Vec2> sites = heapSites(h, *grain);
        if (sites.empty()) {
            diags.error(
                h.loc, key,
                fmt::format("the heap places no grain: x_range [{}, {}] m with slope {} rad leaves no "
                            "room for a grain {:.6g} m wide and {:.6g} m high; widen x_range or steepen "
                            "the slope",
                            h.xLeft, h.xRight, h.slope, grain->width, grain->height));
            continue;
        }
        InitialParticle proto;
        proto.radius = 0.5 * grain->width;
        const auto m = std::find(materialNames.begin(), materialNames.end(), h.material);
        proto.material = m == materialNames.end() ? 0 : static_cast<std::uint32_t>(m - materialNames.begin());
        if (grain->shape || !grain->diskLike) {  // a [[shape]] or plain rectangles: one pool entry
            const auto corners = grain->shape
                                     ? model::deterministicCorners(*grain->shape)
                                     : std::optional(model::rectangle(grain->width, grain->height, 0));
            if (!corners || !geom::checkConvexPolygon(*corners).ok()) continue;  // reported by validate()
            proto.shape = out.shapes.add(*corners);
            proto.radius = out.shapes.circumradius[proto.shape];
            proto.angle = grain->shape ? grain->shape->rotation : 0;  // rectangles: 0 (checked)
        }
        proto.origin = static_cast<std::uint32_t>(out.origins.size());
        out.origins.push_back(h.loc);
        for (const Vec2& site : sites) {
            InitialParticle ip = proto;
            ip.position = site;  // rectangles and regular polygons: the centroid is the centre
            out.particles.push_back(ip);
        }
    }
}

}  // namespace granulab::dem
