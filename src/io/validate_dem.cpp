// SPDX-License-Identifier: MIT
// Def-level checks of a dem scene: ranges, names, materials, walls, springs, outputs, shapes.
// The engine set-up (laws, generation, start overlaps, time step) is dem/scene_setup.cpp.
#include "io/validate_dem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "core/limits.hpp"
#include "core/suggest.hpp"
#include "geom/polygon.hpp"
#include "geom/segment.hpp"
#include "io/shape_checks.hpp"
#include "io/validate_machines.hpp"
#include "model/material_names.hpp"
#include "model/size_bounds.hpp"

namespace granulab::io {

namespace {

class Checker {
public:
    explicit Checker(Diagnostics& d) : m_diags(d) {}

    void positive(const SourceLoc& loc, const std::string& key, Real v, const std::string& unit) {
        if (!(v > 0) || !std::isfinite(v))
            m_diags.error(loc, key, fmt::format("must be > 0 [{}], got {}; allowed (0, inf)", unit, v));
    }
    void nonNegative(const SourceLoc& loc, const std::string& key, Real v, const std::string& unit) {
        if (!(v >= 0) || !std::isfinite(v))
            m_diags.error(loc, key, fmt::format("must be >= 0 [{}], got {}; allowed [0, inf)", unit, v));
    }
    void material(const SourceLoc& loc, const std::string& key, const std::string& name,
                  const std::vector<std::string>& names) {
        if (name.empty()) {
            m_diags.error(loc, key, fmt::format("missing material; defined: {}", joinList(names)));
        } else if (std::find(names.begin(), names.end(), name) == names.end()) {
            m_diags.error(loc, key,
                          fmt::format("unknown material '{}'{}; defined: {}", name, didYouMean(name, names),
                                      joinList(names)));
        }
    }
    void oneOf(const SourceLoc& loc, const std::string& key, const std::string& v,
               const std::vector<std::string>& allowed) {
        checkOneOf(m_diags, loc, key, v, allowed);
    }
    Diagnostics& diags() { return m_diags; }

private:
    Diagnostics& m_diags;
};

void checkSize(Checker& c, const model::SizeDistDef& s, const SourceLoc& loc, const std::string& key) {
    using K = model::SizeDistDef::Kind;
    if (s.kind == K::Constant) {
        c.positive(loc, key, s.value, "m");
        return;
    }
    c.positive(loc, key + ".min", s.min, "m");
    if (!(s.max >= s.min))
        c.diags().error(loc, key + ".max", fmt::format("max ({}) must be >= min ({})", s.max, s.min));
    if (s.kind == K::Gaussian) {
        c.positive(loc, key + ".sigma", s.sigma, "m");
        if (!(s.mean >= s.min && s.mean <= s.max))
            c.diags().error(loc, key + ".mean",
                            fmt::format("mean {} must lie in [min, max] = [{}, {}]", s.mean, s.min, s.max));
    }
}

void checkStatic(const model::SceneDef& sc, Checker& c, const std::vector<std::string>& names) {
    auto& d = c.diags();
    if (sc.run.dimension != 2)
        d.error(sc.run.loc, "run.dimension",
                fmt::format("the dem engine is two-dimensional; allowed: 2, got {}", sc.run.dimension));
    c.positive(sc.run.loc, "run.end_time", sc.run.endTime, "s");
    c.positive(sc.dem.loc.file.empty() ? sc.run.loc : sc.dem.loc, "dem.dt", sc.dem.dt, "s");
    if (sc.dem.dt > 0 && sc.run.endTime > 0 && sc.dem.dt > sc.run.endTime)
        d.error(sc.dem.loc, "dem.dt",
                fmt::format("dt = {} s exceeds run.end_time = {} s", sc.dem.dt, sc.run.endTime));
    if (sc.dem.dt > 0 && sc.run.endTime > 0 && !(sc.run.endTime / sc.dem.dt <= kExactIntegerLimit))
        d.error(sc.run.loc, "run.end_time",
                fmt::format("run.end_time / dem.dt = {:.3g} / {:.3g} = {:.3g} steps; allowed at most 2^53 = "
                            "{:.4g} steps (the clock t = step dt must resolve one step)",
                            sc.run.endTime, sc.dem.dt, sc.run.endTime / sc.dem.dt, kExactIntegerLimit));
    c.positive(sc.dem.loc, "dem.pc_tolerance", sc.dem.pcTolerance, "m/s^2");
    if (sc.dem.pcIterations < 0 || sc.dem.pcIterations > 1000)
        d.error(sc.dem.loc, "dem.pc_iterations",
                fmt::format("must be in [0, 1000] (0: modified Euler), got {}", sc.dem.pcIterations));
    if (!(sc.dem.pcCorrector > 0 && sc.dem.pcCorrector <= 1))
        d.error(sc.dem.loc, "dem.pc_corrector", fmt::format("must be in (0, 1], got {}", sc.dem.pcCorrector));
    if (!(sc.dem.gearC0 > 0 && sc.dem.gearC0 < 1))
        d.error(
            sc.dem.loc, "dem.gear_c0",
            fmt::format("must be in (0, 1) (3/20 textbook, 3/16 velocity-dependent), got {}", sc.dem.gearC0));
    c.oneOf(sc.dem.loc, "dem.mass_model", sc.dem.massModel, {"disk", "sphere"});
    if (sc.dem.sortEvery < 0 || sc.dem.sortEvery > 1000000)
        d.error(sc.dem.loc, "dem.sort_every",
                fmt::format("must be in [0, 1000000] (0: never), got {}", sc.dem.sortEvery));
    if (sc.dem.skin != -1) c.nonNegative(sc.dem.loc, "dem.skin", sc.dem.skin, "m");
    for (std::size_t k = 0; k < sc.dem.damping.size(); ++k) {
        const auto& w = sc.dem.damping[k];
        const std::string key = fmt::format("dem.damping[{}]", k);
        c.nonNegative(w.loc, key + ".gamma", w.gamma, "kg/s");
        c.nonNegative(w.loc, key + ".gamma_rotation", w.gammaRotation, "kg m^2/s");
        if (!(w.to > w.from))
            d.error(w.loc, key, fmt::format("window must have to > from, got [{}, {})", w.from, w.to));
    }
    for (std::size_t k = 0; k < sc.materials.size(); ++k) {
        const auto& m = sc.materials[k];
        if (m.youngsModulus != 0)
            c.positive(m.loc, fmt::format("material[{}].youngs_modulus", k), m.youngsModulus, "Pa");
        if (!(m.poisson >= 0 && m.poisson < 0.5))
            d.error(m.loc, fmt::format("material[{}].poisson", k),
                    fmt::format("must be in [0, 0.5), got {}", m.poisson));
        if (m.name.empty() || m.name == "*")
            d.error(
                m.loc, fmt::format("material[{}].name", k),
                fmt::format("'{}' cannot name a material (\"*\" is the wildcard of [[contact]] materials)",
                            m.name));
        for (std::size_t j = 0; j < k; ++j)
            if (sc.materials[j].name == m.name)
                d.error(m.loc, fmt::format("material[{}].name", k),
                        fmt::format("duplicate material name '{}'", m.name));
    }
    for (std::size_t k = 0; k < sc.particles.size(); ++k) {
        const auto& p = sc.particles[k];
        const std::string key = fmt::format("particle[{}]", k);
        c.material(p.loc, key + ".material", p.material, names);  // shape and radius: checkShapes()
    }
    for (std::size_t k = 0; k < sc.blocks.size(); ++k) {
        const auto& b = sc.blocks[k];
        const std::string key = fmt::format("block[{}]", k);
        const bool disks = b.shape == "disk";  // polygon shapes: checkShapes()
        if (!(b.xmax > b.xmin) || !(b.ymax > b.ymin))
            d.error(b.loc, key + ".region",
                    fmt::format("region [{}, {}, {}, {}] must have xmax > xmin and ymax > ymin", b.xmin,
                                b.ymin, b.xmax, b.ymax));
        if (disks) checkSize(c, b.radius, b.radius.loc.file.empty() ? b.loc : b.radius.loc, key + ".radius");
        c.material(b.loc, key + ".material", b.material, names);
        c.nonNegative(b.loc, key + ".temperature", b.temperature, "J");
        if (b.lattice == model::BlockDef::Lattice::Random) {
            if (b.count <= 0)
                d.error(b.loc, key + ".count", fmt::format("random blocks need count > 0, got {}", b.count));
        } else {
            c.positive(b.loc, key + ".spacing", b.spacing, "m");
            const Real dmax = 2 * model::maxRadius(b.radius);
            if (disks && b.spacing > 0 && dmax > b.spacing)
                d.error(
                    b.loc, key + ".spacing",
                    fmt::format(
                        "spacing {} m is smaller than the largest diameter {} m: neighbours would overlap",
                        b.spacing, dmax));
            if (b.count < -1 || b.count == 0)
                d.error(b.loc, key + ".count",
                        fmt::format("count must be > 0 (or omitted for a full lattice), got {}", b.count));
        }
    }
    for (std::size_t k = 0; k < sc.walls.size(); ++k) {
        const auto& w = sc.walls[k];
        const std::string key = fmt::format("wall[{}]", k);
        c.material(w.loc, key + ".material", w.material, names);
        if (w.points.size() < 2) {
            d.error(w.loc, key + ".points",
                    fmt::format("a wall needs at least 2 points, got {}", w.points.size()));
            continue;
        }
        if (w.closed && w.points.size() < 3)
            d.error(w.loc, key + ".closed", "a closed wall needs at least 3 points");
        const std::size_t segs = w.closed ? w.points.size() : w.points.size() - 1;
        for (std::size_t s = 0; s < segs; ++s)
            if (norm2(w.points[(s + 1) % w.points.size()] - w.points[s]) <= 0)
                d.error(w.loc, key + ".points",
                        fmt::format("points {} and {} coincide (zero-length segment)", s,
                                    (s + 1) % w.points.size()));
    }
    for (std::size_t k = 0; k < sc.springs.size(); ++k) {
        const auto& sp = sc.springs[k];
        const std::string key = fmt::format("spring[{}]", k);
        c.positive(sp.loc, key + ".k", sp.stiffness, "N/m");
        c.nonNegative(sp.loc, key + ".speed", sp.speed, "m/s");
        c.nonNegative(sp.loc, key + ".from", sp.from, "s");
        if (!(sp.to >= sp.from))
            d.error(sp.loc, key + ".to", fmt::format("to = {} s must be >= from = {} s", sp.to, sp.from));
        for (Real v : {sp.attach.x, sp.attach.y, sp.pullStart.x, sp.pullStart.y, sp.direction})
            if (!std::isfinite(v))
                d.error(sp.loc, key, "attach, pull_start and direction must be finite numbers");
    }
    c.nonNegative(sc.output.loc, "output.snapshot_interval", sc.output.snapshotInterval, "s");
    c.nonNegative(sc.output.loc, "output.series_interval", sc.output.seriesInterval, "s");
    c.nonNegative(sc.output.loc, "output.checkpoint_interval", sc.output.checkpointInterval, "s");
}

}  // namespace

void checkDemDef(const model::SceneDef& scene, Diagnostics& diags, std::vector<std::string>& warnings) {
    Checker checker(diags);
    checkStatic(scene, checker, model::materialNames(scene));
    checkMachineDefs(scene, diags, model::materialNames(scene));
    checkShapes(scene, diags, warnings);
}

}  // namespace granulab::io
