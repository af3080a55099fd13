// SPDX-License-Identifier: MIT
// Contact laws, decomposed by axis (DESIGN.md "Contact laws", STYLE.md (b)): each alternative is
// a small stateless struct with its parameters, one noexcept function, and its registration
// (keyword, documentation, parameter table with units, ranges and defaults, factory).
//
// TO ADD AN OVERLAP-DEPTH LAW, EDIT ONLY THIS FILE: write its struct with the static members
// below (kUsesReff = true if it reads R_eff) and append it to the variant of its axis. The
// registry (registry.cpp), validation, `granulab help laws`, the depth kernels
// (dem/forces_depth.hpp) and the contact energy pick it up from the variant. A law of the gc2d
// area family also needs its term in dem/forces_area.hpp (areaLaw), the form traits in
// dem/forces_detail.hpp (kAreaNormal), its pairing rule in registry.cpp (buildContactLaw),
// areaModulus below and its energy in dem/contact_energy.cpp.
#pragma once
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <variant>
#include <vector>

#include "core/types.hpp"
#include "dem/contact/hertz_restitution.hpp"
#include "dem/contact/kinematics.hpp"
#include "dem/contact/law_params.hpp"

namespace granulab::dem {

/// True for a law that reads R_eff (static member kUsesReff = true): the depth kernels compute
/// R_eff, a division, only for such laws (and for rolling resistance).
template <class Law>
constexpr bool lawUsesReff() noexcept {
    if constexpr (requires { Law::kUsesReff; })
        return Law::kUsesReff;
    else
        return false;
}

// ---------------------------------------------------------------- normal spring
/// Linear (Hooke) spring: F = kn * delta. kn [N/m].
struct HookeNormal {
    static constexpr LawAxis kAxis = LawAxis::Normal;
    static constexpr const char* kKeyword = "hooke";
    static constexpr const char* kDoc = "linear spring F_n = kn * delta";
    static std::vector<LawParamSpec> params() {
        return {lawParam("kn", "N/m", 0, kUnbounded, true, "required", "normal spring stiffness")};
    }
    static HookeNormal make(const LawParams& p) { return {p.require("kn")}; }

    Real kn = 0;
    Real force(Real overlap, Real /*reff*/) const noexcept { return kn * overlap; }
    /// Secant stiffness F/delta [N/m], used by damping laws scaled with stiffness.
    Real stiffness(Real /*overlap*/, Real /*reff*/) const noexcept { return kn; }
    /// Stored elastic energy [J].
    Real energy(Real overlap, Real /*reff*/) const noexcept { return 0.5 * kn * overlap * overlap; }
};

/// Hertz spring (cfddem Eq. 3.29-3.34): F = k_Hz delta^(3/2), k_Hz = 4/3 E* sqrt(R_eff), with the
/// effective modulus E* of the two materials' youngs_modulus and poisson (Eq. 3.32).
struct HertzNormal {
    static constexpr LawAxis kAxis = LawAxis::Normal;
    static constexpr const char* kKeyword = "hertz";
    static constexpr bool kUsesReff = true;
    static constexpr const char* kDoc =
        "Hertz spring F_n = 4/3 E* sqrt(R_eff) delta^(3/2); E* from the materials' youngs_modulus and "
        "poisson";
    static std::vector<LawParamSpec> params() { return {}; }
    static HertzNormal make(const LawParams& p) { return {4.0 / 3.0 * p.effectiveModulus()}; }

