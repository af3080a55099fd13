// SPDX-License-Identifier: MIT
// A state as one PostScript picture (app/render_picture.hpp).
#include "app/render_picture.hpp"

#include <cairo-ps.h>
#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "app/render.hpp"
#include "app/render_colors.hpp"
#include "app/render_scene.hpp"

namespace granulab::app {

bool writePicturePs(const std::string& path, const analysis::GrainFrame& g, const analysis::WallSegments& w,
                    double time, int widthPoints) {
    using namespace render;
    constexpr double inf = std::numeric_limits<double>::infinity();
    Vec2 lo{inf, inf}, hi{-inf, -inf};
    const auto add = [&](Vec2 p, double r) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(r)) return;
        lo = {std::min(lo.x, p.x - r), std::min(lo.y, p.y - r)};
        hi = {std::max(hi.x, p.x + r), std::max(hi.y, p.y + r)};
    };
    std::vector<double> radii(g.radius);
    for (std::size_t i = 0; i < g.size(); ++i) {
        if (g.isPolygon(i))
            for (std::size_t c = g.cornerStart[i]; c < g.cornerStart[i + 1]; ++c) add(g.corners[c], 0);
        else
            add({g.x[i], g.y[i]}, g.radius[i]);
    }
    for (std::size_t k = 0; k < w.size(); ++k) {
        add(w.a[k], 0);
        add(w.b[k], 0);
    }
    const RenderLayout L = makeLayout(lo, hi, widthPoints);
    double typical = 0;  // median radius: the wall stroke width
    if (!radii.empty()) {
        std::nth_element(radii.begin(), radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2),
                         radii.end());
        typical = radii[radii.size() / 2];
    }
    double idLo = 0, idHi = 1;  // colour by id, as gc2d's display
    if (g.size() > 0) {
        idLo = static_cast<double>(*std::min_element(g.id.begin(), g.id.end()));
        idHi = static_cast<double>(*std::max_element(g.id.begin(), g.id.end())) + 1;
    }
    const ColorScale scale(ColorMode::Id, idLo, idHi);
    std::vector<Rgb> fill(g.size());
    for (std::size_t i = 0; i < g.size(); ++i) fill[i] = scale.colour(static_cast<double>(g.id[i]));

    cairo_surface_t* surface = cairo_ps_surface_create(path.c_str(), L.width, L.height);
    cairo_t* cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_save(cr);
    clipToScene(cr, L);
    drawGrains(cr, L, g, fill, true);
    drawWalls(cr, L, w, makeStrokeStyle(L, typical));
    cairo_restore(cr);
    drawHeader(cr, L, fmt::format("t = {:.6g} s", time), scale);
    cairo_show_page(cr);
    cairo_destroy(cr);
    cairo_surface_finish(surface);
    const bool ok = cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS;
    cairo_surface_destroy(surface);
    return ok;
}

}  // namespace granulab::app
