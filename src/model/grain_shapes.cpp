// SPDX-License-Identifier: MIT
// Grain shapes of gc2d (spec section 2.3): deterministic polygons and random grains inscribed in
// ellipses (App. B.1.6, Eq. B.4/B.5).
#include "model/grain_shapes.hpp"

#include <algorithm>
#include <cmath>

#include "geom/polygon.hpp"

namespace granulab::model {

std::vector<Vec2> ellipsePolygon(Real a, Real b, int n) {
    std::vector<Vec2> c;
    c.reserve(static_cast<std::size_t>(std::max(n, 0)));
    for (int i = 0; i < n; ++i) {
        const Real phi = 2 * kPi * i / n;
        c.push_back({a * std::cos(phi), b * std::sin(phi)});
    }
    return c;
}

std::vector<Vec2> regularPolygon(int n, Real r) {
    return ellipsePolygon(r, r, n);
}

std::vector<Vec2> rectangle(Real a, Real b, Real chamfer) {
    const Real x = 0.5 * a, y = 0.5 * b;
    if (!(chamfer > 0)) return {{-x, -y}, {x, -y}, {x, y}, {-x, y}};
    // Each edge keeps its middle a (1 - 2c) (resp. b (1 - 2c)); the corners are cut straight.
    const Real xc = x - chamfer * a, yc = y - chamfer * b;
    return {{-xc, -y}, {xc, -y}, {x, -yc}, {x, yc}, {xc, y}, {-xc, y}, {-x, yc}, {-x, -yc}};
}

Real specialGaussianUnit(CounterRng& rng) {
    for (int attempt = 0; attempt < 1000000; ++attempt) {
        const Real u = 0.5 + 0.1 * rng.normal();
        if (u >= 0 && u <= 1) return u;
    }
    return 0.5;  // unreachable in practice: a draw beyond 5 sigma has probability 6e-7
}

namespace {

/// One semi-axis l [m] with relative variation I by size mode.
Real drawAxis(const std::string& mode, Real l, Real variation, CounterRng& rng) {
    const Real lo = l * (1 - variation), hi = l * (1 + variation);
    if (mode == "equal") return rng.uniform(lo, hi);
    if (mode == "gauss") return lo + specialGaussianUnit(rng) * (hi - lo);
    return l;
}

int drawCornerCount(const ShapeDef& d, CounterRng& rng) {
    const std::int64_t ne = d.cornerCount, ni = d.cornerVariation;
    const std::int64_t lo = std::max<std::int64_t>(3, ne - ni), hi = std::max(lo, ne + ni);
    std::int64_t n = ne;
    if (d.cornerCountMode == "equal") {
        n = lo + static_cast<std::int64_t>(rng.uniform() * static_cast<Real>(hi - lo + 1));
        n = std::min(n, hi);
    } else if (d.cornerCountMode == "gauss") {
        n = std::llround(static_cast<Real>(lo) + specialGaussianUnit(rng) * static_cast<Real>(hi - lo));
    }
    return static_cast<int>(std::clamp<std::int64_t>(n, 3, kMaxShapeCorners));
}

std::vector<Real> drawAngles(const std::string& mode, int n, CounterRng& rng) {
    std::vector<Real> phi(static_cast<std::size_t>(n));
    const Real step = 2 * kPi / n;
    for (int i = 0; i < n; ++i) {
        Real p = i * step;  // "regular"
        if (mode == "rand1")
            p = rng.uniform((i - 0.5) * step, (i + 0.5) * step);
        else if (mode == "rand2")
            p = rng.uniform((i - 1.0) * step, (i + 1.0) * step);
        else if (mode == "full")
            p = rng.uniform(0, 2 * kPi);
        // Reduce to [0, 2 pi) before sorting, so that the corners go round the ellipse once.
        p = std::fmod(p, 2 * kPi);
        if (p < 0) p += 2 * kPi;
        if (p >= 2 * kPi) p = 0;
        phi[static_cast<std::size_t>(i)] = p;
    }
    std::sort(phi.begin(), phi.end());
    return phi;
}

/// Corners for sorted angles, dropping corners within `tol` of the previous kept one (and the
/// last one if it comes within `tol` of the first).
void cornersOnEllipse(Real a, Real b, Real tol, std::vector<Real>& phi, std::vector<Vec2>& out) {
    out.clear();
    std::vector<Real> kept;
    for (const Real p : phi) {
        const Vec2 c{a * std::cos(p), b * std::sin(p)};
        if (!out.empty() && norm(c - out.back()) <= tol) continue;
        out.push_back(c);
        kept.push_back(p);
    }
    if (out.size() > 1 && norm(out.back() - out.front()) <= tol) {
        out.pop_back();
        kept.pop_back();
    }
    phi.swap(kept);
}

}  // namespace

Grain randomGrain(const ShapeDef& d, CounterRng& rng) {
    Grain g;
    const Vec2 l = d.fullAxes ? d.size * 0.5 : d.size;
    g.semiAxes = {drawAxis(d.sizeMode, l.x, d.sizeVariation, rng),
                  drawAxis(d.sizeMode, l.y, d.sizeVariation, rng)};
    const Real a = g.semiAxes.x, b = g.semiAxes.y;
    if (d.cornerAngles == "special_rectangle") {
        g.corners = rectangle(2 * a, 2 * b, kSpecialRectangleChamfer);
        return g;
    }
    g.drawnCorners = drawCornerCount(d, rng);
    const Real tol = 1e-9 * std::max(std::abs(a), std::abs(b));
    for (int attempt = 0; attempt <= 1000; ++attempt) {
        const std::string& mode = attempt < 1000 ? d.cornerAngles : std::string("regular");
        g.angles = drawAngles(mode, g.drawnCorners, rng);
        cornersOnEllipse(a, b, tol, g.angles, g.corners);
        if (g.corners.size() >= 3 && geom::checkConvexPolygon(g.corners).ok()) break;
        ++g.redraws;
    }
    return g;
}

Real drawRotation(const ShapeDef& d, CounterRng& rng) {
    if (d.rotationMode == "equal") return rng.uniform(0, 2 * kPi);
    if (d.rotationMode == "gauss") {
        Real u = specialGaussianUnit(rng);
        while (u <= 0 || u >= 1) u = specialGaussianUnit(rng);  // open interval
        return d.rotation - 0.5 * kPi + u * kPi;
    }
    return d.rotation;
}

std::optional<std::vector<Vec2>> deterministicCorners(const ShapeDef& d) {
    std::vector<Vec2> c;
    const bool countOk = d.cornerCount >= 3 && d.cornerCount <= kMaxShapeCorners;
    const int n = static_cast<int>(d.cornerCount);
    if (d.kind == "polygon") {
        c = d.corners;
        Real area2 = 0;
        for (std::size_t k = 0; k < c.size(); ++k) area2 += cross(c[k], c[(k + 1) % c.size()]);
        if (area2 < 0) std::reverse(c.begin(), c.end());
    } else if (d.kind == "regular") {
        if (!countOk || !(d.radius > 0)) return std::nullopt;
        c = regularPolygon(n, d.radius);
    } else if (d.kind == "rectangle") {
        if (!(d.size.x > 0 && d.size.y > 0 && d.chamfer >= 0 && d.chamfer < 0.5)) return std::nullopt;
        c = rectangle(d.size.x, d.size.y, d.chamfer);
    } else if (d.kind == "ellipse") {
        if (!countOk || !(d.size.x > 0 && d.size.y > 0)) return std::nullopt;
        c = ellipsePolygon(d.size.x, d.size.y, n);
    } else {
        return std::nullopt;
    }
    if (!geom::checkConvexPolygon(c).ok()) return std::nullopt;
    return c;
}

Real maxPlacementRadius(const ShapeDef& d) {
    if (d.kind != "grain") {
        const auto c = deterministicCorners(d);
        if (!c) return 0;
        const Vec2 centroid = geom::polygonMass(*c).centroid;
        Real r = 0;
        for (const Vec2& p : *c) r = std::max(r, norm(p - centroid));
        return r;
    }
    const Vec2 l = d.fullAxes ? d.size * 0.5 : d.size;
    const Real grow = d.sizeMode == "const" ? 1.0 : 1.0 + d.sizeVariation;
    const Real a = l.x * grow, b = l.y * grow;
    if (!(a > 0 && b > 0)) return 0;
    if (d.cornerAngles == "special_rectangle") {
        Real r = 0;
        for (const Vec2& p : rectangle(2 * a, 2 * b, kSpecialRectangleChamfer)) r = std::max(r, norm(p));
        return r;
    }
    return std::max(a, b);
}

}  // namespace granulab::model
