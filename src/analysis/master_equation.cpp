// SPDX-License-Identifier: MIT
// Coagulation/fragmentation master equation (edmd spec section 5.6, Eqs. 5.29-5.43).
//
// Why these choices:
// - Eq. 5.31 as printed counts every ordered pair once in the merging gain and in the
//   fragmentation loss, so every reaction keeps the number of clusters: 1 + 1 -> 2 removes one
//   monomer and adds one dimer. sum_s p_s is then an exact invariant (consistent with
//   p_s = n_s/n_tot, normalised), while sum_s s p_s (mass) is not (erratum 14). It is the default
//   because the spec asks for the printed form and its equilibria are those of Eqs. 5.37-5.41
//   (sum p = 1 with the prefactor c fixed), which give the dichotomy of Fig. 5.24: for
//   lambda < lambda* the cut-off w > 0, above it w < 0 (weight at the largest sizes).
//   `symmetricGain` selects the standard Smoluchowski form (1/2 on both ordered-pair sums), which
//   conserves mass instead; detailed balance (Eq. 5.32) zeroes every reaction channel term by
//   term in both forms, so both have the states 5.34-5.35 as fixed points (with different
//   normalisations selecting w).
// - Integrator: explicit Dormand-Prince 5(4) (FSAL, error per component against
//   absTol + relTol |y|, PI step control err^-0.17 errOld^0.04 clamped to [0.2, 5]). The
//   problem is only mildly stiff (fragmentation rates grow like s^(1-1/D)), so an explicit method is adequate
//   and keeps the code dependency-free. The exact solution keeps p_s >= 0 (every loss term is
//   proportional to p_s). Components that are ~0 oscillate around 0 at the accuracy level when
//   the step sits at the stability limit: undershoots within 10 tolerance units are clipped to 0
//   and the state is rescaled to restore its linear invariant (sum p in the printed form, sum s y
//   in the symmetric form), deeper undershoots reject the step and halve it.
#include "analysis/master_equation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace granulab::analysis {

namespace {

void validate(const MasterEquationParams& p) {
    auto fail = [](const std::string& what) { throw std::invalid_argument("master equation: " + what); };
    if (p.maxSize < 1) fail("maxSize must be >= 1, got " + std::to_string(p.maxSize));
    if (p.dim != 2 && p.dim != 3) fail("dim must be 2 or 3, got " + std::to_string(p.dim));
    if (!(p.alpha0 > 0)) fail("alpha0 must be > 0");
    if (!(p.beta0 >= 0)) fail("beta0 must be >= 0");
    if (!(p.lambda > 0)) fail("lambda must be > 0");
    if (!(p.velocity > 0)) fail("velocity must be > 0");
    if (!std::isfinite(p.xi)) fail("xi must be finite");
}

std::size_t idx(int s) {
    return static_cast<std::size_t>(s);
}

}  // namespace

MasterEquation::MasterEquation(const MasterEquationParams& params) : m_params(params) {
    validate(m_params);
    const int S = m_params.maxSize;
    const Real surfaceExp = 1 - 1.0 / m_params.dim;
    m_alphaOfSum.assign(idx(S + 1), 0);
    for (int s = 2; s <= S; ++s) {
        // edmd Eq. 5.29
        m_alphaOfSum[idx(s)] =
            m_params.alpha0 * std::pow(Real(s), surfaceExp) * m_params.velocity * std::sqrt(m_params.lambda);
    }
    m_beta.assign(idx(S + 1) * idx(S + 1), 0);
    m_fragLoss.assign(idx(S + 1), 0);
    for (int i = 1; i < S; ++i) {
        for (int j = 1; i + j <= S; ++j) m_beta[idx(i) * idx(S + 1) + idx(j)] = beta(i, j);
    }
    for (int j = 2; j <= S; ++j) {
        Real sum = 0;
        for (int i = 1; i < j; ++i) sum += m_beta[idx(i) * idx(S + 1) + idx(j - i)];
        m_fragLoss[idx(j)] = sum;
    }
}

Real MasterEquation::alpha(int i, int j) const noexcept {
    const Real s = i + j;
    return m_params.alpha0 * std::pow(s, 1 - 1.0 / m_params.dim) * m_params.velocity *
           std::sqrt(m_params.lambda);  // edmd Eq. 5.29
}

Real MasterEquation::beta(int i, int j) const noexcept {
    const Real s = i + j;
    return m_params.beta0 * std::pow(s, 1 - 1.0 / m_params.dim) * m_params.velocity *
           std::pow(s / (Real(i) * Real(j)), m_params.xi);  // edmd Eq. 5.30
}

