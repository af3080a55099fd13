// SPDX-License-Identifier: MIT
// Scene machines from Defs (gc2d spec 6.1-6.7, cfddem spec 4.1-4.3).
#include "dem/machine_setup.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "dem/setup.hpp"
#include "dem/step_clock.hpp"
#include "geom/polygon.hpp"
#include "model/grain_shapes.hpp"
#include "model/mass_model.hpp"
#include "model/size_bounds.hpp"

namespace granulab::dem {

namespace {

std::uint32_t materialIndex(const std::vector<std::string>& names, const std::string& name) {
    return static_cast<std::uint32_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

Vec2 rotate(Vec2 v, Real angle) {
    const Real c = std::cos(angle), s = std::sin(angle);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}

model::WallDriver driverOf(const model::WallDef& def, const std::vector<Vec2>& points) {
    model::WallDriver d;
    if (def.velocity.x != 0 || def.velocity.y != 0) {
        d.kind = model::WallDriver::Kind::Velocity;
        d.velocity = def.velocity;
    }
    if (!def.vibType.empty()) {
        d.kind = model::WallDriver::Kind::Vibration;
        const std::string& t = def.vibType;
        d.vibration = t == "sawtooth"   ? model::VibrationType::Sawtooth
                      : t == "tapping"  ? model::VibrationType::Tapping
                      : t == "triangle" ? model::VibrationType::Triangle
                                        : model::VibrationType::Cosine;
        d.direction = {std::cos(def.vibDirection), std::sin(def.vibDirection)};
        d.width = def.vibWidth;
        d.frequency = def.vibFrequency;
        d.from = def.vibFrom;
        d.to = def.vibTo;
    }
    if (def.pistonForce) {
        d.kind = model::WallDriver::Kind::Piston;
        d.direction = {std::cos(def.pistonDirection), std::sin(def.pistonDirection)};
        d.targetForce = *def.pistonForce;
        d.maxSpeed = def.pistonMaxSpeed;
        d.gain = def.pistonGain > 0 ? def.pistonGain : def.pistonMaxSpeed / std::abs(*def.pistonForce);
        d.from = def.pistonFrom;
    }
    if (def.omega != 0) {
        d.kind = model::WallDriver::Kind::Rotation;
        d.omega = def.omega;
        if (def.pivot) {
            d.pivot = *def.pivot;
        } else {
            Vec2 c;
            for (const Vec2& p : points) c += p;
            d.pivot = c / static_cast<Real>(points.size());
        }
    }
    return d;
}

/// The outlets of [[outlet]] and of [[boundary]] outlet edges, in this order.
std::vector<model::OutletDef> allOutlets(const model::SceneDef& scene) {
    std::vector<model::OutletDef> all = scene.machines.outlets;
    for (const auto& b : scene.machines.boundaries)
        for (const auto& e : b.edges)
            if (e.type == "outlet") {
                model::OutletDef o;
                o.name = b.name;
                o.a = b.points[static_cast<std::size_t>(e.from)];
                o.b = b.points[static_cast<std::size_t>(e.to)];
                o.openAt = b.openAt;
                o.material = b.material;
                all.push_back(o);
            }
    return all;
}

}  // namespace

std::vector<Vec2> placedWallPoints(const model::WallDef& def) {
    std::vector<Vec2> p = def.points;
    if (def.angle != 0 && !p.empty()) {  // about the area centroid of a closed polygon, else the mean
        Vec2 c;
        const geom::PolygonMass mass = def.closed ? geom::polygonMass(p) : geom::PolygonMass{};
        if (mass.area != 0) {
            c = mass.centroid;
        } else {
            for (const Vec2& q : p) c += q;
            c = c / static_cast<Real>(p.size());
        }
        for (Vec2& q : p) q = c + rotate(q - c, def.angle);
    }
    for (Vec2& q : p) q += def.offset;
    return p;
}

bool wallIsBody(const model::WallDef& def) {
    return def.kind == "polygon";
}

std::vector<Vec2> drumSegment(const model::DrumDef& d, std::int64_t k) {
    const Real step = 2 * kPi / static_cast<Real>(d.count);
    const Real a0 = step * static_cast<Real>(k), a1 = a0 + step;
    const Real scale = 1 / std::cos(0.5 * step);  // corners beyond r so that the edge lies at r
    const Real ri = d.innerRadius * scale, ro = (d.innerRadius + d.thickness) * scale;
    const auto at = [&](Real r, Real a) { return d.centre + Vec2{r * std::cos(a), r * std::sin(a)}; };
    return {at(ri, a0), at(ro, a0), at(ro, a1), at(ri, a1)};
}

model::WallSet buildWalls(const model::SceneDef& scene, const std::vector<std::string>& names) {
    model::WallSet walls;
    const auto last = [&] { return static_cast<std::uint32_t>(walls.walls.size() - 1); };
    for (std::size_t w = 0; w < scene.walls.size(); ++w) {
        const auto& def = scene.walls[w];
        const std::string name = def.name.empty() ? fmt::format("wall{}", w) : def.name;
        const auto mat = materialIndex(names, def.material);
        std::vector<Vec2> points = placedWallPoints(def);
        if (wallIsBody(def)) {
            if (geom::polygonMass(points).area < 0) std::reverse(points.begin(), points.end());
            walls.addPolygon(name, points, mat);
        } else {
            walls.addPolyline(name, points, def.closed, mat, {});
        }
        walls.walls.back().surfaceVelocity = def.surfaceVelocity;
        walls.walls.back().solidUntil = def.solidUntil;
        walls.setDriver(last(), driverOf(def, points));
    }
    for (std::size_t k = 0; k < scene.machines.drums.size(); ++k) {  // gc2d_drum (spec 6.2)
        const auto& d = scene.machines.drums[k];
        const std::string base = d.name.empty() ? fmt::format("drum{}", k) : d.name;
        const auto mat = materialIndex(names, d.material);
        for (std::int64_t s = 0; s < d.count; ++s) {
            walls.addPolygon(fmt::format("{}_{}", base, s), drumSegment(d, s), mat);
            model::WallDriver driver;
            if (d.rotating) {  // the ring turns: inner-surface speed v = omega r
                driver.kind = model::WallDriver::Kind::Rotation;
                driver.pivot = d.centre;
                driver.omega = d.surfaceSpeed / d.innerRadius;
            } else {  // a fixed ring lined with a belt moving counter-clockwise at v
                const Real mid = 2 * kPi * (static_cast<Real>(s) + 0.5) / static_cast<Real>(d.count);
                walls.walls.back().surfaceVelocity = Vec2{-std::sin(mid), std::cos(mid)} * d.surfaceSpeed;
            }
            walls.setDriver(last(), driver);
        }
    }
    for (std::size_t k = 0; k < scene.machines.boundaries.size(); ++k) {  // cfddem 4.1: wall edges
        const auto& b = scene.machines.boundaries[k];
        const std::string base = b.name.empty() ? fmt::format("boundary{}", k) : b.name;
        const auto mat = materialIndex(names, b.material);
        std::vector<Vec2> chain;
        int chains = 0;
        const auto flush = [&](bool closed) {
            if (chain.size() >= 2)
                walls.addPolyline(fmt::format("{}_{}", base, chains++), chain, closed, mat, {});
            chain.clear();
        };
        const auto& edges = b.edges;
        const bool allWalls =
            std::all_of(edges.begin(), edges.end(), [](const auto& e) { return e.type == "wall"; });
        for (std::size_t e = 0; e < edges.size(); ++e) {
            if (edges[e].type != "wall") {
                flush(false);
                continue;
            }
            const Vec2 from = b.points[static_cast<std::size_t>(edges[e].from)];
            const Vec2 to = b.points[static_cast<std::size_t>(edges[e].to)];
            if (chain.empty() || !(chain.back() == from)) {
                flush(false);
                chain.push_back(from);
            }
            chain.push_back(to);
        }
        const bool closedLoop = allWalls && chain.size() > 3 && chain.front() == chain.back();
        if (closedLoop) chain.pop_back();
        flush(closedLoop);
    }
    const auto outlets = allOutlets(scene);
    for (std::size_t k = 0; k < outlets.size(); ++k) {  // the lid of an outlet that opens later
        const auto& o = outlets[k];
        if (o.isRegion || !(o.openAt > 0)) continue;
        walls.addPolyline((o.name.empty() ? fmt::format("outlet{}", k) : o.name) + "_lid", {o.a, o.b}, false,
                          materialIndex(names, o.material), {});
        walls.walls.back().solidUntil = o.openAt;
        walls.setDriver(last(), {});
    }
    walls.place(0);
    return walls;
}

namespace {

InsertTemplate insertTemplate(const model::SceneDef& scene, const model::InsertDef& def,
                              const std::vector<std::string>& names, model::ShapePool& pool) {
    InsertTemplate t;
    t.material = materialIndex(names, def.material);
    for (const auto& m : scene.materials)
        if (m.name == def.material) t.density = m.density;
    t.massModel = model::massModelOf(scene.dem.massModel);
    t.radius = def.radius;
    t.velocity = def.velocity;
    t.angle = def.angle;
    t.omega = def.omega;
    t.attempts = static_cast<int>(def.attempts);
    if (def.shape != "disk")
        for (const auto& s : scene.shapes)
            if (s.name == def.shape) {
                t.shape = s;
                if (s.kind != "grain")
                    if (const auto corners = model::deterministicCorners(s))
                        t.sharedShape = pool.add(*corners);
            }
    return t;
}

}  // namespace

FlowConfig buildFlow(const model::SceneDef& scene, const std::vector<std::string>& names,
                     model::ShapePool& pool) {
    FlowConfig f;
    f.seed = scene.run.seed;
    const auto& m = scene.machines;
    for (const auto& s : m.sources) {
        DropSource d;
        d.name = s.name;
        d.what = insertTemplate(scene, s.insert, names, pool);
        d.position = s.position;
        d.relative = s.placement == "rel";
        d.width = s.width;
        d.widthEnd = s.widthEnd.value_or(s.width);
        d.interval = s.interval;
        d.from = s.from;
        d.to = s.to;
        f.sources.push_back(d);
    }
    const auto addInlet = [&](const std::string& name, Vec2 a, Vec2 b, Real rate, Real from, Real to,
                              bool inset, const model::InsertDef& what) {
        Inlet in;
        in.name = name;
        in.what = insertTemplate(scene, what, names, pool);
        in.a = a;
        in.b = b;
        in.rate = rate;
        in.from = from;
        in.to = to;
        in.inset = inset;
        f.inlets.push_back(in);
    };
    for (const auto& i : m.inlets) addInlet(i.name, i.a, i.b, i.rate, i.from, i.to, i.inset, i.insert);
    for (const auto& b : m.boundaries)
        for (const auto& e : b.edges)
            if (e.type == "inlet")
                addInlet(b.name, b.points[static_cast<std::size_t>(e.from)],
                         b.points[static_cast<std::size_t>(e.to)], b.rate, 0, 1e300, true, b.insert);
    const auto addOutlet = [&](const model::OutletDef& o) {
        Outlet q;
        q.name = o.name;
        q.isRegion = o.isRegion;
        q.a = o.a;
        q.b = o.b;
        q.xmin = o.xmin;
        q.ymin = o.ymin;
        q.xmax = o.xmax;
        q.ymax = o.ymax;
        q.removeInside = o.removeInside;
        q.openAt = o.openAt;
        f.outlets.push_back(q);
    };
    for (const auto& o : allOutlets(scene)) addOutlet(o);
    for (std::size_t k = 0; k < f.outlets.size(); ++k)
        if (f.outlets[k].name.empty()) f.outlets[k].name = fmt::format("outlet{}", k);
    for (std::size_t k = 0; k < f.inlets.size(); ++k)
        if (f.inlets[k].name.empty()) f.inlets[k].name = fmt::format("inlet{}", k);
    for (std::size_t k = 0; k < f.sources.size(); ++k)
        if (f.sources[k].name.empty()) f.sources[k].name = fmt::format("source{}", k);
    return f;
}

Real largestInsertedRadius(const model::SceneDef& scene) {
    Real r = 0;
    for (const model::InsertDef* d : scene.machines.inserts()) {
        if (d->shape == "disk") r = std::max(r, model::maxRadius(d->radius));
        for (const auto& s : scene.shapes)
            if (s.name == d->shape) r = std::max(r, model::maxPlacementRadius(s));
    }
    return r;
}

std::optional<GravitySchedule> buildGravitySchedule(const model::SceneDef& scene) {
    const auto& g = scene.machines.gravity;
    if (!g.present) return std::nullopt;
    GravitySchedule s;
    s.type = g.type == "linear"        ? GravitySchedule::Type::Linear
             : g.type == "step"        ? GravitySchedule::Type::Step
             : g.type == "smooth_step" ? GravitySchedule::Type::SmoothStep
                                       : GravitySchedule::Type::Constant;
    s.g1 = g.g1;
    s.g2 = g.g2;
    s.t1 = g.t1;
    s.t2 = g.t2;
    s.steps = g.steps;
    s.ramp = g.ramp;
    s.direction1 = g.direction1;
    s.direction2 = g.direction2;
    s.tilt1 = g.tilt1;
    s.tilt2 = g.tilt2;
    return s;
}

std::optional<SizeCycle> buildSizeCycle(const model::SceneDef& scene) {
    const auto& z = scene.machines.sizeScaling;
    if (!z.present) return std::nullopt;
    SizeCycle c;
    c.amplitude = z.amplitude;
    c.frequency = z.frequency;
    c.slope = z.slope;
    c.t1 = z.t1;
    c.t2 = z.t2;
    return c;
}

std::vector<WorldConfig::LawChange> buildLawChanges(const model::SceneDef& scene, Real dt) {
    std::vector<model::ChangeDef> changes = scene.machines.changes;
    std::stable_sort(changes.begin(), changes.end(),
                     [](const auto& a, const auto& b) { return a.at < b.at; });
    model::SceneDef current = scene;
    std::vector<WorldConfig::LawChange> out;
    for (const auto& c : changes) {
        auto& params = current.contacts[static_cast<std::size_t>(c.contact)].params;
        for (const auto& [key, value] : c.set) params[key] = value;
        Diagnostics ignored;  // checked by validation
        WorldConfig::LawChange change;
        change.step = firstStepAtOrAfter(c.at, dt);
        change.laws = buildLawTable(current, ignored);
        if (!out.empty() && out.back().step == change.step)
            out.back() = std::move(change);
        else
            out.push_back(std::move(change));
    }
    return out;
}

}  // namespace granulab::dem
