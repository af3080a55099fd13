// SPDX-License-Identifier: MIT
// Gauss-Legendre quadrature for the DEM coarse-graining line integrals and the Janssen integrals
// (gc2d spec section 7 item 3 of the analysis layer, section 8.3).
#pragma once
#include <cstddef>
#include <vector>

#include "core/types.hpp"

namespace granulab::analysis {

/// Nodes and weights of the n-point Gauss-Legendre rule on [0, 1] (exact for polynomials of
/// degree 2n - 1). Nodes by Newton iteration on P_n to machine precision. Throws
/// std::invalid_argument for n = 0 or n > 256.
struct GaussLegendre {
    std::vector<Real> node, weight;
};
GaussLegendre gaussLegendre(std::size_t n);

}  // namespace granulab::analysis
