// SPDX-License-Identifier: MIT
// Def-level checks of a dem scene: ranges, names, materials, walls, springs, outputs, shapes.
// The engine set-up (laws, generation, start overlaps, time step) is dem/scene_setup.cpp.
#include "io/validate_dem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/dem_analyses.hpp"
#include "core/limits.hpp"
#include "core/suggest.hpp"
#include "geom/polygon.hpp"
#include "geom/segment.hpp"
#include "io/range_checks.hpp"
#include "io/shape_checks.hpp"
#include "io/validate_fluid.hpp"
#include "io/validate_machines.hpp"
#include "model/gc2d_generators.hpp"
#include "model/material_names.hpp"
#include "model/size_bounds.hpp"

namespace granulab::io {

namespace {

/// output.gc2d_*: a file stem without folders, positive file numbers, intervals >= 0.
void checkGc2dOutput(const model::OutputDef& o, Diagnostics& d) {
    const model::Gc2dOutputDef& g = o.gc2d;
    if (g.basename.empty() || g.basename.find_first_of("/\\") != std::string::npos || g.basename == "." ||
        g.basename == "..")
        d.error(o.loc, "output.gc2d_basename",
                fmt::format("'{}' must be a file stem without a folder (the files go into the output "
                            "folder), e.g. \"piston2\"",
                            g.basename));
    for (const auto& [key, n] : {std::pair{"output.gc2d_next_data_number", g.nextDataNumber},
                                 std::pair{"output.gc2d_next_setup_number", g.nextSetupNumber}})
        if (n < 1 || n > 9999)
            d.error(o.loc, key, fmt::format("{} is a file number NNNN, allowed [1, 9999]", n));
    for (const auto& [key, v] : {std::pair{"output.gc2d_setup_interval", g.setupInterval},
                                 std::pair{"output.gc2d_line_interval", g.lineInterval}})
        if (!(v >= 0 && std::isfinite(v)))
            d.error(o.loc, key, fmt::format("{} s: an interval in s, allowed [0, inf) (0: never)", v));
}

/// output.gc2d = true: gc2d knows only polygons (spec 2.1), and its ggf has no way to write a disk,
/// so a scene that makes disks (particles, blocks, heaps, sources, inlets) is refused
/// (docs/coming-from-gc2d.md "Legacy outputs").
void checkGc2dGrains(const model::SceneDef& sc, Diagnostics& d) {
    if (!sc.output.gc2d.enabled) return;
    const auto refuse = [&](const SourceLoc& loc, const std::string& what) {
        d.error(loc, "output.gc2d",
                fmt::format("gc2d's files describe polygons only (gc2d has no disks), and {} makes disks; "
                            "give it a polygon [[shape]] (kind = \"regular\" with many corners is close to "
                            "a disk), or set output.gc2d = false",
                            what));
    };
    for (std::size_t k = 0; k < sc.particles.size(); ++k)
        if (sc.particles[k].shape == "disk") refuse(sc.particles[k].loc, fmt::format("particle[{}]", k));
    for (std::size_t k = 0; k < sc.blocks.size(); ++k)
        if (sc.blocks[k].shape == "disk") refuse(sc.blocks[k].loc, fmt::format("block[{}]", k));
    for (std::size_t k = 0; k < sc.heaps.size(); ++k) {
        const model::HeapDef& h = sc.heaps[k];
        if (h.shape == "disk" && !(h.size.x > 0 && h.size.y > 0))  // size: plain rectangles
            refuse(h.loc, fmt::format("heap[{}]", k));
    }
    const auto& m = sc.machines;
    for (std::size_t k = 0; k < m.sources.size(); ++k)
        if (m.sources[k].insert.shape == "disk") refuse(m.sources[k].loc, fmt::format("source[{}]", k));
    for (std::size_t k = 0; k < m.inlets.size(); ++k)
        if (m.inlets[k].insert.shape == "disk") refuse(m.inlets[k].loc, fmt::format("inlet[{}]", k));
    for (std::size_t k = 0; k < m.boundaries.size(); ++k) {
        const model::BoundaryDef& b = m.boundaries[k];
        const bool inlets = std::any_of(b.edges.begin(), b.edges.end(),
                                        [](const model::BoundaryDef::Edge& e) { return e.type == "inlet"; });
        if (inlets && b.insert.shape == "disk")
            refuse(b.loc, fmt::format("boundary[{}] (its inlet edges)", k));
    }
}

/// A gc2d restart: the start time on the step grid and before the end. (PARTICLEs without the
/// Gear state in a restart start with zero higher derivatives, like a grain a source inserts.)
void checkRestart(const model::SceneDef& sc, Diagnostics& d) {
    const Real t0 = sc.run.startTime, dt = sc.dem.dt;
    if (!(t0 >= 0 && std::isfinite(t0)))
        d.error(sc.run.loc, "run.start_time", fmt::format("{} s: allowed [0, end_time)", t0));
    else if (t0 > 0 && dt > 0) {
        const Real steps = t0 / dt;
        if (std::abs(steps - std::round(steps)) > 1e-6 * std::max<Real>(1, steps))
            d.error(
                sc.run.loc, "run.start_time",
                fmt::format("{} s is not a whole number of steps of dt = {} s (the DEM clock is t = k dt)",
                            t0, dt));
        if (!(t0 < sc.run.endTime))
            d.error(sc.run.loc, "run.start_time",
                    fmt::format("{} s: the run starts after its end time {} s", t0, sc.run.endTime));
    }
}

/// output.analyses: names of `granulab analyze` that need no command-line option, and the files
/// they read (snapshots; contact files for the force analyses).
void checkInRunAnalyses(const model::OutputDef& o, Diagnostics& d) {
    std::vector<std::string> names;
    for (const auto& a : analysis::kDemAnalyses) names.push_back(a.name);
    for (const std::string& name : o.analyses) {
        const analysis::DemAnalysisInfo* a = analysis::findDemAnalysis(name);
        if (!a)
            d.error(o.loc, "output.analyses",
                    fmt::format("'{}' is not an analysis{}; allowed: {}", name, didYouMean(name, names),
                                joinList(names)));
        else if (a->needsFlag)
            d.error(o.loc, "output.analyses",
                    fmt::format("'{}' needs {}: run granulab analyze DIR {} {} ... after the run", name,
                                a->needsFlag, name, a->needsFlag));
        else if (a->needsContacts && !o.contacts)
            d.error(o.loc, "output.analyses",
                    fmt::format("'{}' reads the contact files: set output.contacts = true", name));
    }
    if (!o.analyses.empty() && !o.vtk)
        d.error(o.loc, "output.analyses", "the analyses read the snapshots: set output.vtk = true");
}

class Checker {
public:
    explicit Checker(Diagnostics& d) : m_diags(d) {}

