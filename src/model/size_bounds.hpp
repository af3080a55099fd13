// SPDX-License-Identifier: MIT
// Smallest and largest radius a size distribution ([[block]] radius, docs/scene-format.md) can
// produce [m]: constant, uniform or truncated Gaussian.
#pragma once
#include "model/scene_def.hpp"

namespace granulab::model {

inline Real minRadius(const SizeDistDef& d) noexcept {
    return d.kind == SizeDistDef::Kind::Constant ? d.value : d.min;
}
inline Real maxRadius(const SizeDistDef& d) noexcept {
    return d.kind == SizeDistDef::Kind::Constant ? d.value : d.max;
}

}  // namespace granulab::model
