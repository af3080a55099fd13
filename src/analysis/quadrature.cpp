// SPDX-License-Identifier: MIT
// Gauss-Legendre nodes and weights by Newton iteration on the Legendre polynomial.
#include "analysis/quadrature.hpp"

#include <cmath>
#include <stdexcept>

namespace granulab::analysis {

GaussLegendre gaussLegendre(std::size_t n) {
    if (n == 0 || n > 256) throw std::invalid_argument("gaussLegendre: n must be in [1, 256]");
    GaussLegendre q;
    q.node.resize(n);
    q.weight.resize(n);
    const auto nr = static_cast<Real>(n);
    for (std::size_t i = 0; i < n; ++i) {
        Real x = std::cos(kPi * (static_cast<Real>(i) + 0.75) / (nr + 0.5));  // root i on [-1, 1]
        Real dp = 1;
        for (int it = 0; it < 100; ++it) {
            Real p0 = 1, p1 = x;  // P_0, P_1, recurrence up to P_n
            for (std::size_t k = 2; k <= n; ++k) {
                const auto kr = static_cast<Real>(k);
                const Real p2 = ((2 * kr - 1) * x * p1 - (kr - 1) * p0) / kr;
                p0 = p1;
                p1 = p2;
            }
            const Real pn = n == 1 ? x : p1, pm = n == 1 ? 1 : p0;
            dp = nr * (x * pn - pm) / (x * x - 1);
            const Real dx = pn / dp;
            x -= dx;
            if (std::abs(dx) < 1e-16) break;
        }
        q.node[i] = 0.5 * (1 - x);
        q.weight[i] = 1 / ((1 - x * x) * dp * dp);  // 2 / ((1 - x^2) P_n'^2) on [-1, 1], halved
    }
    return q;
}

}  // namespace granulab::analysis