    Real fourThirdsE = 0;  ///< [Pa] 4/3 E*
    Real force(Real overlap, Real reff) const noexcept {
        return fourThirdsE * std::sqrt(reff * overlap) * overlap;
    }
    /// Secant stiffness k_n(delta) = k_Hz sqrt(delta) [N/m] (Eq. 3.34).
    Real stiffness(Real overlap, Real reff) const noexcept { return fourThirdsE * std::sqrt(reff * overlap); }
    Real energy(Real overlap, Real reff) const noexcept { return 0.4 * force(overlap, reff) * overlap; }
};

/// gc2d overlap-area law (gc2d spec section 3.2, Eq. 2.20): F_n = E A / l with the overlap area A
/// and l = r_i r_j/(r_i + r_j) from the lever arms of the contact point; cohesion (Eq. 2.28)
/// k_coh |c1 c2| pulls while the bodies overlap. Works for every shape pair and is the law of
/// polygon contacts; its kernel is dem/forces_area.hpp (dem/forces_area_pairs.hpp), not the
/// overlap-depth kernel.
struct AreaNormal {
    static constexpr LawAxis kAxis = LawAxis::Normal;
    static constexpr const char* kKeyword = "area";
    static constexpr const char* kDoc =
        "gc2d overlap-area law F_n = E A / l, l = r_i r_j/(r_i + r_j); cohesion k_coh |c1 c2| (any shapes, "
        "required by polygons)";
    static std::vector<LawParamSpec> params() {
        return {
            lawParam("E", "N/m", 0, kUnbounded, true, "required", "2D elastic modulus (gc2d default 1e7)"),
            lawParam("cohesion", "N/m", 0, kUnbounded, false, "0",
                     "k_coh: attraction k_coh |c1 c2| along -n while overlapping (gc2d Eq. 2.28)")};
    }
    static AreaNormal make(const LawParams& p) { return {p.require("E"), p.getOr("cohesion", 0.0)}; }

    Real E = 0;         ///< [N/m]
    Real cohesion = 0;  ///< [N/m]
    // The depth interface of the other normal laws, for generic code (time-step advice) only:
    // a flat face of unit length, A = delta.
    Real force(Real overlap, Real /*reff*/) const noexcept { return E * overlap; }
    Real stiffness(Real /*overlap*/, Real /*reff*/) const noexcept { return E; }
    Real energy(Real overlap, Real /*reff*/) const noexcept { return 0.5 * E * overlap * overlap; }
};

/// Energy-conserving overlap-area law (Feng, Han & Owen 2012, "Energy-conserving contact
/// interaction models for arbitrarily shaped discrete elements", CMAME; docs/physics/
/// contact-laws.md, `normal = "area_potential"`): potential W(A) = E A^2 / (2 l0^2) with a constant
/// l0 = R_i R_j/(R_i + R_j) from the bounding radii (l0 = R_i at a wall). The force is the exact
/// generalised force -W'(A) dA/dq: on i, W'(A) times the area gradient of the overlap edges on
/// i's boundary (geom::AreaContact::pull, twist); with two crossings W'(A) L_c along the chord
/// normal at the chord midpoint, so a flat face with L_c = l0 feels gc2d's E A / l0. Cohesion
/// k_coh adds the potential -k_coh A (gc2d's k_coh L_c along -n). Same kernel and damping and
/// friction partners as AreaNormal.
struct AreaPotentialNormal {
    static constexpr LawAxis kAxis = LawAxis::Normal;
    static constexpr const char* kKeyword = "area_potential";
    static constexpr const char* kDoc =
        "energy-conserving overlap-area law (Feng et al. 2012): W = E A^2/(2 l0^2), l0 = R_i R_j/(R_i + R_j) "
        "from the bounding radii, F = -dW/dq (W'(A) L_c n for two crossings); cohesion -k_coh A";
    static std::vector<LawParamSpec> params() {
        return {lawParam("E", "N/m", 0, kUnbounded, true, "required",
                         "2D elastic modulus (a flat face of length l0 feels E A / l0)"),
                lawParam("cohesion", "N/m", 0, kUnbounded, false, "0",
                         "k_coh: potential -k_coh A, i.e. k_coh L_c along -n while overlapping")};
    }
    static AreaPotentialNormal make(const LawParams& p) { return {p.require("E"), p.getOr("cohesion", 0.0)}; }

