// SPDX-License-Identifier: MIT
// Small constructors of flow fields (cfddem spec 5.4).
#include "fluid/flow_field.hpp"

namespace granulab::fluid {

FlowField uniformField(Vec2 lo, Vec2 hi, Vec2 velocity) {
    FlowField f;
    f.source = "uniform";
    f.x = {lo.x, hi.x, lo.x, hi.x};
    f.y = {lo.y, lo.y, hi.y, hi.y};
    f.ux.assign(4, velocity.x);
    f.uy.assign(4, velocity.y);
    return f;
}

}  // namespace granulab::fluid
