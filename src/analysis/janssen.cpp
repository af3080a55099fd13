// SPDX-License-Identifier: MIT
// Janssen silo stresses in 2D (gc2d spec section 8.3, Eq. 3.11/3.12, 3.15, 3.17/3.18 corrected,
// 3.20-3.24), their numerical integration for any r(z), and the k / mu_j fits.
#include "analysis/janssen.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

#include "analysis/quadrature.hpp"

namespace granulab::analysis {

namespace {

constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();

void requirePositive(Real v, const char* what) {
    if (!(v > 0) || !std::isfinite(v))
        throw std::invalid_argument(std::string("janssen: ") + what + " must be finite and > 0");
}

void checkParams(const JanssenParams& p) {
    requirePositive(p.k, "k");
    requirePositive(p.mu, "mu_j");
    requirePositive(p.rho, "rho");
    requirePositive(p.g, "g");
}

/// Straight-silo sigma_zz [N/m] of radius r at depth z, continued from sigma0 at depth z0.
Real straightFrom(Real r, const JanssenParams& p, Real z, Real z0, Real sigma0) {
    const Real e = std::exp(-p.k * p.mu * (z - z0) / r);
    return sigma0 * e + p.rho * p.g * r / (p.k * p.mu) * (1 - e);
}

/// The piece [lo, hi] of `breaks` (ascending, with 0 and +inf added) that holds z, z in (lo, hi].
std::pair<Real, Real> pieceOf(const std::vector<Real>& breaks, Real z) {
    Real lo = 0, hi = std::numeric_limits<Real>::infinity();
    for (const Real b : breaks) {
        if (b < z) lo = std::max(lo, b);
        if (b >= z) hi = std::min(hi, b);
    }
    return {lo, hi};
}

/// r'(z) [1] by central differences strictly inside (lo, hi) (one-sided near its ends, 1 nm
/// away from them so a jump of r at a breakpoint is never sampled).
Real numericSlope(const std::function<Real(Real)>& r, Real z, Real lo, Real hi) {
    const Real d = 1e-6, margin = 1e-9;
    const Real zm = std::max(lo + margin, z - d), zp = std::min(hi - margin, z + d);
    if (zp <= zm) return 0;
    return (r(zp) - r(zm)) / (zp - zm);
}

/// xi'(z) of Eq. 3.12 [1/m] inside the piece (lo, hi).
Real xiPrime(const SiloShape& s, Real k, Real z, Real lo, Real hi) {
    const Real eps = 1e-12 * std::max<Real>(1, std::abs(z));
    z = std::clamp(z, lo + eps, std::isfinite(hi) ? hi - eps : z);
    const Real r = s.halfWidth(z);
    Real dr;
    if (s.kind == SiloShape::Kind::General && !s.slope)
        dr = numericSlope(s.radius, z, lo, std::isfinite(hi) ? hi : z + 1);
    else
        dr = s.halfWidthSlope(z);
    const Real q = 1 + dr * dr;
    return (dr * dr + k) / (r * q * std::sqrt(q));
}

std::vector<Real> breaksOf(const SiloShape& s) {
    if (s.kind == SiloShape::Kind::Stepped) return {s.h0};
    if (s.kind == SiloShape::Kind::General) return s.breakpoints;
    return {};
}

}  // namespace

Real SiloShape::halfWidth(Real z) const {
    switch (kind) {
        case Kind::Straight:
            return r;
        case Kind::Stepped:
            return z < h0 ? r1 : r2;
        case Kind::Slanted:
            return a * z + b;
        case Kind::Parabolic:
            return z <= b ? std::sqrt((b - z) / a) : kNaN;
        case Kind::General:
            return radius(z);
    }
    return kNaN;
}

Real SiloShape::halfWidthSlope(Real z) const {
    switch (kind) {
        case Kind::Straight:
        case Kind::Stepped:
            return 0;
        case Kind::Slanted:
            return a;
        case Kind::Parabolic:
            return -1 / (2 * a * halfWidth(z));
        case Kind::General: {
            if (slope) return slope(z);
            const auto [lo, hi] = pieceOf(breakpoints, z);
            return numericSlope(radius, z, lo, std::isfinite(hi) ? hi : z + 1);
        }
    }
    return kNaN;
}

SiloShape straightSilo(Real r) {
    requirePositive(r, "straight silo r");
    SiloShape s;
    s.kind = SiloShape::Kind::Straight;
    s.r = r;
    return s;
}

SiloShape steppedSilo(Real r1, Real r2, Real h0) {
    requirePositive(r2, "stepped silo r2");
    requirePositive(h0, "stepped silo h0");
    if (!(r1 > r2) || !std::isfinite(r1))
        throw std::invalid_argument("janssen: the stepped silo needs r1 > r2 (narrowing, spec 8.3)");
    SiloShape s;
    s.kind = SiloShape::Kind::Stepped;
    s.r1 = r1;
    s.r2 = r2;
    s.h0 = h0;
    return s;
}

SiloShape slantedSilo(Real a, Real b) {
    requirePositive(b, "slanted silo b");
    if (!std::isfinite(a)) throw std::invalid_argument("janssen: slanted silo a must be finite");
    SiloShape s;
    s.kind = SiloShape::Kind::Slanted;
    s.a = a;
    s.b = b;
    return s;
}

SiloShape parabolicSilo(Real a, Real b) {
    requirePositive(a, "parabolic silo a");
    requirePositive(b, "parabolic silo b");
    SiloShape s;
    s.kind = SiloShape::Kind::Parabolic;
    s.a = a;
    s.b = b;
    return s;
}

SiloShape generalSilo(std::function<Real(Real)> radius, std::function<Real(Real)> slope,
                      std::vector<Real> breakpoints) {
    if (!radius) throw std::invalid_argument("janssen: a general silo needs r(z)");
    SiloShape s;
    s.kind = SiloShape::Kind::General;
    s.radius = std::move(radius);
    s.slope = std::move(slope);
    std::sort(breakpoints.begin(), breakpoints.end());
    s.breakpoints = std::move(breakpoints);
    return s;
}

Real parabolicXi(Real k, Real a, Real b, Real z) {
    const auto F = [&](Real zz) {
        return (1 - 4 * k * a * b + 4 * k * a * zz - 2 * k) / std::sqrt(4 * a * b - 4 * a * zz + 1);
    };
    return F(z) - F(0);
}

Real parabolicEffectiveRadius(Real k, Real a, Real b) {
    requirePositive(k, "k");
    requirePositive(a, "parabolic silo a");
    requirePositive(b, "parabolic silo b");
    return k * std::pow(1 + 4 * a * b, 1.5) / (2 * a * (1 + 4 * k * a * b));
}

Real janssenSigmaZz(const SiloShape& s, const JanssenParams& p, Real z) {
    checkParams(p);
    if (!(z >= 0)) throw std::invalid_argument("janssen: depth z must be >= 0");
    const Real rg = p.rho * p.g;
    switch (s.kind) {
        case SiloShape::Kind::Straight:
            return straightFrom(s.r, p, z, 0, 0);
        case SiloShape::Kind::Stepped:
            if (z <= s.h0) return straightFrom(s.r1, p, z, 0, 0);
            return straightFrom(s.r2, p, z, s.h0, straightFrom(s.r1, p, s.h0, 0, 0));
        case SiloShape::Kind::Slanted: {
            const Real r = s.a * z + s.b;
            if (!(r > 0)) return kNaN;
            if (s.a == 0) return straightFrom(s.b, p, z, 0, 0);
            const Real alpha = std::pow(1 + s.a * s.a, 1.5), C = p.mu * (s.a * s.a + p.k);
            const Real denom = C + alpha * s.a;
            if (std::abs(denom) < 1e-12 * std::abs(alpha * s.a))  // limit C = -alpha a
                return rg / s.a * r * std::log(r / s.b);
            // Corrected Eq. 3.17/3.18: [r - r^(-C/(alpha a)) b^((C + alpha a)/(alpha a))]
            const Real e = C / (alpha * s.a);
            return alpha * rg / denom * (r - r * std::pow(r / s.b, -e - 1));
        }
        case SiloShape::Kind::Parabolic: {
            if (z > s.b) return kNaN;
            // sigma = rho g int_0^z exp(mu (xi(z') - xi(z))) dz', composite Gauss-Legendre.
            static const GaussLegendre q = gaussLegendre(16);
            const std::size_t panels = 32;
            const Real xiZ = parabolicXi(p.k, s.a, s.b, z), h = z / static_cast<Real>(panels);
            Real sum = 0;
            for (std::size_t m = 0; m < panels; ++m)
                for (std::size_t g = 0; g < q.node.size(); ++g) {
                    const Real zz = h * (static_cast<Real>(m) + q.node[g]);
                    sum += q.weight[g] * std::exp(p.mu * (parabolicXi(p.k, s.a, s.b, zz) - xiZ));
                }
            return rg * h * sum;
        }
        case SiloShape::Kind::General:
            return janssenNumeric(s, p, {z}).front();
    }
    return kNaN;
}

Real janssenSigmaXx(const SiloShape& s, const JanssenParams& p, Real z) {
    if (s.kind == SiloShape::Kind::Stepped && z > s.h0) {
        checkParams(p);
        // Eq. 3.15, below the step.
        const Real r1 = s.r1, r2 = s.r2, mk = p.mu * p.k;
        return p.rho * p.g / p.mu *
               ((r1 - r2) * std::exp(mk * (s.h0 - z) / r2) + r2 -
                r1 * std::exp(mk * (s.h0 * r1 - r1 * z - s.h0 * r2) / (r1 * r2)));
    }
    return p.k * janssenSigmaZz(s, p, z);
}

std::vector<Real> janssenNumeric(const SiloShape& s, const JanssenParams& p, const std::vector<Real>& z,
                                 Real step) {
    checkParams(p);
    requirePositive(step, "step");
    if (!std::is_sorted(z.begin(), z.end()) || (!z.empty() && !(z.front() >= 0)))
        throw std::invalid_argument("janssenNumeric: depths must be ascending and >= 0");
    std::vector<Real> breaks = breaksOf(s);
    std::vector<Real> out(z.size());
    Real zc = 0, sigma = 0;
    const Real rg = p.rho * p.g;
    for (std::size_t n = 0; n < z.size(); ++n) {
        while (zc < z[n]) {
            // integrate to the next target or breakpoint, whichever comes first
            const auto [lo, hi] = pieceOf(breaks, std::nextafter(zc, z[n]));
            const Real end = std::min(z[n], hi);
            const auto steps =
                std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil((end - zc) / step)));
            const Real h = (end - zc) / static_cast<Real>(steps);
            const auto f = [&](Real zz, Real sg) { return rg - p.mu * xiPrime(s, p.k, zz, lo, hi) * sg; };
            for (std::size_t m = 0; m < steps; ++m) {
                const Real z0 = zc + h * static_cast<Real>(m);
                const Real k1 = f(z0, sigma), k2 = f(z0 + 0.5 * h, sigma + 0.5 * h * k1);
                const Real k3 = f(z0 + 0.5 * h, sigma + 0.5 * h * k2), k4 = f(z0 + h, sigma + h * k3);
                sigma += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
            }
            zc = end;
        }
        out[n] = sigma;
    }
    return out;
}