    Real E = 0;         ///< [N/m]
    Real cohesion = 0;  ///< [N/m]
    /// dU/dA = W'(A) - k_coh = E A / l0^2 - k_coh [N/m], for the overlap area A [m^2] and 1/l0 [1/m].
    Real slope(Real area, Real invL0) const noexcept { return E * area * invL0 * invL0 - cohesion; }
    /// U(A) = E A^2 / (2 l0^2) - k_coh A [J] (per unit depth: J/m in strict 2D).
    Real potential(Real area, Real invL0) const noexcept {
        const Real h = area * invL0;
        return 0.5 * E * h * h - cohesion * area;
    }
    // The depth interface of the other normal laws, for generic code (time-step advice) only:
    // a flat face of length l0, A = l0 delta.
    Real force(Real overlap, Real /*reff*/) const noexcept { return E * overlap; }
    Real stiffness(Real /*overlap*/, Real /*reff*/) const noexcept { return E; }
    Real energy(Real overlap, Real /*reff*/) const noexcept { return 0.5 * E * overlap * overlap; }
};

using NormalLaw = std::variant<HookeNormal, HertzNormal, AreaNormal, AreaPotentialNormal>;

/// The modulus E [N/m] of an overlap-area normal law (gc2d or energy-conserving), else null.
inline const Real* areaModulus(const NormalLaw& n) noexcept {
    if (const auto* a = std::get_if<AreaNormal>(&n)) return &a->E;
    if (const auto* a = std::get_if<AreaPotentialNormal>(&n)) return &a->E;
    return nullptr;
}

// ---------------------------------------------------------------- normal damping
// Each returns the normal damping coefficient c [N s/m]; the damping force is c * v_n.

struct NoDamping {
    static constexpr LawAxis kAxis = LawAxis::Damping;
    static constexpr const char* kKeyword = "none";
    static constexpr const char* kDoc = "no normal damping (elastic)";
    static std::vector<LawParamSpec> params() { return {}; }
    static NoDamping make(const LawParams&) { return {}; }

    Real coefficient(Real /*meff*/, Real /*stiffness*/) const noexcept { return 0; }
};

/// Constant coefficient: c = cn [N s/m].
struct ViscousDamping {
    static constexpr LawAxis kAxis = LawAxis::Damping;
    static constexpr const char* kKeyword = "coefficient";
    static constexpr const char* kDoc = "viscous normal damping F = cn * v_n";
    static std::vector<LawParamSpec> params() {
        return {lawParam("cn", "N s/m", 0, kUnbounded, false, "required", "damping coefficient")};
    }
    static ViscousDamping make(const LawParams& p) { return {p.require("cn")}; }

    Real cn = 0;
    Real coefficient(Real /*meff*/, Real /*stiffness*/) const noexcept { return cn; }
};

/// From a restitution coefficient e: c = 2 beta sqrt(meff kn), beta = -ln e / sqrt(pi^2 + ln^2 e).
/// Exact for the linear spring without attraction clipping (docs/physics/contact-laws.md).
struct RestitutionDamping {
    static constexpr LawAxis kAxis = LawAxis::Damping;
    static constexpr const char* kKeyword = "restitution";
    static constexpr const char* kDoc =
        "damping from the normal restitution coefficient e (exact for hooke without clipping)";
    static std::vector<LawParamSpec> params() {
        return {lawParam("e", "-", 0, 1, false, "required", "normal restitution coefficient")};
    }
    static RestitutionDamping make(const LawParams& p) {
        const Real e = p.require("e");
        const bool clip = p.getOr("clip_attraction", 0.0) != 0.0;
        // Hooke: Eq. 3.78 (exact, unclipped). Hertz: e(D) of the Hertz-Lehr collision, inverted.
        if (!p.uses(HertzNormal::kKeyword)) return {linearDampingRatio(e)};
        const Real d = hertzDampingRatio(e, clip);
        const Real reached = hertzRestitution(d, clip);
        if (reached > e + 1e-3)
            p.fail("e", fmt::format(
                            "e = {:.4g} is below the smallest restitution this Hertz law reaches ({:.4g}{}); "
                            "allowed [{:.4g}, 1]",
                            e, reached, clip ? ", clipped" : "", reached));
        return {d};
    }

    Real beta = 0;  ///< damping ratio derived from e
    Real coefficient(Real meff, Real stiffness) const noexcept {
        return 2.0 * beta * std::sqrt(meff * stiffness);
    }
};

/// Lehr damping ratio D_n (cfddem Eq. 3.44): c_n = 2 D_n sqrt(meff k_n(delta)); with the Hertz
/// spring c_n grows as delta^(1/4). D_n = 1 is the aperiodic limit of the linear law.
struct LehrDamping {
    static constexpr LawAxis kAxis = LawAxis::Damping;
    static constexpr const char* kKeyword = "lehr";
    static constexpr const char* kDoc =
        "Lehr damping ratio: c_n = 2 D_n sqrt(meff k_n(delta)) (Uphoff Eq. 3.44)";
    static std::vector<LawParamSpec> params() {
        return {lawParam("D_n", "-", 0, kUnbounded, false, "required", "normal damping ratio (0 elastic)")};
    }
    static LehrDamping make(const LawParams& p) { return {p.require("D_n")}; }

