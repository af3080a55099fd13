// SPDX-License-Identifier: MIT
// Coagulation/fragmentation master equation of the cluster population (edmd spec section 5.6,
// Eqs. 5.29-5.43; erratum 14 of section 9): rates, right-hand side, an adaptive Dormand-Prince
// integrator that keeps p_s >= 0, and the detailed-balance equilibrium for comparison.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "core/types.hpp"

namespace granulab::analysis {

/// Parameters of the population model. The thesis gives the model no physical time scale: time is
/// in the units the rate prefactors alpha0, beta0 (rates per unit time) are given in; p_s are
/// dimensionless.
struct MasterEquationParams {
    int maxSize = 100;  ///< S_max: sizes s = 1..S_max are tracked; merging beyond S_max is not allowed
    int dim = 3;        ///< D in the surface factor (i+j)^(1 - 1/D) of Eqs. 5.29-5.30
    Real alpha0 = 1;    ///< merging prefactor (Eq. 5.29), > 0
    Real beta0 = 1;     ///< fragmentation prefactor (Eq. 5.30), >= 0
    Real lambda = 1;    ///< dissipation 1 - eps^2 (enters as lambda^(1/2)), > 0
    Real xi = 2;        ///< fragment power-law exponent (Eq. 5.30), spec: xi > 1
    Real velocity = 1;  ///< v_ij, taken constant (spec section 5.6 [I])
    /// false (default): Eq. 5.31 exactly as printed: every ordered pair counted once in the
    /// merging gain and in the fragmentation loss. Each reaction then keeps the number of clusters
    /// (1 + 1 -> 2 removes one monomer, adds one dimer), so sum_s p_s is the exact invariant and
    /// p_s = n_s/n_tot stays normalised; the mass sum_s s p_s = M1 is not conserved.
    /// true: the standard symmetric Smoluchowski form, 1/2 on the ordered-pair merging gain and,
    /// so that Eq. 5.32 stays the detailed balance, 1/2 on the ordered-pair fragmentation loss. Its
    /// state is y_s = n_s/n_tot(0) with the invariant sum_s s y_s (= N/n_tot(0)); samples report
    /// p_s = y_s/sum y. Both forms have the same detailed-balance states (Eqs. 5.34-5.35).
    bool symmetricGain = false;
};

/// Tolerances and limits of the adaptive Dormand-Prince 5(4) integration.
struct MasterIntegratorOptions {
    Real relTol = 1e-8;                  ///< relative error per step
    Real absTol = 1e-12;                 ///< absolute error per step (also scales the undershoot tolerance)
    Real initialStep = 1e-4;             ///< first trial step
    std::int64_t maxSteps = 10'000'000;  ///< accepted + rejected steps; exceeded -> std::runtime_error
};

/// The state at one requested time.
struct MasterSample {
    Real t = 0;
    std::vector<Real> p;  ///< p[s-1] = p_s normalised to sum 1 (the raw state divided by `total`)
    Real total = 0;       ///< sum_s y_s of the integrated state (invariant of the printed form)
    Real mass = 0;        ///< sum_s s y_s of the integrated state (invariant of the symmetric form)
    Real m1 = 0;          ///< M1 = sum s p_s (Eq. 5.12)
    Real m2 = 0;          ///< M2 = sum s^2 p_s (Eq. 5.12)
};

struct MasterResult {
    std::vector<MasterSample> samples;  ///< one per requested time, same order
    std::int64_t acceptedSteps = 0;
    std::int64_t rejectedSteps = 0;
    std::int64_t rhsEvaluations = 0;
};

/// Rates and right-hand side of Eq. 5.31. Construction precomputes O(S_max^2) rate tables;
/// afterwards all members are const and thread-safe.
class MasterEquation {
public:
    /// Throws std::invalid_argument for maxSize < 1, dim not 2/3, alpha0 <= 0, beta0 < 0,
    /// lambda <= 0, velocity <= 0.
    explicit MasterEquation(const MasterEquationParams& params);

