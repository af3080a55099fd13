// SPDX-License-Identifier: MIT
// Def-level checks of the scene machines (docs/scene-format.md; gc2d spec 6.1-6.7, cfddem spec
// 4.1-4.3): wall kinds and drivers, drums, sources, inlets, outlets, boundaries, the gravity
// schedule and law changes. Every message names the key, its value and the allowed range.
#include "io/validate_machines.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/suggest.hpp"
#include "geom/polygon.hpp"
#include "io/range_checks.hpp"
#include "model/size_bounds.hpp"

namespace granulab::io {

namespace {

struct Check {
    Diagnostics& d;
    void positive(const SourceLoc& loc, const std::string& key, Real v, const std::string& unit) {
        checkPositive(d, loc, key, v, unit);
    }
    void nonNegative(const SourceLoc& loc, const std::string& key, Real v, const std::string& unit) {
        checkNonNegative(d, loc, key, v, unit);
    }
    void finite(const SourceLoc& loc, const std::string& key, std::initializer_list<Real> vs) {
        for (const Real v : vs)
            if (!std::isfinite(v)) {
                d.error(loc, key, fmt::format("must be a finite number, got {}", v));
                return;
            }
    }
    void window(const SourceLoc& loc, const std::string& key, Real from, Real to) {
        if (!(from >= 0) || !(to >= from) || std::isnan(to))
            d.error(loc, key,
                    fmt::format("window [{}, {}] s must have 0 <= from <= to (a reversed window is an error)",
                                from, to));
    }
    void material(const SourceLoc& loc, const std::string& key, const std::string& name,
                  const std::vector<std::string>& names) {
        if (std::find(names.begin(), names.end(), name) == names.end())
            d.error(loc, key,
                    fmt::format("unknown material '{}'{}; defined: {}", name, didYouMean(name, names),
                                joinList(names)));
    }
};

void checkWallMotion(Check& c, const model::WallDef& w, const std::string& key) {
    const bool vib = !w.vibType.empty(), piston = w.pistonForce.has_value();
    const bool moving = w.velocity.x != 0 || w.velocity.y != 0, rotating = w.omega != 0;
    if (vib + piston + moving + rotating > 1)
        c.d.error(w.loc, key,
                  "a wall has at most one motion: `velocity`, vibration (`vib_*`), piston (`piston_*`) or "
                  "rotation (`omega`); a wall cannot be both a piston and a vibrating wall (gc2d 6.3)");
    c.finite(w.loc, key + ".offset", {w.offset.x, w.offset.y});
    c.finite(w.loc, key + ".angle", {w.angle});
    c.finite(w.loc, key + ".velocity", {w.velocity.x, w.velocity.y});
    c.finite(w.loc, key + ".surface_velocity", {w.surfaceVelocity.x, w.surfaceVelocity.y});
    if (vib) {
        c.positive(w.loc, key + ".vib_width", w.vibWidth, "m");
        c.positive(w.loc, key + ".vib_frequency", w.vibFrequency, "1/s");
        c.finite(w.loc, key + ".vib_direction", {w.vibDirection});
        c.window(w.loc, key + ".vib_window", w.vibFrom, w.vibTo);
    } else if (w.vibWidth != 0 || w.vibFrequency != 0) {
        c.d.error(w.loc, key + ".vib_type",
                  "vib_width / vib_frequency need vib_type = \"cosine\" | \"sawtooth\" | \"tapping\" | "
                  "\"triangle\"");
    }
    if (piston) {
        if (!std::isfinite(*w.pistonForce) || *w.pistonForce == 0)
            c.d.error(w.loc, key + ".piston_force",
                      fmt::format("must be a finite non-zero force [N], got {}", *w.pistonForce));
        c.positive(w.loc, key + ".piston_v_max", w.pistonMaxSpeed, "m/s");
        c.nonNegative(w.loc, key + ".piston_gain", w.pistonGain, "m/(N s)");
        c.nonNegative(w.loc, key + ".piston_from", w.pistonFrom, "s");
        c.finite(w.loc, key + ".piston_direction", {w.pistonDirection});
    }
    if (rotating) {
        c.finite(w.loc, key + ".omega", {w.omega});
        if (w.pivot) c.finite(w.loc, key + ".pivot", {w.pivot->x, w.pivot->y});
    }
    if (w.kind == "polygon") {
        std::vector<Vec2> p = w.points;
        if (p.size() >= 3 && geom::polygonMass(p).area < 0) std::reverse(p.begin(), p.end());
        const auto problem = geom::checkConvexPolygon(p);
        if (!problem.ok())
            c.d.error(
                w.loc, key + ".points",
                fmt::format("a polygon wall must be a convex polygon (either orientation); its corners are "
                            "{} (corner {}); use kind = \"polyline\" with closed = true for other shapes",
                            problem.what, problem.corner));
    }
}

void checkInsert(Check& c, const model::SceneDef& sc, const model::InsertDef& in, const SourceLoc& loc,
                 const std::string& key, const std::vector<std::string>& names) {
    c.material(loc, key + ".material", in.material, names);
    for (const auto& m : sc.materials)
        if (m.name == in.material && !(m.density > 0))
            c.d.error(loc, key + ".material",
                      fmt::format("material '{}' needs density > 0 for inserted particles", in.material));
    if (in.shape == "disk") {
        const auto& r = in.radius;
        using K = model::SizeDistDef::Kind;
        if (r.kind == K::Constant)
            c.positive(loc, key + ".radius", r.value, "m");
        else {
            c.positive(loc, key + ".radius.min", r.min, "m");
            if (!(r.max >= r.min))
                c.d.error(loc, key + ".radius.max",
                          fmt::format("max ({}) must be >= min ({})", r.max, r.min));
        }
    } else {
        std::vector<std::string> shapes = {"disk"};
        for (const auto& s : sc.shapes) shapes.push_back(s.name);
        if (std::find(shapes.begin(), shapes.end(), in.shape) == shapes.end())
            c.d.error(loc, key + ".shape",
                      fmt::format("unknown shape '{}'{}; defined: {}", in.shape, didYouMean(in.shape, shapes),
                                  joinList(shapes)));
        if (in.radius.value != 0 || in.radius.max != 0)
            c.d.error(loc, key + ".radius",
                      "a polygon shape takes its size from its [[shape]]; remove `radius`");
    }
    c.finite(loc, key + ".velocity", {in.velocity.x, in.velocity.y, in.angle, in.omega});
    if (in.attempts < 1 || in.attempts > 1000)
        c.d.error(loc, key + ".attempts", fmt::format("must be in [1, 1000], got {}", in.attempts));
}

/// Largest bounding radius an InsertDef can produce [m] (0 if unknown).
Real insertRadius(const model::SceneDef& sc, const model::InsertDef& in) {
    if (in.shape == "disk") return model::maxRadius(in.radius);
    for (const auto& s : sc.shapes)
        if (s.name == in.shape) return s.size.x > 0 ? std::max(s.size.x, s.size.y) : s.radius;
    return 0;
}

void checkEdge(Check& c, const SourceLoc& loc, const std::string& key, Vec2 a, Vec2 b) {
    c.finite(loc, key, {a.x, a.y, b.x, b.y});
    if (!(norm2(b - a) > 0))
        c.d.error(loc, key,
                  fmt::format("the edge [[{}, {}], [{}, {}]] has zero length; allowed: two distinct points",
                              a.x, a.y, b.x, b.y));
}

void checkInletRate(Check& c, const model::SceneDef& sc, const SourceLoc& loc, const std::string& key, Vec2 a,
                    Vec2 b, Real rate, const model::InsertDef& in) {
    c.positive(loc, key + ".rate", rate, "1/s");
    if (rate > 0 && sc.dem.dt > 0 && rate * sc.dem.dt > 1)
        c.d.error(loc, key + ".rate",
                  fmt::format("rate {} /s emits more than one particle per step (dt = {} s); allowed (0, "
                              "1/dt] = (0, {:.6g}]",
                              rate, sc.dem.dt, 1 / sc.dem.dt));
    const Vec2 d = b - a;
    if (!(norm2(d) > 0)) return;
    const Vec2 nOut = perp(d) / norm(d);
    // cfddem 4.2 pre-run checks: (a) into the domain, (b) fast enough not to hit the previous particle.
    if (!(dot(in.velocity, nOut) < 0))
        c.d.error(
            loc, key + ".velocity",
            fmt::format(
                "the inlet velocity ({}, {}) m/s must point into the domain, which lies to the right of "
                "the edge from its first to its second point (v . n_out < 0 with n_out = ({:.3g}, {:.3g}))",
                in.velocity.x, in.velocity.y, nOut.x, nOut.y));
    const Real r = insertRadius(sc, in);
    if (rate > 0 && r > 0 && norm(in.velocity) < 2 * r * rate)
        c.d.error(
            loc, key + ".velocity",
            fmt::format(
                "inlet speed {:.4g} m/s is below 2 R pps = {:.4g} m/s: a new particle would hit the previous "
                "one (cfddem 4.2 check b); raise the speed or lower the rate",
                norm(in.velocity), 2 * r * rate));
}

}  // namespace

void checkMachineDefs(const model::SceneDef& sc, Diagnostics& d, const std::vector<std::string>& names) {
    Check c{d};
    for (std::size_t k = 0; k < sc.walls.size(); ++k)
        checkWallMotion(c, sc.walls[k], fmt::format("wall[{}]", k));
    const auto& m = sc.machines;
    for (std::size_t k = 0; k < m.drums.size(); ++k) {
        const auto& dr = m.drums[k];
        const std::string key = fmt::format("drum[{}]", k);
        c.positive(dr.loc, key + ".inner_radius", dr.innerRadius, "m");
        c.positive(dr.loc, key + ".thickness", dr.thickness, "m");
        if (dr.count < 3 || dr.count > 100000)
            d.error(dr.loc, key + ".count", fmt::format("must be in [3, 100000], got {}", dr.count));
        c.finite(dr.loc, key + ".surface_speed", {dr.surfaceSpeed, dr.centre.x, dr.centre.y});
        c.material(dr.loc, key + ".material", dr.material, names);
    }
    for (std::size_t k = 0; k < m.sources.size(); ++k) {
        const auto& s = m.sources[k];
        const std::string key = fmt::format("source[{}]", k);
        c.finite(s.loc, key + ".position", {s.position.x, s.position.y});
        c.nonNegative(s.loc, key + ".width", s.width, "m");
        if (s.widthEnd) c.nonNegative(s.loc, key + ".width_end", *s.widthEnd, "m");
        c.positive(s.loc, key + ".interval", s.interval, "s");
        if (s.interval > 0 && sc.dem.dt > 0 && s.interval < sc.dem.dt)
            d.error(
                s.loc, key + ".interval",
                fmt::format(
                    "interval {} s is shorter than the time step dt = {} s (more than one drop per step); "
                    "allowed [dt, inf) = [{}, inf)",
                    s.interval, sc.dem.dt, sc.dem.dt));
        c.window(s.loc, key + ".from", s.from, s.to);
        if (s.interval > 0 && s.to > s.from && (s.to - s.from) / s.interval > 1e9)
            d.error(s.loc, key + ".interval",
                    fmt::format("the window holds {:.3g} drops; allowed at most 1e9",
                                (s.to - s.from) / s.interval));
        checkInsert(c, sc, s.insert, s.loc, key, names);
        // A source must sit inside the walls: its drop point lies in the bounding box of some wall.
        if (!sc.walls.empty() || !m.drums.empty() || !m.boundaries.empty()) {
            Real xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
            for (const auto& w : sc.walls)
                for (const Vec2 p : w.points) {
                    xmin = std::min(xmin, p.x + w.offset.x);
                    xmax = std::max(xmax, p.x + w.offset.x);
                    ymin = std::min(ymin, p.y + w.offset.y);
                    ymax = std::max(ymax, p.y + w.offset.y);
                }
            for (const auto& dr : m.drums) {
                const Real r = dr.innerRadius;
                xmin = std::min(xmin, dr.centre.x - r);
                xmax = std::max(xmax, dr.centre.x + r);
                ymin = std::min(ymin, dr.centre.y - r);
                ymax = std::max(ymax, dr.centre.y + r);
            }
            for (const auto& b : m.boundaries)
                for (const Vec2 p : b.points) {
                    xmin = std::min(xmin, p.x);
                    xmax = std::max(xmax, p.x);
                    ymin = std::min(ymin, p.y);
                    ymax = std::max(ymax, p.y);
                }
            const Real half = 0.5 * std::max(s.width, s.widthEnd.value_or(s.width));
            if (s.placement == "abs" &&
                (s.position.x + half < xmin || s.position.x - half > xmax ||
                 s.position.y < ymin - (ymax - ymin) || s.position.y > ymax + (ymax - ymin)))
                d.error(
                    s.loc, key + ".position",
                    fmt::format(
                        "the source at ({}, {}) m lies outside every wall (walls span x in [{:.4g}, {:.4g}], "
                        "y in [{:.4g}, {:.4g}] m)",
                        s.position.x, s.position.y, xmin, xmax, ymin, ymax));
        }
    }
    for (std::size_t k = 0; k < m.inlets.size(); ++k) {
        const auto& in = m.inlets[k];
        const std::string key = fmt::format("inlet[{}]", k);
        checkEdge(c, in.loc, key + ".edge", in.a, in.b);
        c.window(in.loc, key + ".from", in.from, in.to);
        checkInsert(c, sc, in.insert, in.loc, key, names);
        checkInletRate(c, sc, in.loc, key, in.a, in.b, in.rate, in.insert);
    }
    for (std::size_t k = 0; k < m.outlets.size(); ++k) {
        const auto& o = m.outlets[k];
        const std::string key = fmt::format("outlet[{}]", k);
        if (o.isRegion) {
            if (!(o.xmax > o.xmin) || !(o.ymax > o.ymin))
                d.error(o.loc, key + ".region",
                        fmt::format("region [{}, {}, {}, {}] must have xmax > xmin and ymax > ymin", o.xmin,
                                    o.ymin, o.xmax, o.ymax));
        } else {
            checkEdge(c, o.loc, key + ".edge", o.a, o.b);
        }
        c.nonNegative(o.loc, key + ".open_at", o.openAt, "s");
        if (!o.isRegion && o.openAt > 0) c.material(o.loc, key + ".material", o.material, names);
    }
    for (std::size_t k = 0; k < m.boundaries.size(); ++k) {
        const auto& b = m.boundaries[k];
        const std::string key = fmt::format("boundary[{}]", k);
        bool indicesOk = true;
        for (std::size_t e = 0; e < b.edges.size(); ++e) {
            const auto& ed = b.edges[e];
            const auto n = static_cast<std::int64_t>(b.points.size());
            if (ed.from < 0 || ed.from >= n || ed.to < 0 || ed.to >= n) {
                d.error(b.loc, fmt::format("{}.edges[{}]", key, e),
                        fmt::format("point index out of range: [{}, {}]; allowed [0, {}]", ed.from, ed.to,
                                    n - 1));
                indicesOk = false;
                continue;
            }
            if (ed.type != "wall" && ed.type != "outlet" && ed.type != "inlet")
                d.error(b.loc, fmt::format("{}.edges[{}]", key, e),
                        fmt::format(
                            "unknown edge type '{}'; allowed: \"wall\" (1), \"outlet\" (2), \"inlet\" (3)",
                            ed.type));
            checkEdge(c, b.loc, fmt::format("{}.edges[{}]", key, e),
                      b.points[static_cast<std::size_t>(ed.from)], b.points[static_cast<std::size_t>(ed.to)]);
        }
        const auto has = [&](const char* t) {
            return std::any_of(b.edges.begin(), b.edges.end(), [&](const auto& e) { return e.type == t; });
        };
        if (has("wall") || (has("outlet") && b.openAt > 0))
            c.material(b.loc, key + ".material", b.material, names);
        c.nonNegative(b.loc, key + ".open_at", b.openAt, "s");
        if (has("inlet") && indicesOk) {
            checkInsert(c, sc, b.insert, b.loc, key + ".inlet", names);
            for (const auto& e : b.edges)
                if (e.type == "inlet")
                    checkInletRate(c, sc, b.loc, key, b.points[static_cast<std::size_t>(e.from)],
                                   b.points[static_cast<std::size_t>(e.to)], b.rate, b.insert);
        }
        // cfddem 4.1 orientation rule, checked on a closed loop of edges: outer clockwise, obstacles
        // counter-clockwise, so that n_out = z x d points out of the flow domain.
        bool loop = indicesOk && b.edges.size() >= 3;
        for (std::size_t e = 0; loop && e < b.edges.size(); ++e)
            loop = b.edges[e].to == b.edges[(e + 1) % b.edges.size()].from;
        if (loop) {
            std::vector<Vec2> ring;
            for (const auto& e : b.edges) ring.push_back(b.points[static_cast<std::size_t>(e.from)]);
            const Real area = geom::polygonMass(ring).area;
            if (!b.obstacle && area > 0)
                d.error(
                    b.loc, key + ".edges",
                    "an outer boundary must run clockwise (cfddem 4.1), so that each edge's outward normal "
                    "z x d points out of the domain; reverse the edge order or set obstacle = true");
            if (b.obstacle && area < 0)
                d.error(
                    b.loc, key + ".edges",
                    "an obstacle boundary must run counter-clockwise (cfddem 4.1); reverse the edge order");
        }
    }
    if (m.gravity.present) {
        const auto& g = m.gravity;
        if (sc.dem.gravity.x != 0 || sc.dem.gravity.y != 0)
            d.error(g.loc, "gravity",
                    "give gravity either as dem.gravity (constant vector) or as [gravity], not both");
        c.finite(g.loc, "gravity.magnitude", {g.g1, g.g2});
        c.window(g.loc, "gravity.window", g.t1, g.t2);
        c.window(g.loc, "gravity.tilt_window", g.tilt1, g.tilt2);
        c.finite(g.loc, "gravity.direction", {g.direction1, g.direction2});
        if (!(g.steps >= 1 && g.steps <= 1e6 && g.steps == std::floor(g.steps)))
            d.error(g.loc, "gravity.steps",
                    fmt::format("must be a whole number in [1, 1e6], got {}", g.steps));
        if (!(g.ramp >= 0 && g.ramp <= 1))
            d.error(g.loc, "gravity.ramp",
                    fmt::format("must be in [0, 1] (0: step, 1: linear), got {}", g.ramp));
    }
    if (m.sizeScaling.present) {
        const auto& z = m.sizeScaling;
        if (!(z.amplitude > -1 && z.amplitude <= 1))
            d.error(z.loc, "size_scaling.amplitude",
                    fmt::format("must be in (-1, 1] (s stays positive), got {}", z.amplitude));
        c.nonNegative(z.loc, "size_scaling.frequency", z.frequency, "1/s");
        c.finite(z.loc, "size_scaling.slope", {z.slope});
        c.window(z.loc, "size_scaling.window", z.t1, z.t2);
    }
    for (std::size_t k = 0; k < m.changes.size(); ++k) {
        const auto& ch = m.changes[k];
        const std::string key = fmt::format("change[{}]", k);
        c.nonNegative(ch.loc, key + ".at", ch.at, "s");
        if (ch.contact < 0 || ch.contact >= static_cast<std::int64_t>(sc.contacts.size()))
            d.error(ch.loc, key + ".contact",
                    fmt::format("no [[contact]] number {}; allowed [0, {}]", ch.contact,
                                static_cast<std::int64_t>(sc.contacts.size()) - 1));
        if (ch.set.empty()) d.error(ch.loc, key + ".set", "names no law parameter to change");
    }
}

}  // namespace granulab::io
