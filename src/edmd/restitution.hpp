// SPDX-License-Identifier: MIT
// Normal restitution of a hard-sphere collision as a function of the normal impact speed
// (edmd spec 2.5.2 uses a constant eps; issue 5 asks for velocity-dependent restitution as an
// option). Three models, chosen once per run:
//  * constant:        eps(v) = eps0 (edmd Eq. 4.1, the thesis' model).
//  * mcnamara_falcon: eps(v) = 1 - (1 - eps0) (v/v0)^(3/4) for v < v0, eps0 above (McNamara &
//                     Falcon, Phys. Rev. E 71, 031302 (2005)): slow impacts become elastic,
//                     which removes inelastic collapse without the TC model.
//  * viscoelastic:    eps(v) = 1 - C1 (v/v0)^(1/5) + C2 (v/v0)^(2/5), C1 = 1.15344,
//                     C2 = 0.79826 (Schwager & Poeschel, Phys. Rev. E 78, 051304 (2008), the
//                     expansion for viscoelastic spheres to second order in v^(1/5); v0 is
//                     their material speed scale, eps(v0) = 0.645), clipped to [0, 1].
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/types.hpp"

namespace granulab::edmd {

enum class RestitutionModel : std::uint8_t { Constant, McNamaraFalcon, Viscoelastic };

struct Restitution {
    RestitutionModel model = RestitutionModel::Constant;
    Real eps = 1;    ///< eps0: constant value, or the value at v >= v0 (mcnamara_falcon)
    Real speed = 1;  ///< v0 [m/s]: the crossover (mcnamara_falcon) or characteristic speed (viscoelastic)

    /// Restitution for a normal impact speed |v_n| [m/s].
    Real operator()(Real normalSpeed) const noexcept {
        switch (model) {
            case RestitutionModel::Constant:
                return eps;
            case RestitutionModel::McNamaraFalcon:
                return normalSpeed >= speed ? eps : 1 - (1 - eps) * std::pow(normalSpeed / speed, 0.75);
            case RestitutionModel::Viscoelastic: {
                const Real s = std::pow(normalSpeed / speed, 0.2);
                return std::clamp(1 - 1.15344 * s + 0.79826 * s * s, Real(0), Real(1));
            }
        }
        return eps;
    }
    bool elastic() const noexcept { return model == RestitutionModel::Constant && eps == 1; }
};

}  // namespace granulab::edmd