    Real ratio = 0;
    Real coefficient(Real meff, Real stiffness) const noexcept {
        return 2.0 * ratio * std::sqrt(meff * stiffness);
    }
};

/// LAMMPS gran/hooke/history convention: c = meff * gamma_n, gamma_n [1/s].
struct MassScaledDamping {
    static constexpr LawAxis kAxis = LawAxis::Damping;
    static constexpr const char* kKeyword = "lammps";
    static constexpr const char* kDoc =
        "mass-scaled damping F = meff * gamma_n * v_n (LAMMPS gran/hooke/history)";
    static std::vector<LawParamSpec> params() {
        return {lawParam("gamma_n", "1/s", 0, kUnbounded, false, "required", "normal damping rate")};
    }
    static MassScaledDamping make(const LawParams& p) { return {p.require("gamma_n")}; }

    Real gammaN = 0;
    Real coefficient(Real meff, Real /*stiffness*/) const noexcept { return meff * gammaN; }
};

/// gc2d normal damping (gc2d spec section 3.3, Eq. 2.21/2.22 with erratum 1): D = gamma
/// sqrt(E m_perp) dA / (l dt), dA the change of the overlap area since the last step; while
/// separating clipped so that F_n + D >= 0 (never attractive). Only with normal = "area" or
/// "area_potential" (there l = l0).
struct AreaDamping {
    static constexpr LawAxis kAxis = LawAxis::Damping;
    static constexpr const char* kKeyword = "gamma";
    static constexpr const char* kDoc =
        "gc2d damping gamma sqrt(E m_perp) dA/(l dt), clipped so the contact never attracts (normal = "
        "\"area\" or \"area_potential\", l = l0)";
    static std::vector<LawParamSpec> params() {
        return {lawParam("gamma", "-", 0, kUnbounded, false, "required",
                         "damping factor (gc2d default 0.5; 0 elastic)")};
    }
    static AreaDamping make(const LawParams& p) { return {p.require("gamma")}; }

    Real gamma = 0;
    Real coefficient(Real /*meff*/, Real /*stiffness*/) const noexcept { return 0; }  // not a depth law
};

using DampingLaw =
    std::variant<NoDamping, ViscousDamping, RestitutionDamping, MassScaledDamping, LehrDamping, AreaDamping>;

// ---------------------------------------------------------------- tangential
/// Frictionless contact.
struct NoFriction {
    static constexpr LawAxis kAxis = LawAxis::Tangential;
    static constexpr const char* kKeyword = "none";
    static constexpr const char* kDoc = "frictionless";
    static std::vector<LawParamSpec> params() { return {}; }
    static NoFriction make(const LawParams&) { return {}; }

