// SPDX-License-Identifier: MIT
// Drag laws of a sphere of radius R in a fluid (cfddem spec 5.3 and its [R] "keep the drag law
// behind an interface"; docs/physics/fluid.md): one stateless struct per law with its keyword and
// one noexcept force function on the relative velocity v_r = v_p - u_f, registered in one variant
// like the contact laws (dem/contact/laws.hpp). The law is chosen once per force evaluation
// (std::visit outside the particle loop).
#pragma once
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "core/types.hpp"

namespace granulab::fluid {

/// The fluid's properties as the drag laws see them.
struct FluidProperties {
    Real density = 0;    ///< [kg/m^3] rho_f
    Real viscosity = 0;  ///< [Pa s] mu
};

/// Particle Reynolds number Re = rho_f |v_r| d / mu (with the voidage factor eps for Di Felice).
inline Real reynolds(const FluidProperties& f, Real speed, Real radius) noexcept {
    return f.viscosity > 0 ? f.density * speed * 2 * radius / f.viscosity : 0;
}

struct NoDrag {
    static constexpr const char* kKeyword = "none";
    static constexpr const char* kDoc = "no drag force";
    Vec2 force(Vec2, Real, const FluidProperties&, Real) const noexcept { return {}; }
};

/// The seed's Rayleigh law, cfddem Eq. 3.64-3.65: F = -1/2 rho_f c_w pi R^2 |v_r| v_r, constant c_w.
struct QuadraticDrag {
    static constexpr const char* kKeyword = "quadratic";
    static constexpr const char* kDoc = "F = -1/2 rho_f c_w pi R^2 |v_r| v_r, constant c_w (cfddem Eq. 3.64)";
    Real cw = 0.47;
    Vec2 force(Vec2 vr, Real radius, const FluidProperties& f, Real) const noexcept {
        return vr * (-0.5 * f.density * cw * kPi * radius * radius * norm(vr));
    }
};

/// Stokes' law for creeping flow (Re << 1): F = -6 pi mu R v_r.
struct StokesDrag {
    static constexpr const char* kKeyword = "stokes";
    static constexpr const char* kDoc = "F = -6 pi mu R v_r (creeping flow, Re << 1)";
    Vec2 force(Vec2 vr, Real radius, const FluidProperties& f, Real) const noexcept {
        return vr * (-6 * kPi * f.viscosity * radius);
    }
};

/// Schiller and Naumann (1933): C_D = 24/Re (1 + 0.15 Re^0.687) for Re < 1000, 0.44 above;
/// F = -1/2 rho_f C_D pi R^2 |v_r| v_r (Stokes' law as Re -> 0).
struct SchillerNaumannDrag {
    static constexpr const char* kKeyword = "schiller_naumann";
    static constexpr const char* kDoc =
        "C_D = 24/Re (1 + 0.15 Re^0.687), 0.44 above Re = 1000 (Schiller-Naumann)";
    static Real coefficient(Real re) noexcept {
        return re < 1000 ? 24 / re * (1 + 0.15 * std::pow(re, 0.687)) : 0.44;
    }
    Vec2 force(Vec2 vr, Real radius, const FluidProperties& f, Real) const noexcept {
        const Real speed = norm(vr);
        if (speed == 0) return {};
        const Real re = reynolds(f, speed, radius);
        // 1/2 rho C_D A |v| v with C_D = 24/Re (...) written without dividing by Re -> 0.
        const Real scale = re < 1000 ? 6 * kPi * f.viscosity * radius * (1 + 0.15 * std::pow(re, 0.687))
                                     : 0.5 * f.density * 0.44 * kPi * radius * radius * speed;
        return vr * (-scale);
    }
};

/// Di Felice (1994) for particles in a crowd, in the form of Zhu et al. (2007):
/// F = -1/2 rho_f C_D pi R^2 eps^2 |v_r| v_r eps^-chi, C_D = (0.63 + 4.8 / sqrt(Re))^2 (Dalla Valle),
/// Re = rho_f eps |v_r| d / mu, chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2); eps the local voidage.
/// At eps = 1 it is Dalla Valle's single-sphere law.
struct DiFeliceDrag {
    static constexpr const char* kKeyword = "di_felice";
    static constexpr const char* kDoc =
        "Di Felice voidage-dependent drag, C_D = (0.63 + 4.8/sqrt(Re))^2, factor eps^(2-chi)";
    static Real coefficient(Real re) noexcept {
        const Real c = 0.63 + 4.8 / std::sqrt(re);
        return c * c;
    }
    static Real exponent(Real re) noexcept {
        const Real l = 1.5 - std::log10(re);
        return 3.7 - 0.65 * std::exp(-0.5 * l * l);
    }
    Vec2 force(Vec2 vr, Real radius, const FluidProperties& f, Real voidage) const noexcept {
        const Real speed = norm(vr);
        if (speed == 0) return {};
        const Real re = reynolds(f, voidage * speed, radius);
        const Real factor = std::pow(voidage, 2 - exponent(re));
        return vr * (-0.5 * f.density * coefficient(re) * kPi * radius * radius * speed * factor);
    }
};

using DragLaw = std::variant<NoDrag, QuadraticDrag, StokesDrag, SchillerNaumannDrag, DiFeliceDrag>;

/// Keywords of the registered laws, in variant order (the scene's `fluid.drag`).
std::vector<std::string> dragKeywords();
/// The law of `keyword` (an unknown keyword gives NoDrag; the scene reader checks keywords);
/// `cw` is the quadratic law's coefficient.
DragLaw makeDragLaw(const std::string& keyword, Real cw);
/// True if the law depends on the viscosity (stokes, schiller_naumann, di_felice).
inline bool needsViscosity(const DragLaw& law) noexcept {
    return !std::holds_alternative<NoDrag>(law) && !std::holds_alternative<QuadraticDrag>(law);
}
/// True if the law needs the local voidage (di_felice).
inline bool needsVoidage(const DragLaw& law) noexcept {
    return std::holds_alternative<DiFeliceDrag>(law);
}

}  // namespace granulab::fluid
