// SPDX-License-Identifier: MIT
// Continuum coarse-graining (Goldhirsch 2010, Weinhart et al. 2012) of a DEM snapshot; the
// conventions and the momentum-balance derivation are in the header.
#include "analysis/dem_coarse_grain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "analysis/quadrature.hpp"

namespace granulab::analysis {

namespace {

/// The points binned in square cells of edge `cell` [m]: visit the points within a box.
struct PointBins {
    Vec2 lo;
    Real cell = 1;
    std::size_t nx = 1, ny = 1;
    std::vector<std::size_t> start, items;

    PointBins(const std::vector<Vec2>& p, Real edge) : cell(edge) {
        if (p.empty()) return;
        lo = hiFrom(p, true);
        const Vec2 hi = hiFrom(p, false);
        nx = std::min<std::size_t>(4096, 1 + static_cast<std::size_t>((hi.x - lo.x) / cell));
        ny = std::min<std::size_t>(4096, 1 + static_cast<std::size_t>((hi.y - lo.y) / cell));
        start.assign(nx * ny + 1, 0);
        for (const Vec2& q : p) ++start[bin(q) + 1];
        for (std::size_t k = 0; k < nx * ny; ++k) start[k + 1] += start[k];
        items.resize(p.size());
        std::vector<std::size_t> fill(start.begin(), start.end() - 1);
        for (std::size_t n = 0; n < p.size(); ++n) items[fill[bin(p[n])]++] = n;
    }
    static Vec2 hiFrom(const std::vector<Vec2>& p, bool low) {
        Vec2 e = p.front();
        for (const Vec2& q : p)
            e = low ? Vec2{std::min(e.x, q.x), std::min(e.y, q.y)}
                    : Vec2{std::max(e.x, q.x), std::max(e.y, q.y)};
        return e;
    }
    std::size_t axis(Real v, Real o, std::size_t n) const {
        const Real c = std::floor((v - o) / cell);
        return c <= 0 ? 0 : std::min(n - 1, static_cast<std::size_t>(c));
    }
    std::size_t bin(Vec2 q) const { return axis(q.y, lo.y, ny) * nx + axis(q.x, lo.x, nx); }
    template <class F>
    void forEach(Vec2 a, Vec2 b, F&& f) const {  // points possibly inside the box [a, b]
        if (items.empty()) return;
        const std::size_t i0 = axis(a.x, lo.x, nx), i1 = axis(b.x, lo.x, nx);
        const std::size_t j0 = axis(a.y, lo.y, ny), j1 = axis(b.y, lo.y, ny);
        for (std::size_t j = j0; j <= j1; ++j)
            for (std::size_t i = i0; i <= i1; ++i)
                for (std::size_t m = start[j * nx + i]; m < start[j * nx + i + 1]; ++m) f(items[m]);
    }
};

/// I(r) = int_0^1 phi(|d - s b|) ds with d = r - r_x, split where the integrand is not smooth.
Real lineIntegral(const CoarseGrainParams& p, const GaussLegendre& q, Real cutoff, Vec2 d, Vec2 b) {
    const Real bb = norm2(b);
    if (bb == 0) return kernelValue(p, norm(d));
    Real cuts[5] = {0, 1, 0, 0, 0};  // ends, closest approach, two cutoff crossings
    std::size_t nc = 2;
    const Real db = dot(d, b), sStar = db / bb;
    if (sStar > 0 && sStar < 1) cuts[nc++] = sStar;
    // |d - s b|^2 = cutoff^2 : bb s^2 - 2 db s + |d|^2 - cutoff^2 = 0
    const Real disc = db * db - bb * (norm2(d) - cutoff * cutoff);
    if (disc <= 0) return 0;  // the line never enters the support
    const Real root = std::sqrt(disc);
    for (const Real s : {(db - root) / bb, (db + root) / bb})
        if (s > 0 && s < 1) cuts[nc++] = s;
    for (std::size_t i = 1; i < nc; ++i)  // insertion sort (std::sort trips -Warray-bounds at -O3)
        for (std::size_t j = i; j > 0 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);
    Real sum = 0;
    for (std::size_t k = 0; k + 1 < nc; ++k) {
        const Real s0 = cuts[k], len = cuts[k + 1] - s0;
        if (len <= 0) continue;
        if (norm(d - b * (s0 + 0.5 * len)) >= cutoff) continue;  // piece outside the support
        Real piece = 0;
        for (std::size_t g = 0; g < q.node.size(); ++g)
            piece += q.weight[g] * kernelValue(p, norm(d - b * (s0 + len * q.node[g])));
        sum += len * piece;
    }
    return sum;
}

}  // namespace

Real kernelCutoff(const CoarseGrainParams& p) {
    return p.kernel == CoarseKernel::Gaussian ? 3 * p.width : p.width;
}

Real kernelValue(const CoarseGrainParams& p, Real r) {
    if (p.kernel == CoarseKernel::Gaussian) {
        const Real w = p.width;
        if (r >= 3 * w) return 0;
        return std::exp(-r * r / (2 * w * w)) / (2 * kPi * w * w * (1 - std::exp(-4.5)));
    }
    const Real c = p.width, s = r / c;
    if (s >= 1) return 0;
    const Real t = 1 - s;
    return 5 / (kPi * c * c) * (1 + 3 * s) * t * t * t;
}

std::vector<Vec2> gridPoints(Vec2 origin, Real dx, Real dy, std::size_t nx, std::size_t ny) {
    std::vector<Vec2> p;
    p.reserve(nx * ny);
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i)
            p.push_back(origin + Vec2{static_cast<Real>(i) * dx, static_cast<Real>(j) * dy});
    return p;
}

