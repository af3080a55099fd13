// SPDX-License-Identifier: MIT
// [[shape]] validation and polygon start-overlap geometry (gc2d spec sections 2.1-2.3).
#include "io/shape_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/suggest.hpp"
#include "geom/polygon.hpp"
#include "geom/segment.hpp"
#include "model/gc2d_generators.hpp"
#include "model/grain_shapes.hpp"

namespace granulab::io {

namespace {

const std::vector<std::string> kModes = {"const", "equal", "gauss"};
const std::vector<std::string> kCornerAngles = {"regular", "rand1", "rand2", "full", "special_rectangle"};

void cornerCountInRange(Diagnostics& d, const SourceLoc& loc, const std::string& key, std::int64_t n) {
    if (n < 3 || n > model::kMaxShapeCorners)
        d.error(loc, key,
                fmt::format("must be in [3, {}] (a polygon needs at least 3 corners), got {}",
                            model::kMaxShapeCorners, n));
}

void positiveSize(Diagnostics& d, const SourceLoc& loc, const std::string& key, Vec2 size) {
    if (!(size.x > 0 && size.y > 0))
        d.error(loc, key,
                fmt::format("both entries must be > 0 [m], got [{}, {}]; allowed (0, inf)", size.x, size.y));
}

/// Explains a corner-list problem of geom::checkConvexPolygon, with the corner index of the list
/// as written.
std::string describe(const geom::ShapeProblem& p, std::size_t n) {
    if (p.what == "fewer than 3 corners") return fmt::format("a polygon needs at least 3 corners, got {}", n);
    if (p.what == "duplicate")
        return fmt::format("corner {} coincides with a neighbouring corner (duplicate)", p.corner);
    if (p.what == "collinear")
        return fmt::format(
            "corner {} lies on the straight line through its neighbours (collinear); remove it", p.corner);
    if (p.what == "non-convex")
        return fmt::format("the polygon is not convex at corner {}; corners must form a convex polygon",
                           p.corner);
    if (p.what == "self-intersecting")
        return fmt::format(
            "the corners wind around the polygon more than once (self-intersecting, from corner {}); "
            "list them once around, counter-clockwise",
            p.corner);
    return fmt::format("{} at corner {}", p.what, p.corner);
}

void checkPolygonCorners(const model::ShapeDef& s, const std::string& key, Diagnostics& d,
                         std::vector<std::string>& warnings) {
    if (s.corners.size() >
        static_cast<std::size_t>(model::kMaxShapeCorners)) {  // feature caches hold 16-bit indices
        d.error(s.loc, key,
                fmt::format("{} corners; allowed [3, {}]", s.corners.size(), model::kMaxShapeCorners));
        return;
    }
    geom::ShapeProblem p = geom::checkConvexPolygon(s.corners);
    if (p.what == "clockwise") {
        std::vector<Vec2> ccw(s.corners.rbegin(), s.corners.rend());
        p = geom::checkConvexPolygon(ccw);
        if (p.ok()) {
            warnings.push_back(
                fmt::format("{}: {}: the corners of shape '{}' are listed clockwise; "
                            "reversed to counter-clockwise",
                            s.loc.str(), key, s.name));
            return;
        }
        const int n = static_cast<int>(s.corners.size());
        if (p.corner >= 0) p.corner = n - 1 - p.corner;  // index in the list as written
    }
    if (!p.ok()) d.error(s.loc, key, describe(p, s.corners.size()));
}

void checkShapeDef(const model::ShapeDef& s, std::size_t k, const std::vector<model::ShapeDef>& all,
                   Diagnostics& d, std::vector<std::string>& warnings) {
    const std::string key = fmt::format("shape[{}]", k);
    if (s.name.empty() || s.name == "disk")
        d.error(s.loc, key + ".name",
                fmt::format("'{}' cannot name a shape (\"disk\" is the built-in round particle)", s.name));
    for (std::size_t j = 0; j < k; ++j)
        if (all[j].name == s.name && !s.name.empty())
            d.error(s.loc, key + ".name",
                    fmt::format("duplicate shape name '{}' (first defined at {})", s.name, all[j].loc.str()));
    checkOneOf(d, s.loc, key + ".rotation_mode", s.rotationMode, kModes);
    if (s.kind == "polygon") {
        checkPolygonCorners(s, key + ".corners", d, warnings);
    } else if (s.kind == "regular") {
        cornerCountInRange(d, s.loc, key + ".corner_count", s.cornerCount);
        if (!(s.radius > 0))
            d.error(s.loc, key + ".radius",
                    fmt::format("must be > 0 [m], got {}; allowed (0, inf)", s.radius));
    } else if (s.kind == "rectangle") {
        positiveSize(d, s.loc, key + ".size", s.size);
        if (!(s.chamfer >= 0 && s.chamfer < 0.5))
            d.error(s.loc, key + ".chamfer", fmt::format("must be in [0, 0.5), got {}", s.chamfer));
    } else if (s.kind == "ellipse") {
        positiveSize(d, s.loc, key + ".size", s.size);
        cornerCountInRange(d, s.loc, key + ".corner_count", s.cornerCount);
    } else if (s.kind == "grain") {
        positiveSize(d, s.loc, key + ".size", s.size);
        checkOneOf(d, s.loc, key + ".size_mode", s.sizeMode, kModes);
        checkOneOf(d, s.loc, key + ".corner_count_mode", s.cornerCountMode, kModes);
        checkOneOf(d, s.loc, key + ".corner_angles", s.cornerAngles, kCornerAngles);
        if (!(s.sizeVariation >= 0 && s.sizeVariation < 1))
            d.error(s.loc, key + ".size_variation",
                    fmt::format("must be in [0, 1), got {}", s.sizeVariation));
        if (s.cornerAngles != "special_rectangle") {
            cornerCountInRange(d, s.loc, key + ".corner_count", s.cornerCount);
            if (s.cornerVariation < 0)
                d.error(s.loc, key + ".corner_variation",
                        fmt::format("must be >= 0, got {}", s.cornerVariation));
            else if (s.cornerCountMode != "const" && s.cornerCount >= 3 &&
                     (s.cornerCount - s.cornerVariation < 3 ||
                      s.cornerCount + s.cornerVariation > model::kMaxShapeCorners))
                d.error(s.loc, key + ".corner_variation",
                        fmt::format(
                            "corner counts [{}, {}] (corner_count -+ corner_variation) must lie in [3, {}]",
                            s.cornerCount - s.cornerVariation, s.cornerCount + s.cornerVariation,
                            model::kMaxShapeCorners));
        }
    }
}

}  // namespace

void checkShapes(const model::SceneDef& sc, Diagnostics& d, std::vector<std::string>& warnings) {
    std::vector<std::string> names = {"disk"};
    for (std::size_t k = 0; k < sc.shapes.size(); ++k) {
        checkShapeDef(sc.shapes[k], k, sc.shapes, d, warnings);
        names.push_back(sc.shapes[k].name);
    }
    const auto find = [&](const std::string& name) -> const model::ShapeDef* {
        for (const auto& s : sc.shapes)
            if (s.name == name) return &s;
        return nullptr;
    };
    const auto known = [&](const SourceLoc& loc, const std::string& key, const std::string& name) {
        if (name == "disk" || find(name)) return true;
        d.error(
            loc, key,
            fmt::format("unknown shape '{}'{}; defined: {}", name, didYouMean(name, names), joinList(names)));
        return false;
    };
    std::string polygonUser;  // a particle or block with a polygon shape, for the mass-model check
    for (std::size_t k = 0; k < sc.particles.size(); ++k) {
        const auto& p = sc.particles[k];
        const std::string key = fmt::format("particle[{}]", k);
        if (!known(p.loc, key + ".shape", p.shape)) continue;
        if (p.shape == "disk") {
            if (!(p.radius > 0) || !std::isfinite(p.radius))
                d.error(p.loc, key + ".radius",
                        fmt::format("must be > 0 [m], got {}; allowed (0, inf)", p.radius));
        } else if (polygonUser.empty()) {
            polygonUser = fmt::format("{} ({}, shape '{}')", key, p.loc.str(), p.shape);
        }
    }
    for (std::size_t k = 0; k < sc.blocks.size(); ++k) {
        const auto& b = sc.blocks[k];
        const std::string key = fmt::format("block[{}]", k);
        if (!known(b.loc, key + ".shape", b.shape) || b.shape == "disk") continue;
        if (polygonUser.empty()) polygonUser = fmt::format("{} ({}, shape '{}')", key, b.loc.str(), b.shape);
        const Real spacing = model::nearestSiteDistance(b);  // b.spacing for hexagonal and square
        if (!(spacing > 0)) continue;
        const bool gc2d =
            b.lattice == model::BlockDef::Lattice::Rect || b.lattice == model::BlockDef::Lattice::Fcc;
        // Shapes of fixed size and orientation (square lattices of squares, as in LAMMPS's
        // polygon piles) may sit closer than their circumcircles: the exact start-overlap check
        // of the generated particles decides. Random sizes or rotations need the bound.
        const model::ShapeDef& shape = *find(b.shape);
        if (shape.kind != "grain" && shape.rotationMode == "const") continue;
        const Real rmax = model::maxPlacementRadius(shape);
        if (rmax > 0 && 2 * rmax > spacing)
            d.error(
                b.loc, key + (gc2d ? ".grid" : ".spacing"),
                fmt::format(
                    "{} {:.6g} m is smaller than {:.6g} m, twice the largest circumradius {:.6g} m of shape "
                    "'{}': neighbours could overlap",
                    gc2d ? "the nearest-site distance of grid" : "spacing", spacing, 2 * rmax, rmax,
                    b.shape));
    }
    for (std::size_t k = 0; k < sc.heaps.size() && polygonUser.empty(); ++k)  // shapes: checkHeap()
        if (sc.heaps[k].shape != "disk" || sc.heaps[k].size.x != 0 || sc.heaps[k].size.y != 0)
            polygonUser = fmt::format("heap[{}] ({}, {})", k, sc.heaps[k].loc.str(),
                                      sc.heaps[k].shape != "disk" ? "shape '" + sc.heaps[k].shape + "'"
                                                                  : std::string("rectangles"));
    if (!polygonUser.empty() && sc.dem.massModel != "disk")
        d.error(
            sc.dem.loc, "dem.mass_model",
            fmt::format("polygon particles need mass_model = \"disk\" (areal density in kg/m^2), got '{}'; "
                        "the first polygon is {}",
                        sc.dem.massModel, polygonUser));
}

}  // namespace granulab::io