JanssenFit fitJanssen(const SiloShape& shape, const std::vector<Real>& z, const std::vector<Real>& sxx,
                      const std::vector<Real>& szz, Real rho, Real g, Real kStart, Real muStart) {
    if (z.size() != sxx.size() || z.size() != szz.size())
        throw std::invalid_argument("fitJanssen: z, sigma_xx and sigma_zz need equal lengths");
    requirePositive(rho, "rho");
    requirePositive(g, "g");
    requirePositive(kStart, "start k");
    requirePositive(muStart, "start mu_j");
    std::vector<std::size_t> use;
    Real sumXx = 0, sumZz = 0;
    for (std::size_t i = 0; i < z.size(); ++i)
        if (std::isfinite(z[i]) && z[i] >= 0 && std::isfinite(sxx[i]) && std::isfinite(szz[i])) {
            use.push_back(i);
            sumXx += sxx[i] * sxx[i];
            sumZz += szz[i] * szz[i];
        }
    if (use.size() < 3) throw std::invalid_argument("fitJanssen: needs at least 3 finite samples");
    const auto m = static_cast<Real>(use.size());
    const Real wXx = sumXx > 0 ? std::sqrt(m / sumXx) : 1, wZz = sumZz > 0 ? std::sqrt(m / sumZz) : 1;
    std::vector<Real> zs;
    for (const std::size_t i : use) zs.push_back(z[i]);
    std::vector<std::size_t> order(use.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return zs[a] < zs[b]; });

    const auto residuals = [&](Real lk, Real lmu, std::vector<Real>& r) {
        const JanssenParams p{std::exp(lk), std::exp(lmu), rho, g};
        r.assign(2 * use.size(), 0);
        std::vector<Real> model(use.size());
        if (shape.kind == SiloShape::Kind::General) {
            std::vector<Real> sorted(use.size());
            for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = zs[order[i]];
            const std::vector<Real> s = janssenNumeric(shape, p, sorted);
            for (std::size_t i = 0; i < order.size(); ++i) model[order[i]] = s[i];
        } else {
            for (std::size_t i = 0; i < use.size(); ++i) model[i] = janssenSigmaZz(shape, p, zs[i]);
        }
        Real cost = 0;
        for (std::size_t i = 0; i < use.size(); ++i) {
            const Real mxx =
                shape.kind == SiloShape::Kind::Stepped ? janssenSigmaXx(shape, p, zs[i]) : p.k * model[i];
            r[2 * i] = (sxx[use[i]] - mxx) * wXx;
            r[2 * i + 1] = (szz[use[i]] - model[i]) * wZz;
            cost += r[2 * i] * r[2 * i] + r[2 * i + 1] * r[2 * i + 1];
        }
        return std::isfinite(cost) ? cost : std::numeric_limits<Real>::infinity();
    };
    JanssenFit fit;
    Real lk = std::log(kStart), lmu = std::log(muStart), lambda = 1e-3;
    std::vector<Real> r, rp, rm;
    Real cost = residuals(lk, lmu, r);
    const Real d = 1e-6;
    for (fit.iterations = 0; fit.iterations < 300; ++fit.iterations) {
        // Jacobian columns by central differences in (ln k, ln mu)
        Real A00 = 0, A01 = 0, A11 = 0, g0 = 0, g1 = 0;
        std::vector<Real> J0(r.size()), J1(r.size());
        residuals(lk + d, lmu, rp);
        residuals(lk - d, lmu, rm);
        for (std::size_t i = 0; i < r.size(); ++i) J0[i] = (rp[i] - rm[i]) / (2 * d);
        residuals(lk, lmu + d, rp);
        residuals(lk, lmu - d, rm);
        for (std::size_t i = 0; i < r.size(); ++i) J1[i] = (rp[i] - rm[i]) / (2 * d);
        for (std::size_t i = 0; i < r.size(); ++i) {
            A00 += J0[i] * J0[i];
            A01 += J0[i] * J1[i];
            A11 += J1[i] * J1[i];
            g0 += J0[i] * r[i];
            g1 += J1[i] * r[i];
        }
        bool accepted = false;
        Real step = 0;
        for (int tries = 0; tries < 40 && !accepted; ++tries) {
            const Real a00 = A00 * (1 + lambda), a11 = A11 * (1 + lambda);
            const Real det = a00 * a11 - A01 * A01;
            if (!(det > 0)) {
                lambda *= 10;
                continue;
            }
            const Real dk = -(a11 * g0 - A01 * g1) / det, dmu = -(a00 * g1 - A01 * g0) / det;
            const Real maxStep = 1;  // at most a factor e per step in k or mu
            const Real scale = std::min<Real>(1, maxStep / std::max(std::abs(dk), std::abs(dmu)));
            std::vector<Real> trial;
            const Real c = residuals(lk + scale * dk, lmu + scale * dmu, trial);
            if (c < cost) {
                lk += scale * dk;
                lmu += scale * dmu;
                step = scale * std::max(std::abs(dk), std::abs(dmu));
                const Real drop = cost - c;
                cost = c;
                r = std::move(trial);
                lambda = std::max<Real>(1e-12, lambda / 3);
                accepted = true;
                if (step < 1e-10 || drop < 1e-15 * cost) fit.converged = true;
            } else {
                lambda *= 4;
            }
        }
        if (!accepted) {  // no descent direction left: at a minimum to rounding
            fit.converged = true;
            break;
        }
        if (fit.converged) break;
    }
    fit.k = std::exp(lk);
    fit.mu = std::exp(lmu);
    fit.rms = std::sqrt(cost / static_cast<Real>(r.size()));
    return fit;
}