void MasterEquation::rhs(std::span<const Real> p, std::span<Real> outDpdt) const {
    const int S = m_params.maxSize;
    if (p.size() != idx(S) || outDpdt.size() != idx(S)) {
        throw std::invalid_argument("master equation: rhs needs states of maxSize entries");
    }
    const Real gainFactor = m_params.symmetricGain ? 0.5 : 1.0;
    const Real fragLossFactor = m_params.symmetricGain ? 0.5 : 1.0;
    const std::size_t row = idx(S + 1);
    // p_s = p[s-1]; edmd Eq. 5.31, term by term
    for (int j = 1; j <= S; ++j) {
        Real mergeGain = 0;  // sum_{i=1}^{j-1} alpha_{i,j-i} p_i p_{j-i}
        for (int i = 1; i < j; ++i) mergeGain += p[idx(i - 1)] * p[idx(j - i - 1)];
        mergeGain *= gainFactor * m_alphaOfSum[idx(j)];
        Real mergeLoss = 0;  // sum_{i=1}^{S-j} alpha_{i,j} p_i p_j
        Real fragGain = 0;   // sum_{i=1}^{S-j} beta_{i,j} p_{i+j}
        for (int i = 1; i + j <= S; ++i) {
            mergeLoss += m_alphaOfSum[idx(i + j)] * p[idx(i - 1)];
            fragGain += m_beta[idx(i) * row + idx(j)] * p[idx(i + j - 1)];
        }
        mergeLoss *= p[idx(j - 1)];
        const Real fragLoss = fragLossFactor * m_fragLoss[idx(j)] * p[idx(j - 1)];  // sum beta_{i,j-i} p_j
        outDpdt[idx(j - 1)] = mergeGain - mergeLoss + fragGain - fragLoss;
    }
}