    Real force(const ContactKinematics&, Real /*kn*/, Real /*fn*/, Real& /*ioXi*/) const noexcept {
        return 0;
    }
    Real energy(Real, Real, Real, Real) const noexcept { return 0; }
};

/// Energy F^2 / (2 k) of a tangential spring whose force k |xi| is capped at `cap` [J].
inline Real springEnergy(Real k, Real xi, Real cap) noexcept {
    if (!(k > 0)) return 0;
    const Real f = std::min(k * std::abs(xi), cap);
    return 0.5 * f * f / k;
}

/// Coulomb cap shared by the tangential springs: |F_t| <= mu |F_n|. When the trial force exceeds
/// the cap, the force is scaled onto it and, if `resetSpring`, the spring xi is reset so that
/// kt xi + ct vt gives exactly the capped force (Cundall's fix, LAMMPS convention).
[[gnu::always_inline]] inline Real coulombCap(Real trial, Real fn, Real mu, Real kt, Real ct, Real vt,
                                              bool resetSpring, Real& ioXi) noexcept {
    const Real cap = mu * std::abs(fn);
    const Real mag = std::abs(trial);
    if (mag <= cap) return trial;
    const Real scale = cap / mag;
    if (resetSpring) ioXi = kt > 0 ? scale * (ioXi + ct * vt / kt) - ct * vt / kt : 0;
    return trial * scale;
}

/// Cundall-Strack spring with Coulomb cap (Cundall & Strack 1979): the tangential displacement
/// xi [m] is kept in the current tangent direction (a scalar in 2D, so rotation of the contact
/// keeps its magnitude). F_t = -(kt xi + c_t v_t), |F_t| <= mu |F_n|; when capped, xi is reset
/// to the value that gives exactly the capped force (LAMMPS convention).
/// c_t = ct + meff * gammaT.
struct CundallStrack {
    static constexpr LawAxis kAxis = LawAxis::Tangential;
    static constexpr const char* kKeyword = "cundall_strack";
    static constexpr const char* kDoc =
        "tangential spring with history, viscous term and Coulomb cap mu * |F_n|";
    static std::vector<LawParamSpec> params() {
        return {
            lawParam("mu", "-", 0, kUnbounded, false, "required", "friction coefficient"),
            lawParam("kt", "N/m", 0, kUnbounded, false, "2/7 kn", "tangential stiffness"),
            lawParam("ct", "N s/m", 0, kUnbounded, false, "0", "constant tangential damping"),
            lawParam("gamma_t", "1/s", 0, kUnbounded, false, "gamma_n/2 with damping = \"lammps\", else 0",
                     "mass-scaled tangential damping (c_t += meff * gamma_t)")};
    }
    static CundallStrack make(const LawParams& p) {
        CundallStrack cs;
        cs.mu = p.require("mu");
        cs.kt = p.getOr("kt", 2.0 / 7.0 * p.getOr("kn", 0.0));
        cs.ct = p.getOr("ct", 0.0);
        cs.gammaT =
            p.getOr("gamma_t", p.uses(MassScaledDamping::kKeyword) ? 0.5 * p.getOr("gamma_n", 0.0) : 0.0);
        return cs;
    }

    Real kt = 0;      ///< [N/m]
    Real ct = 0;      ///< [N s/m] constant tangential damping
    Real gammaT = 0;  ///< [1/s] mass-scaled tangential damping
    Real mu = 0;      ///< Coulomb friction coefficient

    [[gnu::always_inline]] Real force(const ContactKinematics& k, Real /*kn*/, Real fn,
                                      Real& ioXi) const noexcept {
        const Real c = ct + k.meff * gammaT;
        ioXi += k.dxt;
        return coulombCap(-(kt * ioXi + c * k.vt), fn, mu, kt, c, k.vt, true, ioXi);
    }
    /// Stored energy F_t^2 / (2 kt) of the spring force, at most the Coulomb cap [J].
    Real energy(Real, Real, Real xi, Real normalForce) const noexcept {
        return springEnergy(kt, xi, mu * std::abs(normalForce));
    }
};

/// Mindlin tangential spring of the cfddem seed (Eq. 3.47-3.54): k_t = 8 G* sqrt(R_eff delta) with
/// G* = E*/(2 (1 + nu*)), nu* = (1/nu_a + 1/nu_b)^-1 (Eq. 3.49/3.51), damper
/// c_t = 2 D_t sqrt(meff k_n(delta)) with the NORMAL stiffness (Eq. 3.53), Coulomb cap mu |F_n|.
/// `literal = true` reads Eq. 3.48 as printed, k_t = 8 G* sqrt(R_eff) delta (spec section 3.6).
/// The seed caps the force only; `reset_spring = true` also resets the spring (Cundall's fix).
struct MindlinTangential {
    static constexpr LawAxis kAxis = LawAxis::Tangential;
    static constexpr const char* kKeyword = "mindlin";
    static constexpr bool kUsesReff = true;
    static constexpr const char* kDoc =
        "Mindlin spring k_t = 8 G* sqrt(R_eff delta), damper 2 D_t sqrt(meff k_n), Coulomb cap (Uphoff Eq. "
        "3.47-3.55)";
    static std::vector<LawParamSpec> params() {
        LawParamSpec literal =
            lawParam("literal", "-", 0, 1, false, "false",
                     "k_t = 8 G* sqrt(R_eff) delta as printed in the seed (dimensionally odd)");
        literal.isBool = true;
        LawParamSpec reset =
            lawParam("reset_spring", "-", 0, 1, false, "false",
                     "when sliding, reset the spring to the capped force (the seed caps the force only)");
        reset.isBool = true;
        return {lawParam("mu", "-", 0, kUnbounded, false, "required", "friction coefficient"),
                lawParam("D_t", "-", 0, kUnbounded, false, "0", "tangential damping ratio"), literal, reset};
    }
    static MindlinTangential make(const LawParams& p) {
        MindlinTangential m;
        const auto& mat = p.materials();
        const Real nuEff =
            (mat.poissonA > 0 && mat.poissonB > 0) ? 1.0 / (1.0 / mat.poissonA + 1.0 / mat.poissonB) : 0.0;
        m.eightG = 8.0 * p.effectiveModulus() / (2.0 * (1.0 + nuEff));
        m.ratio = p.getOr("D_t", 0.0);
        m.mu = p.require("mu");
        m.literal = p.getOr("literal", 0.0) != 0.0;
        m.resetSpring = p.getOr("reset_spring", 0.0) != 0.0;
        return m;
    }

