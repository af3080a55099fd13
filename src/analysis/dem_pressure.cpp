// SPDX-License-Identifier: MIT
// Wall and floor pressure of a DEM snapshot (gc2d spec section 7 items 1-2, Eqs. 2.36-2.40).
//
// Sign: (fx, fy) of a wall contact is the force ON the grain (analysis/dem_frame.hpp), so the wall
// feels minus it, and the grains push the wall along -n_in: the pressure (1/l) sum n_in . F_i is
// positive for a loaded wall.
#include "analysis/dem_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "analysis/dem_geometry.hpp"
#include "analysis/table_note.hpp"

namespace granulab::analysis {

namespace {

constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();

void checkScale(const PileScale& s, const std::string& who) {
    if (!(s.rho > 0) || !(s.g > 0) || !(s.h > 0) || !(s.x1 > s.x0))
        throw std::invalid_argument(who + ": the pile scale needs rho > 0, g > 0, h > 0 and x1 > x0");
}

}  // namespace

WallPressure wallPressure(const ContactFrame& contacts, const WallSegments& segments,
                          const WallPressureParams& params) {
    const WallGeometry geometry = wallGeometry(segments, params.walls, "wallPressure");
    WallPressure r;
    r.length = geometry.length;
    r.straight = geometry.straight;
    Vec2 onGrains{};     // [N]
    Real normalSum = 0;  // [N]
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        if (!isSelectedWall(params.walls, contacts.wall[k])) continue;
        onGrains += Vec2{contacts.fx[k], contacts.fy[k]};
        normalSum += contacts.fn[k];
        ++r.contacts;
    }
    r.force = -onGrains;
    r.forcePerLength = r.force / r.length;
    r.normalPressure = normalSum / r.length;  // [N/m]
    if (geometry.straight) {
        r.normal = inwardNormal(geometry, contacts, params.walls, params.inwardNormal);
        r.pressure = dot(r.normal, onGrains) / r.length;  // gc2d Eq. 2.36/2.37
    } else {
        r.normal = {kNaN, kNaN};
        r.pressure = kNaN;
    }
    return r;
}

Table toTable(const WallPressure& result, std::string name) {
    Table t;
    t.name = std::move(name);
    const std::pair<const char*, const char*> heads[] = {{"Fx", "N"},     {"Fy", "N"},      {"l", "m"},
                                                         {"Fx/l", "N/m"}, {"Fy/l", "N/m"},  {"p", "N/m"},
                                                         {"p_n", "N/m"},  {"contacts", "1"}};
    for (const auto& [n, u] : heads) t.add(n, u);
    const Real row[] = {
        result.force.x,          result.force.y,  result.length,         result.forcePerLength.x,
        result.forcePerLength.y, result.pressure, result.normalPressure, static_cast<Real>(result.contacts)};
    for (std::size_t c = 0; c < t.columns.size(); ++c) t.columns[c].values.push_back(row[c]);
    t.notes.push_back(
        "force on the wall = -(sum of the contact forces on the grains); p = (1/l) sum n_in . F "
        "(gc2d Eq. 2.36/2.37), p_n = (1/l) sum fn");
    if (!result.straight) t.notes.push_back("the wall is bent: p is undefined (NaN), use Fx/l, Fy/l or p_n");
    t.notes.push_back(noteLine("normal_x", result.normal.x));
    t.notes.push_back(noteLine("normal_y", result.normal.y));
    return t;
}

