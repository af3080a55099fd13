// SPDX-License-Identifier: MIT
// The drag-law registry (fluid/drag_laws.hpp).
#include "fluid/drag_laws.hpp"

#include <utility>

namespace granulab::fluid {

namespace {
template <std::size_t... I>
std::vector<std::string> keywords(std::index_sequence<I...>) {
    return {std::variant_alternative_t<I, DragLaw>::kKeyword...};
}
}  // namespace

std::vector<std::string> dragKeywords() {
    return keywords(std::make_index_sequence<std::variant_size_v<DragLaw>>{});
}

DragLaw makeDragLaw(const std::string& keyword, Real cw) {
    if (keyword == QuadraticDrag::kKeyword) return QuadraticDrag{cw};
    if (keyword == StokesDrag::kKeyword) return StokesDrag{};
    if (keyword == SchillerNaumannDrag::kKeyword) return SchillerNaumannDrag{};
    if (keyword == DiFeliceDrag::kKeyword) return DiFeliceDrag{};
    return NoDrag{};
}

}  // namespace granulab::fluid