    void positive(const SourceLoc& loc, const std::string& key, Real v, const std::string& unit) {
        checkPositive(m_diags, loc, key, v, unit);
    }
    void nonNegative(const SourceLoc& loc, const std::string& key, Real v, const std::string& unit) {
        checkNonNegative(m_diags, loc, key, v, unit);
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
        } else if (b.lattice == model::BlockDef::Lattice::Rect ||
                   b.lattice == model::BlockDef::Lattice::Fcc) {
            // gc2d lattices: checkGc2dBlock()
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
    checkGc2dOutput(sc.output, d);
    checkRestart(sc, d);
    checkGc2dGrains(sc, d);
    checkInRunAnalyses(sc.output, d);
}

/// The gc2d GENERATE_BLOCK keys of block k (spec section 6.5): grid, jitter, velocity ranges.
void checkGc2dBlock(Checker& c, const model::BlockDef& b, std::size_t k) {
    using L = model::BlockDef::Lattice;
    auto& d = c.diags();
    const std::string key = fmt::format("block[{}]", k);
    const bool gc2d = b.lattice == L::Rect || b.lattice == L::Fcc;
    const char* lattice = b.lattice == L::Rect ? "rect" : "fcc";
    if (gc2d) {
        if (!(b.grid.x > 0 && b.grid.y > 0 && std::isfinite(b.grid.x) && std::isfinite(b.grid.y)))
            d.error(
                b.loc, key + ".grid",
                fmt::format("lattice '{}' needs grid = [dx, dy] with dx > 0 and dy > 0 [m], got [{}, {}]; "
                            "allowed (0, inf) each",
                            lattice, b.grid.x, b.grid.y));
        if (b.spacing != 0)
            d.error(
                b.loc, key + ".spacing",
                fmt::format("spacing belongs to the hexagonal and square lattices; lattice '{}' uses grid = "
                            "[dx, dy]",
                            lattice));
        const Real nearest = model::nearestSiteDistance(b);
        const Real dmax = 2 * model::maxRadius(b.radius);
        if (b.shape == "disk" && nearest > 0 && dmax > nearest)
            d.error(
                b.loc, key + ".grid",
                fmt::format("the nearest sites of lattice '{}' with grid [{}, {}] are {:.6g} m apart, less "
                            "than the largest diameter {} m: neighbours would overlap",
                            lattice, b.grid.x, b.grid.y, nearest, dmax));
        if (b.count < -1 || b.count == 0)
            d.error(b.loc, key + ".count",
                    fmt::format("count must be > 0 (or omitted for a full lattice), got {}", b.count));
    } else {
        if (b.grid.x != 0 || b.grid.y != 0)
            d.error(b.loc, key + ".grid",
                    "grid belongs to the gc2d lattices \"rect\" and \"fcc\"; hexagonal and square lattices "
                    "use spacing");
        if (b.jitter != model::BlockDef::Jitter::None)
            d.error(b.loc, key + ".jitter",
                    "jitter applies to the lattices \"rect\" and \"fcc\" only; allowed here: \"none\"");
    }
    if (!(b.jitterFraction > 0 && b.jitterFraction <= 1))
        d.error(b.loc, key + ".jitter_fraction", fmt::format("must be in (0, 1], got {}", b.jitterFraction));
    if (!(b.directionRange.y >= b.directionRange.x) ||
        !std::isfinite(b.directionRange.y - b.directionRange.x))
        d.error(
            b.loc, key + ".direction_range",
            fmt::format(
                "[a1, a2] = [{}, {}] rad needs a2 >= a1 and a finite a2 - a1; allowed a1 <= a2 (default [0, "
                "2 pi])",
                b.directionRange.x, b.directionRange.y));
    if (!(b.speedRange.x >= 0 && b.speedRange.y >= b.speedRange.x))
        d.error(b.loc, key + ".speed_range",
                fmt::format("[v1, v2] = [{}, {}] m/s needs 0 <= v1 <= v2; allowed [0, inf)", b.speedRange.x,
                            b.speedRange.y));
}

/// [[heap]] k (gc2d heap.pm, spec section 6.5): ends, slope, gaps, grain, material.
void checkHeap(Checker& c, const model::SceneDef& sc, std::size_t k, const std::vector<std::string>& names) {
    const model::HeapDef& h = sc.heaps[k];
    auto& d = c.diags();
    const std::string key = fmt::format("heap[{}]", k);
    const bool hex = h.stacking == model::HeapDef::Stacking::Hexagonal;
    c.material(h.loc, key + ".material", h.material, names);
    if (!(h.xRight > h.xLeft))
        d.error(h.loc, key + ".x_range",
                fmt::format("[x_left, x_right] = [{}, {}] m needs x_right > x_left", h.xLeft, h.xRight));
    if (!(h.gap.x >= 0) || !(h.gap.y >= 0))
        d.error(
            h.loc, key + ".spacing",
            fmt::format("gaps [dx, dy] = [{}, {}] m must be >= 0; allowed [0, inf) each", h.gap.x, h.gap.y));
    // The grain: exactly one of radius (disks), size (plain rectangles), shape (a [[shape]]).
    const bool sized = h.size.x != 0 || h.size.y != 0;
    const bool named = h.shape != "disk";
    if (sized && named)
        d.error(h.loc, key + ".size",
                fmt::format("size makes plain rectangles; it cannot be combined with shape '{}'", h.shape));
    if (h.radius != 0 && (sized || named))
        d.error(
            h.loc, key + ".radius",
            named ? fmt::format("radius belongs to disks; the size of shape '{}' comes from its [[shape]]",
                                h.shape)
                  : std::string("radius belongs to disks; size = [a, b] makes rectangles: give one of them"));
    if (sized && !(h.size.x > 0 && h.size.y > 0))
        d.error(h.loc, key + ".size",
                fmt::format("rectangle edges [a, b] = [{}, {}] m must be > 0; allowed (0, inf) each",
                            h.size.x, h.size.y));
    if (!sized && !named) c.positive(h.loc, key + ".radius", h.radius, "m");
    if (named && !sized) {
        std::vector<std::string> shapeNames = {"disk"};
        const model::ShapeDef* def = nullptr;
        for (const auto& s : sc.shapes) {
            shapeNames.push_back(s.name);
            if (s.name == h.shape) def = &s;
        }
        if (!def) {
            d.error(h.loc, key + ".shape",
                    fmt::format("unknown shape '{}'{}; defined: {}", h.shape, didYouMean(h.shape, shapeNames),
                                joinList(shapeNames)));
        } else if (def->kind != "rectangle" && def->kind != "regular") {
            d.error(
                h.loc, key + ".shape",
                fmt::format("shape '{}' is of kind '{}'; a heap stacks disks, rectangle shapes or regular "
                            "shapes (by their circumcircle)",
                            h.shape, def->kind));
        } else if (def->rotationMode != "const" || (def->kind == "rectangle" && def->rotation != 0)) {
            d.error(h.loc, key + ".shape",
                    fmt::format("shape '{}' must have rotation_mode = \"const\"{}; a heap stacks its grains "
                                "upright",
                                h.shape,
                                def->kind == "rectangle" ? " and rotation = 0 (swap size instead)" : ""));
        }
    }
    const auto grain = model::heapGrain(h, sc.shapes);
    const bool slopeFinite = std::isfinite(h.slope);
    if (!grain) {
        if (!(h.slope > 0 && h.slope < 0.5 * kPi) || !slopeFinite)
            d.error(h.loc, key + ".slope",
                    fmt::format("slope psi = {} rad; allowed (0, {:.6g}) rad", h.slope, 0.5 * kPi));
        return;
    }
    const Real maxSlope = model::heapMaxSlope(h, *grain);
    if (!(h.slope > 0 && h.slope < maxSlope) || !slopeFinite) {
        std::string why = "below pi/2";
        if (hex)
            why = grain->diskLike || grain->width == grain->height
                      ? "arctan 2 for hexagonal stacks of disks and squares: steeper flanks overhang"
                      : fmt::format(
                            "arctan(2b/a) = arctan(2 x {:.6g} / {:.6g}) for hexagonal stacks of "
                            "rectangles: steeper flanks overhang",
                            grain->height, grain->width);
        d.error(h.loc, key + ".slope",
                fmt::format("slope psi = {} rad ({:.4g} deg) is not allowed; allowed (0, {:.6g}) rad ({})",
                            h.slope, h.slope * 180 / kPi, maxSlope, why));
    }
    const Real maxGap = model::heapMaxGapX(h, *grain);
    if (hex && h.gap.x >= 0 && h.gap.y >= 0 && (grain->diskLike ? !(h.gap.x <= maxGap) : !(h.gap.x < maxGap)))
        d.error(
            h.loc, key + ".spacing",
            grain->diskLike
                ? fmt::format("gap dx = {} m is too wide for a hexagonal stack of disks of radius {:.6g} m "
                              "(each rests on the two below; rows two apart must not overlap); allowed "
                              "[0, {:.6g}] m",
                              h.gap.x, 0.5 * grain->width, maxGap)
                : fmt::format("gap dx = {} m is too wide for a hexagonal stack of rectangles {:.6g} m wide "
                              "(each must rest on the two below); allowed [0, {:.6g}) m",
                              h.gap.x, grain->width, maxGap));
}

/// gc2d generators: block keys of GENERATE_BLOCK and the heaps.
void checkGc2dGenerators(const model::SceneDef& sc, Checker& c, const std::vector<std::string>& names) {
    for (std::size_t k = 0; k < sc.blocks.size(); ++k) checkGc2dBlock(c, sc.blocks[k], k);
    for (std::size_t k = 0; k < sc.heaps.size(); ++k) checkHeap(c, sc, k, names);
}

}  // namespace

void checkDemDef(const model::SceneDef& scene, Diagnostics& diags, std::vector<std::string>& warnings) {
    Checker checker(diags);
    checkStatic(scene, checker, model::materialNames(scene));
    checkMachineDefs(scene, diags, model::materialNames(scene));
    checkGc2dGenerators(scene, checker, model::materialNames(scene));
    checkShapes(scene, diags, warnings);
    checkFluidDef(scene, diags);
}

}  // namespace granulab::io