CoarseGrainFields coarseGrain(const GrainFrame& grains, const ContactFrame& contacts,
                              const std::vector<Vec2>& points, const CoarseGrainParams& params) {
    if (!(params.width > 0) || !std::isfinite(params.width))
        throw std::invalid_argument("coarseGrain: kernel width must be finite and > 0");
    if (params.quadraturePoints == 0)
        throw std::invalid_argument("coarseGrain: quadraturePoints must be >= 1");
    const GaussLegendre q = gaussLegendre(params.quadraturePoints);
    const Real R = kernelCutoff(params);
    const std::size_t np = points.size();
    CoarseGrainFields f;
    f.points = points;
    for (auto* v : {&f.rho, &f.jx, &f.jz, &f.vx, &f.vz, &f.kxx, &f.kxz, &f.kzz, &f.cxx, &f.cxz, &f.czx,
                    &f.czz, &f.fcx, &f.fcz, &f.fwx, &f.fwz})
        v->assign(np, 0);
    const PointBins bins(points, R);
    const Vec2 reach{R, R};
    const std::size_t n = grains.size();
    std::vector<Real> mvv(3 * np, 0);  // sum m v v phi: xx, xz, zz
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 ri{grains.x[i], grains.y[i]};
        const Real m = grains.mass[i], vx = grains.vx[i], vz = grains.vy[i];
        bins.forEach(ri - reach, ri + reach, [&](std::size_t k) {
            const Real phi = kernelValue(params, norm(points[k] - ri));
            if (phi == 0) return;
            f.rho[k] += m * phi;
            f.jx[k] += m * vx * phi;
            f.jz[k] += m * vz * phi;
            mvv[3 * k] += m * vx * vx * phi;
            mvv[3 * k + 1] += m * vx * vz * phi;
            mvv[3 * k + 2] += m * vz * vz * phi;
        });
    }
    std::size_t empty = 0;
    for (std::size_t k = 0; k < np; ++k) {
        if (f.rho[k] > 0) {
            f.vx[k] = f.jx[k] / f.rho[k];
            f.vz[k] = f.jz[k] / f.rho[k];
            // sum m v' v' phi = sum m v v phi - rho V V
            f.kxx[k] = mvv[3 * k] - f.rho[k] * f.vx[k] * f.vx[k];
            f.kxz[k] = mvv[3 * k + 1] - f.rho[k] * f.vx[k] * f.vz[k];
            f.kzz[k] = mvv[3 * k + 2] - f.rho[k] * f.vz[k] * f.vz[k];
        } else {
            f.vx[k] = f.vz[k] = std::numeric_limits<Real>::quiet_NaN();
            ++empty;
        }
    }
    if (empty > 0)
        f.notes.push_back("points without grains in reach (v = NaN): " + std::to_string(empty) + " of " +
                          std::to_string(np));

    std::unordered_map<std::int64_t, std::size_t> slot;
    slot.reserve(n);
    for (std::size_t i = 0; i < n; ++i) slot.emplace(grains.id[i], i);
    const auto centre = [&](std::int64_t id) {
        const auto it = slot.find(id);
        if (it == slot.end())
            throw std::invalid_argument("coarseGrain: contact names grain id " + std::to_string(id) +
                                        " that is not in the grain frame");
        return Vec2{grains.x[it->second], grains.y[it->second]};
    };
    // One side of a contact: force F on the grain at centre rc, applied at c.
    const auto side = [&](Vec2 rc, Vec2 c, Vec2 F) {
        const Vec2 b = c - rc;
        const Vec2 lo{std::min(rc.x, c.x), std::min(rc.y, c.y)}, hi{std::max(rc.x, c.x), std::max(rc.y, c.y)};
        bins.forEach(lo - reach, hi + reach, [&](std::size_t k) {
            const Vec2 d = points[k] - rc;
            const Real phiCentre = kernelValue(params, norm(d));
            f.fcx[k] += F.x * phiCentre;
            f.fcz[k] += F.y * phiCentre;
            const Real I = lineIntegral(params, q, R, d, b);
            if (I == 0) return;
            f.cxx[k] -= F.x * b.x * I;  // sigma_ab = - F_a b_b I
            f.cxz[k] -= F.x * b.y * I;
            f.czx[k] -= F.y * b.x * I;
            f.czz[k] -= F.y * b.y * I;
        });
    };
    for (std::size_t c = 0; c < contacts.size(); ++c) {
        const Vec2 p{contacts.px[c], contacts.py[c]}, F{contacts.fx[c], contacts.fy[c]};
        side(centre(contacts.a[c]), p, F);
        if (contacts.b[c] >= 0) {
            side(centre(contacts.b[c]), p, -F);
        } else {
            bins.forEach(p - reach, p + reach, [&](std::size_t k) {
                const Real phi = kernelValue(params, norm(points[k] - p));
                f.fwx[k] += F.x * phi;
                f.fwz[k] += F.y * phi;
            });
        }
    }
    return f;
}

