// SPDX-License-Identifier: MIT
// World corners of the polygon particles, once per force evaluation (gc2d spec section 5.4, steps
// 2-3; Eq. 2.35 with s = 1 and the angle counter-clockwise, i.e. phi = -angle).
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "dem/forces.hpp"

namespace granulab::dem {

void ShapeContext::update(const model::ParticleStore& s, int threads,
                          const std::vector<std::uint32_t>* cuts) {
    if (!anyPolygon) return;
    GL_ASSERT(pool != nullptr, "shape pool set before the first update");
    const std::size_t n = s.size();
    first.resize(n);
    std::size_t total = 0;
    for (std::size_t i = 0; i < n; ++i) {
        first[i] = static_cast<std::uint32_t>(total);
        GL_ASSERT(s.shape[i] == model::kDiskShape || s.shape[i] < pool->size(), "shape index in range");
        if (s.shape[i] != model::kDiskShape) total += pool->count[s.shape[i]];
    }
    world.resize(total);
    rotations.resize(n);
    parallelSlots(threads, cuts, n, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint32_t k = s.shape[i];
            if (k == model::kDiskShape) continue;
            const geom::CosSin r = rotations(i, s.angle[i]);
            const Real c = r.c * scale, sn = r.s * scale;  // s R(phi)
            const Vec2 x{s.x[i], s.y[i]};
            const Vec2* body = pool->corners.data() + pool->start[k];
            Vec2* out = world.data() + first[i];
            for (std::uint32_t m = 0; m < pool->count[k]; ++m)
                out[m] = {x.x + (c * body[m].x - sn * body[m].y), x.y + (sn * body[m].x + c * body[m].y)};
        }
    });
}

}  // namespace granulab::dem