PressureProfile pressureProfile(const ContactFrame& contacts, const WallSegments& segments,
                                const PressureProfileParams& params) {
    const std::string who = "pressureProfile";
    if (!(params.halfWidth > 0) || !std::isfinite(params.halfWidth))
        throw std::invalid_argument(who + ": halfWidth b must be finite and > 0");
    if (!(params.step > 0) || !std::isfinite(params.step))
        throw std::invalid_argument(who + ": step must be finite and > 0");
    if (params.movingAverage == 0 || params.movingAverage % 2 == 0)
        throw std::invalid_argument(who + ": movingAverage M must be odd and >= 1");
    if (params.scale) checkScale(*params.scale, who);
    const WallGeometry geometry = wallGeometry(segments, params.walls, who);
    if (!geometry.straight)
        throw std::invalid_argument(
            who + ": the selected wall segments are not parallel; choose one straight wall");
    const Real from = params.from.value_or(geometry.sMin), to = params.to.value_or(geometry.sMax);  // [m]
    if (!std::isfinite(from) || !std::isfinite(to) || from > to)
        throw std::invalid_argument(who + ": the window range needs finite from <= to");
    const Real windows = std::floor((to - from) / params.step * (1 + 1e-12)) + 1;
    if (windows > 1e7) throw std::invalid_argument(who + ": more than 1e7 windows; use a larger step");

    PressureProfile r;
    r.tangent = geometry.tangent;
    r.normal = inwardNormal(geometry, contacts, params.walls, params.inwardNormal);
    r.halfWidth = params.halfWidth;
    r.step = params.step;
    r.movingAverage = params.movingAverage;
    r.scale = params.scale;

    // Contacts sorted by their wall coordinate, with prefix sums of n_in . F [N].
    std::vector<std::pair<Real, Real>> load;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        if (!isSelectedWall(params.walls, contacts.wall[k])) continue;
        const Real s = contacts.px[k] * r.tangent.x + contacts.py[k] * r.tangent.y;  // [m]
        load.emplace_back(s, contacts.fx[k] * r.normal.x + contacts.fy[k] * r.normal.y);
    }
    std::sort(load.begin(), load.end());
    std::vector<Real> prefix(load.size() + 1, 0);
    for (std::size_t k = 0; k < load.size(); ++k) prefix[k + 1] = prefix[k] + load[k].second;

    const auto n = static_cast<std::size_t>(windows);
    r.x.resize(n);
    r.p.resize(n);
    r.contacts.resize(n);
    const Real width = 2 * params.halfWidth;  // [m]
    for (std::size_t w = 0; w < n; ++w) {
        const Real x = from + static_cast<Real>(w) * params.step;
        const auto lo = std::lower_bound(load.begin(), load.end(), x - params.halfWidth,
                                         [](const std::pair<Real, Real>& c, Real v) { return c.first < v; });
        const auto hi = std::upper_bound(load.begin(), load.end(), x + params.halfWidth,
                                         [](Real v, const std::pair<Real, Real>& c) { return v < c.first; });
        const auto i0 = static_cast<std::size_t>(lo - load.begin()),
                   i1 = static_cast<std::size_t>(hi - load.begin());
        r.x[w] = x;
        r.contacts[w] = i1 - i0;
        r.p[w] = (prefix[i1] - prefix[i0]) / width;  // gc2d Eq. 2.38
        if (r.contacts[w] < params.minContacts) ++r.sparseWindows;
    }

    // Centred moving average over M windows, truncated at the ends.
    const std::size_t half = params.movingAverage / 2;
    std::vector<Real> pPrefix(n + 1, 0);
    for (std::size_t w = 0; w < n; ++w) pPrefix[w + 1] = pPrefix[w] + r.p[w];
    r.pAverage.resize(n);
    for (std::size_t w = 0; w < n; ++w) {
        const std::size_t a = w >= half ? w - half : 0, b = std::min(n, w + half + 1);
        r.pAverage[w] = (pPrefix[b] - pPrefix[a]) / static_cast<Real>(b - a);
    }

    if (params.scale) {
        const PileScale& s = *params.scale;
        const Real d = s.x1 - s.x0, pScale = s.rho * s.g * s.h;  // [m], [N/m]
        r.xOverD.resize(n);
        r.pOverRhoGH.resize(n);
        r.pAverageOverRhoGH.resize(n);
        for (std::size_t w = 0; w < n; ++w) {
            r.xOverD[w] = (r.x[w] - s.x0) / d;
            r.pOverRhoGH[w] = r.p[w] / pScale;
            r.pAverageOverRhoGH[w] = r.pAverage[w] / pScale;
        }
    }
    if (load.empty()) r.notes.push_back("warning: no contact with the selected walls; p = 0 everywhere");
    if (r.sparseWindows > 0)
        r.notes.push_back(
            fmt::format("warning: {} of {} windows hold fewer than {} contacts (rule of thumb: "
                        "10-20 per window, gc2d spec 7 item 2)",
                        r.sparseWindows, n, params.minContacts));
    return r;
}