Table coarseGrainTable(const CoarseGrainFields& f, const CoarseGrainParams& p) {
    Table t;
    t.name = "coarse_grain";
    t.notes.push_back(std::string("kernel = ") + (p.kernel == CoarseKernel::Gaussian ? "gaussian" : "lucy"));
    t.notes.push_back("width = " + std::to_string(p.width) + " [m]");
    t.notes.push_back("contact stress compressive-positive; div sigma^c = -f^c + f^w");
    t.notes.insert(t.notes.end(), f.notes.begin(), f.notes.end());
    const char* names[] = {"x",         "z",         "rho",       "v_x",       "v_z",
                           "sigmak_xx", "sigmak_xz", "sigmak_zz", "sigmac_xx", "sigmac_xz",
                           "sigmac_zx", "sigmac_zz", "sigma_xx",  "sigma_zz"};
    const char* units[] = {"m",   "m",   "kg/m^2", "m/s", "m/s", "N/m", "N/m",
                           "N/m", "N/m", "N/m",    "N/m", "N/m", "N/m", "N/m"};
    for (std::size_t c = 0; c < 14; ++c) t.add(names[c], units[c]);
    for (std::size_t k = 0; k < f.points.size(); ++k) {
        const Real row[] = {f.points[k].x,
                            f.points[k].y,
                            f.rho[k],
                            f.vx[k],
                            f.vz[k],
                            f.kxx[k],
                            f.kxz[k],
                            f.kzz[k],
                            f.cxx[k],
                            f.cxz[k],
                            f.czx[k],
                            f.czz[k],
                            f.kxx[k] + f.cxx[k],
                            f.kzz[k] + f.czz[k]};
        for (std::size_t col = 0; col < 14; ++col) t.columns[col].values.push_back(row[col]);
    }
    return t;
}

}  // namespace granulab::analysis