DepthProfile depthProfile(const StressGrid& s, Real surfaceY) {
    checkGrid(s.grid, "depthProfile");
    DepthProfile out;
    Real kSum = 0, kSum2 = 0;
    std::size_t kCount = 0;
    for (std::size_t jj = s.grid.ny; jj-- > 0;) {  // top row first: ascending depth
        Real xx = 0, zz = 0;
        std::size_t count = 0;
        for (std::size_t i = 0; i < s.grid.nx; ++i) {
            const std::size_t k = s.grid.index(i, jj);
            if (!std::isfinite(s.sigmaXx[k]) || !std::isfinite(s.sigmaZz[k])) continue;
            xx += s.sigmaXx[k];
            zz += s.sigmaZz[k];
            ++count;
            if (s.sigmaZz[k] != 0) {
                const Real ratio = s.sigmaXx[k] / s.sigmaZz[k];
                kSum += ratio;
                kSum2 += ratio * ratio;
                ++kCount;
            }
        }
        if (count == 0) continue;
        out.z.push_back(surfaceY - (s.grid.bottom(jj) + 0.5 * s.grid.h));
        out.sigmaXx.push_back(xx / static_cast<Real>(count));
        out.sigmaZz.push_back(zz / static_cast<Real>(count));
        out.areas.push_back(count);
    }
    if (kCount == 0) {
        out.kMean = out.kStd = kNaN;
    } else {
        const auto n = static_cast<Real>(kCount);
        out.kMean = kSum / n;
        out.kStd =
            kCount > 1 ? std::sqrt(std::max<Real>(0, (kSum2 - n * out.kMean * out.kMean) / (n - 1))) : 0;
    }
    return out;
}