Table toTable(const PressureProfile& profile, std::string name) {
    Table t;
    t.name = std::move(name);
    t.add("x", "m").values = profile.x;
    t.add("p", "N/m").values = profile.p;
    t.add("p_avg", "N/m").values = profile.pAverage;
    t.add("contacts", "1").values.assign(profile.contacts.begin(), profile.contacts.end());
    if (profile.scale) {
        t.add("x/d", "1").values = profile.xOverD;
        t.add("p/(rho g h)", "1").values = profile.pOverRhoGH;
        t.add("p_avg/(rho g h)", "1").values = profile.pAverageOverRhoGH;
    }
    t.notes.push_back(
        "p(x) = (1/2b) sum n_in . F_i over contacts with x - b <= x_i <= x + b (gc2d Eq. 2.38); "
        "x = contact point . wall direction");
    t.notes.push_back(noteLine("half_width_b", profile.halfWidth, "m"));
    t.notes.push_back(noteLine("step", profile.step, "m"));
    t.notes.push_back(noteLine("moving_average_windows", static_cast<Real>(profile.movingAverage)));
    t.notes.push_back(noteLine("normal_x", profile.normal.x));
    t.notes.push_back(noteLine("normal_y", profile.normal.y));
    if (profile.scale) {
        t.notes.push_back(noteLine("rho", profile.scale->rho, "kg/m^2"));
        t.notes.push_back(noteLine("g", profile.scale->g, "m/s^2"));
        t.notes.push_back(noteLine("h", profile.scale->h, "m"));
        t.notes.push_back(noteLine("x0", profile.scale->x0, "m"));
        t.notes.push_back(noteLine("x1", profile.scale->x1, "m"));
    }
    t.notes.push_back(noteLine("sparse_windows", static_cast<Real>(profile.sparseWindows)));
    for (const std::string& n : profile.notes) t.notes.push_back(n);
    return t;
}

PileScale measurePileScale(const GrainFrame& grains, const ContactFrame& contacts,
                           const WallSegments& segments, const std::vector<std::int32_t>& walls, Real rho,
                           Real g, bool allGrains) {
    const std::string who = "measurePileScale";
    if (!(rho > 0) || !(g > 0)) throw std::invalid_argument(who + ": rho and g must be > 0");
    const WallGeometry geometry = wallGeometry(segments, walls, who);
    if (!geometry.straight)
        throw std::invalid_argument(who + ": the selected wall segments are not parallel");
    const Vec2 t = geometry.tangent, n = inwardNormal(geometry, contacts, walls);

    std::vector<char> foot(grains.size(), allGrains ? 1 : 0);
    if (!allGrains) {
        const auto index = indexById(grains);
        for (std::size_t k = 0; k < contacts.size(); ++k) {
            if (!isSelectedWall(walls, contacts.wall[k])) continue;
            const auto it = index.find(contacts.a[k]);
            if (it != index.end()) foot[it->second] = 1;
        }
    }
    PileScale s;
    s.rho = rho;
    s.g = g;
    // Level of the wall along n: every segment of a straight wall is parallel; take the one nearest
    // the grains (largest level) so a thick floor of two segment lines measures from its top.
    Real level = -std::numeric_limits<Real>::infinity();
    for (std::size_t k = 0; k < segments.size(); ++k)
        if (isSelectedWall(walls, segments.wall[k])) level = std::max(level, dot(segments.a[k], n));
    Real top = -std::numeric_limits<Real>::infinity();
    s.x0 = std::numeric_limits<Real>::infinity();
    s.x1 = -s.x0;
    for (std::size_t i = 0; i < grains.size(); ++i) {
        top = std::max(top, grainReach(grains, i, n));
        if (!foot[i]) continue;
        s.x0 = std::min(s.x0, -grainReach(grains, i, -t));
        s.x1 = std::max(s.x1, grainReach(grains, i, t));
    }
    s.h = grains.size() > 0 ? top - level : kNaN;
    if (!(s.x1 >= s.x0)) s.x0 = s.x1 = kNaN;  // no grain touches the wall: the data has no foot
    return s;
}

}  // namespace granulab::analysis