    Real eightG = 0;  ///< [Pa] 8 G*
    Real ratio = 0;   ///< D_t
    Real mu = 0;
    bool literal = false;
    bool resetSpring = false;

    Real stiffness(Real overlap, Real reff) const noexcept {
        return literal ? eightG * std::sqrt(reff) * overlap : eightG * std::sqrt(reff * overlap);
    }
    [[gnu::always_inline]] Real force(const ContactKinematics& k, Real kn, Real fn,
                                      Real& ioXi) const noexcept {
        const Real kt = stiffness(k.overlap, k.reff);
        const Real ct = 2.0 * ratio * std::sqrt(k.meff * kn);
        ioXi += k.dxt;
        return coulombCap(-(kt * ioXi + ct * k.vt), fn, mu, kt, ct, k.vt, resetSpring, ioXi);
    }
    /// Stored energy of the spring force, at most the Coulomb cap [J]: in the seed's faithful
    /// mode the spring keeps growing while the force is capped, and only the capped part is real.
    Real energy(Real overlap, Real reff, Real xi, Real normalForce) const noexcept {
        return springEnergy(stiffness(overlap, reff), xi, mu * std::abs(normalForce));
    }
};

/// gc2d Cundall-Strack friction (gc2d spec section 3.4, Eq. 2.23-2.27, errata 3 and 4): a spring
/// S += k_t v_par dt attached at first touch, a viscous term sqrt(k_t m_par) v_par, the total
/// capped at mu F_n (Coulomb, Eq. 2.24) or mu (|v_par| / 1 m/s)^(-1/10) F_n (Rabinowicz,
/// Eq. 2.25), the spring clipped to the cap. Only with normal = "area" or "area_potential".
struct AreaFriction {
    static constexpr LawAxis kAxis = LawAxis::Tangential;
    static constexpr const char* kKeyword = "gc2d";
    static constexpr const char* kDoc =
        "gc2d Cundall-Strack spring k_t (2/7 E) + sqrt(k_t m_par) v_par, capped at mu F_n, spring clipped "
        "(normal = \"area\" or \"area_potential\")";
    static std::vector<LawParamSpec> params() {
        LawParamSpec damped = lawParam("damped", "-", 0, 1, false, "true",
                                       "viscous term sqrt(k_t m_par) v_par (gc2d Eq. 2.26)");
        damped.isBool = true;
        LawParamSpec rab =
            lawParam("rabinowicz", "-", 0, 1, false, "false",
                     "velocity-weakening cap mu (|v_par| / 1 m/s)^(-1/10) F_n (gc2d Eq. 2.25)");
        rab.isBool = true;
        LawParamSpec total =
            lawParam("cap_total", "-", 0, 1, false, "false",
                     "cap with the total normal force (elastic + damping - cohesion), not the elastic one");
        total.isBool = true;
        LawParamSpec mu = lawParam("mu", "-", 0, 1, false, "required",
                                   "friction coefficient (gc2d default 0.6; the gc2d spec allows [0, 1))");
        mu.maxExclusive = true;
        return {mu, lawParam("kt", "N/m", 0, kUnbounded, false, "2/7 E", "tangential spring stiffness"),
                damped, rab, total};
    }
    static AreaFriction make(const LawParams& p) {
        AreaFriction f;
        f.mu = p.require("mu");
        f.kt = p.getOr("kt", 2.0 / 7.0 * p.getOr("E", 0.0));
        f.damped = p.getOr("damped", 1.0) != 0.0;
        f.rabinowicz = p.getOr("rabinowicz", 0.0) != 0.0;
        f.capTotal = p.getOr("cap_total", 0.0) != 0.0;
        return f;
    }