Table janssenTable(const DepthProfile& pr, const SiloShape& shape, const JanssenFit& fit, Real rho, Real g) {
    Table t;
    t.name = "janssen";
    const auto fmt = [](Real v) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.4g", v);
        return std::string(buf);
    };
    t.notes.push_back("k = " + fmt(fit.k));
    t.notes.push_back("mu_j = " + fmt(fit.mu));
    t.notes.push_back("rho = " + fmt(rho) + " [kg/m^2]");
    t.notes.push_back("g = " + fmt(g) + " [m/s^2]");
    t.notes.push_back("fit rms = " + fmt(fit.rms) + (fit.converged ? "" : " (not converged)"));
    t.notes.push_back("k_areas = " + fmt(pr.kMean) + " +- " + fmt(pr.kStd));
    t.add("z", "m");
    t.add("sigma_xx", "N/m");
    t.add("sigma_zz", "N/m");
    t.add("sigma_xx_theory", "N/m");
    t.add("sigma_zz_theory", "N/m");
    const JanssenParams p{fit.k, fit.mu, rho, g};
    for (std::size_t i = 0; i < pr.z.size(); ++i) {
        const bool ok = pr.z[i] >= 0 && fit.k > 0 && fit.mu > 0;
        t.columns[0].values.push_back(pr.z[i]);
        t.columns[1].values.push_back(pr.sigmaXx[i]);
        t.columns[2].values.push_back(pr.sigmaZz[i]);
        t.columns[3].values.push_back(ok ? janssenSigmaXx(shape, p, pr.z[i]) : kNaN);
        t.columns[4].values.push_back(ok ? janssenSigmaZz(shape, p, pr.z[i]) : kNaN);
    }
    return t;
}

}  // namespace granulab::analysis