    const MasterEquationParams& params() const noexcept { return m_params; }
    /// Merging rate alpha_ij = alpha0 (i+j)^(1-1/D) v lambda^(1/2) (Eq. 5.29). i, j >= 1.
    Real alpha(int i, int j) const noexcept;
    /// Fragmentation rate beta_ij = beta0 (i+j)^(1-1/D) v ((i+j)/(ij))^xi (Eq. 5.30). i, j >= 1.
    Real beta(int i, int j) const noexcept;

    /// dp/dt of Eq. 5.31 (printed or symmetric form) at state p (p[s-1] = p_s, size S_max).
    /// outDpdt must have size S_max (else std::invalid_argument). O(S_max^2), no allocation.
    void rhs(std::span<const Real> p, std::span<Real> outDpdt) const;

    /// Integrates from t = 0 with the initial state p0 (p0[s-1]; empty: p_1 = 1, the rest 0) and
    /// returns the state at each of `times` (non-decreasing, >= 0). Dormand-Prince 5(4) with PI
    /// step-size control. The state stays >= 0: undershoots within 10 tolerance units
    /// (absTol + relTol |y_s|) are set to 0 and the state rescaled to keep the form's invariant,
    /// deeper ones reject the step and halve it. Throws std::invalid_argument for a bad p0 or
    /// times, std::runtime_error past maxSteps or on step-size underflow.
    MasterResult integrate(std::span<const Real> p0, std::span<const Real> times,
                           const MasterIntegratorOptions& options = {}) const;

private:
    MasterEquationParams m_params;
    std::vector<Real> m_alphaOfSum;  ///< alpha for i + j = s, index s (0 unused)
    std::vector<Real> m_beta;        ///< beta(i, j) at i * (S+1) + j, for i + j <= S
    std::vector<Real> m_fragLoss;    ///< sum_{i=1}^{j-1} beta(i, j-i), index j
};

/// Moment M_k = sum_s s^k p_s / sum_s p_s of a size distribution p[s-1] (Eq. 5.12).
Real clusterMoment(std::span<const Real> p, int k);

/// Detailed-balance state p_s = c s^-xi exp(-w s), s = 1..S_max (Eqs. 5.34-5.35).
struct DetailedBalanceState {
    Real c = 0;           ///< (beta0/alpha0) lambda^(-1/2) (Eq. 5.35)
    Real w = 0;           ///< cut-off from the normalisation; w < 0: weight at the largest sizes
    std::vector<Real> p;  ///< p[s-1]
};

/// What detailedBalanceEquilibrium normalises: the number sum_s p_s (the printed form, Eqs.
/// 5.37-5.38) or the mass sum_s s p_s (the invariant of the symmetric form).
enum class EquilibriumNorm { Number, Mass };

/// Detailed-balance equilibrium with sum_{s=1}^{S_max} p_s = norm (Number: 1 by default, 1 - q_x
/// for Eq. 5.38) or sum_s s p_s = norm (Mass). w is the unique root of the normalisation
/// (log-space Newton with bisection safeguard). Throws std::invalid_argument for norm <= 0,
/// beta0 = 0 or bad params.
DetailedBalanceState detailedBalanceEquilibrium(const MasterEquationParams& params, Real norm = 1,
                                                EquilibriumNorm kind = EquilibriumNorm::Number);

/// Population-model threshold lambda* = (beta0/alpha0)^2 (sum_{s=1}^{S_max} s^-xi)^2: below it the
/// equilibrium has w > 0, above it w < 0 and 1 - q_x = sqrt(lambda*/lambda) (Eq. 5.41).
Real populationThresholdLambda(const MasterEquationParams& params);

/// Least-squares fit of ln(p_s s^xi) = ln c - w s over the sizes sMin..sMax with p_s > minP;
/// returns w (positive: exponential cut-off; negative: weight growing towards large s).
/// Throws std::invalid_argument if fewer than 2 sizes qualify.
Real fitExponentialCutoff(std::span<const Real> p, Real xi, int sMin, int sMax, Real minP = 0);

}  // namespace granulab::analysis