MasterResult MasterEquation::integrate(std::span<const Real> p0, std::span<const Real> times,
                                       const MasterIntegratorOptions& opt) const {
    const std::size_t S = idx(m_params.maxSize);
    std::vector<Real> y(S, 0);
    if (p0.empty()) {
        y[0] = 1;
    } else {
        if (p0.size() != S) throw std::invalid_argument("master equation: p0 must have maxSize entries");
        Real sum = 0;
        for (std::size_t s = 0; s < S; ++s) {
            if (!(p0[s] >= 0)) throw std::invalid_argument("master equation: p0 must be >= 0");
            y[s] = p0[s];
            sum += p0[s];
        }
        if (!(sum > 0)) throw std::invalid_argument("master equation: p0 must not be all zero");
    }
    for (std::size_t k = 0; k < times.size(); ++k) {
        if (!(times[k] >= 0) || (k > 0 && times[k] < times[k - 1])) {
            throw std::invalid_argument("master equation: times must be >= 0 and non-decreasing");
        }
    }
    if (!(opt.relTol > 0) || !(opt.absTol > 0) || !(opt.initialStep > 0)) {
        throw std::invalid_argument("master equation: tolerances and initial step must be > 0");
    }

    // Dormand-Prince 5(4) tableau
    static constexpr Real a21 = 1.0 / 5;
    static constexpr Real a31 = 3.0 / 40, a32 = 9.0 / 40;
    static constexpr Real a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
    static constexpr Real a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                          a54 = -212.0 / 729;
    static constexpr Real a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                          a65 = -5103.0 / 18656;
    static constexpr Real b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                          b6 = 11.0 / 84;
    static constexpr Real e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                          e6 = 22.0 / 525, e7 = -1.0 / 40;

    std::array<std::vector<Real>, 7> k;
    for (auto& v : k) v.assign(S, 0);
    std::vector<Real> stage(S), yNew(S);

    // Linear invariant of the flow: sum y (printed form) or sum s y (symmetric form). Runge-Kutta
    // steps keep it to round-off; the clipping below restores it by rescaling.
    auto invariant = [&](const std::vector<Real>& v) {
        Real sum = 0;
        for (std::size_t s = 0; s < S; ++s) sum += (m_params.symmetricGain ? Real(s + 1) : 1.0) * v[s];
        return sum;
    };
    // Undershoots up to this many error-tolerance units are accuracy noise (components that are
    // ~0 oscillate at the stability limit) and are clipped; deeper ones reject the step.
    constexpr Real kUndershootFactor = 10;

    MasterResult result;
    auto f = [&](const std::vector<Real>& in, std::vector<Real>& out) {
        rhs(in, out);
        ++result.rhsEvaluations;
    };
    auto sample = [&](Real t) {
        MasterSample smp;
        smp.t = t;
        for (std::size_t s = 0; s < S; ++s) {
            smp.total += y[s];
            smp.mass += Real(s + 1) * y[s];
        }
        smp.p.resize(S);
        for (std::size_t s = 0; s < S; ++s) smp.p[s] = y[s] / smp.total;
        smp.m1 = clusterMoment(smp.p, 1);
        smp.m2 = clusterMoment(smp.p, 2);
        return smp;
    };

    Real t = 0, h = opt.initialStep, errOld = 1e-4;
    f(y, k[0]);
    bool k0Valid = true;
    std::int64_t steps = 0;
    for (const Real target : times) {
        while (t < target) {
            if (++steps > opt.maxSteps) {
                throw std::runtime_error("master equation: more than maxSteps steps before t = " +
                                         std::to_string(target));
            }
            if (!k0Valid) {
                f(y, k[0]);
                k0Valid = true;
            }
            const bool last = t + h >= target;
            const Real hs = last ? target - t : h;
            for (std::size_t s = 0; s < S; ++s) stage[s] = y[s] + hs * a21 * k[0][s];
            f(stage, k[1]);
            for (std::size_t s = 0; s < S; ++s) stage[s] = y[s] + hs * (a31 * k[0][s] + a32 * k[1][s]);
            f(stage, k[2]);
            for (std::size_t s = 0; s < S; ++s) {
                stage[s] = y[s] + hs * (a41 * k[0][s] + a42 * k[1][s] + a43 * k[2][s]);
            }
            f(stage, k[3]);
            for (std::size_t s = 0; s < S; ++s) {
                stage[s] = y[s] + hs * (a51 * k[0][s] + a52 * k[1][s] + a53 * k[2][s] + a54 * k[3][s]);
            }
            f(stage, k[4]);
            for (std::size_t s = 0; s < S; ++s) {
                stage[s] = y[s] + hs * (a61 * k[0][s] + a62 * k[1][s] + a63 * k[2][s] + a64 * k[3][s] +
                                        a65 * k[4][s]);
            }
            f(stage, k[5]);
            for (std::size_t s = 0; s < S; ++s) {
                yNew[s] =
                    y[s] + hs * (b1 * k[0][s] + b3 * k[2][s] + b4 * k[3][s] + b5 * k[4][s] + b6 * k[5][s]);
            }
            f(yNew, k[6]);  // FSAL: derivative at the new point
            Real errSq = 0;
            bool undershoot = false;
            for (std::size_t s = 0; s < S; ++s) {
                const Real e = hs * (e1 * k[0][s] + e3 * k[2][s] + e4 * k[3][s] + e5 * k[4][s] +
                                     e6 * k[5][s] + e7 * k[6][s]);
                const Real scale = opt.absTol + opt.relTol * std::max(std::abs(y[s]), std::abs(yNew[s]));
                errSq += (e / scale) * (e / scale);
                if (yNew[s] < -kUndershootFactor * (opt.absTol + opt.relTol * std::abs(y[s])))
                    undershoot = true;
            }
            const Real err = std::sqrt(errSq / Real(S));
            if (!std::isfinite(err)) throw std::runtime_error("master equation: non-finite state");
            if (err > 1 || undershoot) {
                ++result.rejectedSteps;
                Real factor = err > 1 ? std::max(0.2, 0.9 * std::pow(err, -0.2)) : 1.0;
                if (undershoot) factor = std::min(factor, 0.5);
                h = hs * factor;
                if (h < 1e-14 * std::max(Real(1), t)) {
                    throw std::runtime_error("master equation: step size underflow at t = " +
                                             std::to_string(t));
                }
                continue;
            }
            ++result.acceptedSteps;
            bool clipped = false;
            for (std::size_t s = 0; s < S; ++s) {
                if (yNew[s] < 0) {
                    yNew[s] = 0;
                    clipped = true;
                }
            }
            if (clipped) {
                // restore the linear invariant the clipping perturbed (by a relative ~absTol)
                const Real before = invariant(y), after = invariant(yNew);
                if (after > 0) {
                    for (Real& v : yNew) v *= before / after;
                }
            }
            y.swap(yNew);
            k[0].swap(k[6]);
            k0Valid = !clipped;
            t = last ? target : t + hs;
            // PI step control (Hairer-Wanner DOPRI5, beta = 0.04): damps the accept/reject cycling
            // at the stability limit of the stiff fragmentation terms
            const Real errUsed = std::max(err, Real(1e-10));
            const Real grow = std::clamp(0.9 * std::pow(errUsed, -0.17) * std::pow(errOld, 0.04), 0.2, 5.0);
            errOld = std::max(err, Real(1e-4));
            // a truncated last step says little about the free step: keep the larger proposal
            h = last ? std::max(h, hs * grow) : hs * grow;
        }
        result.samples.push_back(sample(target));
    }
    return result;
}