    Real mu = 0;
    Real kt = 0;  ///< [N/m]
    bool damped = true;
    bool rabinowicz = false;
    bool capTotal = false;
};

using TangentialLaw = std::variant<NoFriction, CundallStrack, MindlinTangential, AreaFriction>;

// ---------------------------------------------------------------- rolling resistance
// Not part of the compile-time form of a law: the disk-disk loop is compiled with and without
// rolling (dem/forces_depth.hpp), and each material pair switches it on at run time, so rolling
// resistance does not multiply the kernels by the number of rolling laws.

/// No rolling resistance.
struct NoRolling {
    static constexpr LawAxis kAxis = LawAxis::Rolling;
    static constexpr const char* kKeyword = "none";
    static constexpr const char* kDoc = "no rolling resistance";
    static std::vector<LawParamSpec> params() { return {}; }
    static NoRolling make(const LawParams&) { return {}; }
};

/// Rolling spring-dashpot of the cfddem seed (Eq. 3.56-3.59, after Cundall-Strack and Marshall
/// 2009): rolling velocity v_roll = -R_eff (omega_i - omega_j) - 1/2 (R_j - R_i)/(R_j + R_i) v_t
/// (at a wall: -R omega - 1/2 v_t), rolling displacement Xi = integral of v_roll, torque on i
/// M = k_r Xi + c_r v_roll opposing the relative rotation, on j -M. The seed gives no formula for
/// k_r (a user parameter here) and c_r = 2 D_r sqrt(meff k_n(delta)) R_eff by analogy with c_t.
struct SpringDashpotRolling {
    static constexpr LawAxis kAxis = LawAxis::Rolling;
    static constexpr const char* kKeyword = "spring_dashpot";
    static constexpr const char* kDoc =
        "rolling spring k_r [N] on the rolling displacement and damper c_r = 2 D_r sqrt(meff k_n) R_eff "
        "(Uphoff Eq. 3.56-3.59)";
    static std::vector<LawParamSpec> params() {
        return {lawParam("k_r", "N", 0, kUnbounded, false, "0",
                         "rolling stiffness (torque per rolling displacement)"),
                lawParam("D_r", "-", 0, kUnbounded, false, "0", "rolling damping ratio")};
    }
    static SpringDashpotRolling make(const LawParams& p) {
        return {p.getOr("k_r", 0.0), p.getOr("D_r", 0.0)};
    }

    Real kr = 0;     ///< [N]
    Real ratio = 0;  ///< D_r
};

using RollingLaw = std::variant<NoRolling, SpringDashpotRolling>;

/// Rolling parameters as the kernel uses them (enabled = some resistance).
struct RollingSettings {
    bool enabled = false;
    Real kr = 0;
    Real ratio = 0;
};

inline RollingSettings rollingSettings(const RollingLaw& law) noexcept {
    if (const auto* r = std::get_if<SpringDashpotRolling>(&law))
        return {r->kr > 0 || r->ratio > 0, r->kr, r->ratio};
    return {};
}

/// One resolved contact law for a pair of materials.
struct ContactLaw {
    NormalLaw normal;
    DampingLaw damping;
    TangentialLaw tangential;
    RollingLaw rolling;
    bool clipAttraction = false;  ///< clip the normal force at zero (never attractive)
};

/// Parameters valid for every law.
inline std::vector<LawParamSpec> commonLawParamSpecs() {
    LawParamSpec clip = lawParam("clip_attraction", "-", 0, 1, false, "false",
                                 "clip the normal force at zero so the contact never attracts");
    clip.isBool = true;
    return {clip};
}

}  // namespace granulab::dem