Real clusterMoment(std::span<const Real> p, int k) {
    Real num = 0, den = 0;
    for (std::size_t s = 0; s < p.size(); ++s) {
        num += std::pow(Real(s + 1), k) * p[s];
        den += p[s];
    }
    return num / den;  // edmd Eq. 5.12
}

namespace {

/// log sum_s exp(-xi ln s - w s) over s = 1..S and the weight-averaged s (d/dw of it is -<s>).
struct LogSum {
    Real value;
    Real meanSize;
};

LogSum logSumPowerExp(int S, Real xi, Real w) {
    Real maxE = -std::numeric_limits<Real>::infinity();
    for (int s = 1; s <= S; ++s) maxE = std::max(maxE, -xi * std::log(Real(s)) - w * s);
    Real sum = 0, sumS = 0;
    for (int s = 1; s <= S; ++s) {
        const Real e = std::exp(-xi * std::log(Real(s)) - w * s - maxE);
        sum += e;
        sumS += s * e;
    }
    return {maxE + std::log(sum), sumS / sum};
}

}  // namespace

DetailedBalanceState detailedBalanceEquilibrium(const MasterEquationParams& params, Real norm,
                                                EquilibriumNorm kind) {
    validate(params);
    if (!(norm > 0)) throw std::invalid_argument("detailedBalanceEquilibrium: norm must be > 0");
    if (!(params.beta0 > 0)) throw std::invalid_argument("detailedBalanceEquilibrium: beta0 must be > 0");
    DetailedBalanceState st;
    st.c = params.beta0 / params.alpha0 / std::sqrt(params.lambda);  // edmd Eq. 5.35
    const int S = params.maxSize;
    // F(w) = ln c + ln sum s^-x e^-ws - ln norm with x = xi (Number) or xi - 1 (Mass); strictly
    // decreasing (F' = -<s>) for S > 1
    const Real x = kind == EquilibriumNorm::Mass ? params.xi - 1 : params.xi;
    auto F = [&](Real w) {
        const LogSum ls = logSumPowerExp(S, x, w);
        return LogSum{std::log(st.c) + ls.value - std::log(norm), ls.meanSize};
    };
    Real w = 0;
    if (S == 1) {
        w = std::log(st.c / norm);  // c e^-w = norm
    } else {
        Real lo = 0, hi = 0;
        if (F(0).value > 0) {
            hi = 1;
            while (F(hi).value > 0) hi *= 2;
        } else {
            lo = -1;
            while (F(lo).value < 0) lo *= 2;
        }
        w = 0.5 * (lo + hi);
        for (int it = 0; it < 200; ++it) {
            const LogSum v = F(w);
            if (v.value > 0) {
                lo = w;
            } else {
                hi = w;
            }
            Real next = w + v.value / v.meanSize;  // Newton: F' = -<s>
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (std::abs(next - w) <= 1e-15 * std::max(Real(1), std::abs(w))) {
                w = next;
                break;
            }
            w = next;
        }
    }
    st.w = w;
    st.p.resize(idx(S));
    for (int s = 1; s <= S; ++s) {
        st.p[idx(s - 1)] = st.c * std::exp(-params.xi * std::log(Real(s)) - w * s);  // edmd Eq. 5.34
    }
    return st;
}

Real populationThresholdLambda(const MasterEquationParams& params) {
    validate(params);
    Real sum = 0;
    for (int s = 1; s <= params.maxSize; ++s) sum += std::pow(Real(s), -params.xi);
    const Real r = params.beta0 / params.alpha0 * sum;  // edmd Eq. 5.41: c sum s^-xi = 1
    return r * r;
}

Real fitExponentialCutoff(std::span<const Real> p, Real xi, int sMin, int sMax, Real minP) {
    Real n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    const int hi = std::min(sMax, static_cast<int>(p.size()));
    for (int s = std::max(1, sMin); s <= hi; ++s) {
        const Real ps = p[idx(s - 1)];
        if (!(ps > minP) || !(ps > 0)) continue;
        const Real x = s, yv = std::log(ps) + xi * std::log(Real(s));
        n += 1;
        sx += x;
        sy += yv;
        sxx += x * x;
        sxy += x * yv;
    }
    if (n < 2) throw std::invalid_argument("fitExponentialCutoff: fewer than 2 sizes with p_s > minP");
    const Real slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    return -slope;
}

}  // namespace granulab::analysis
