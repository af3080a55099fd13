// SPDX-License-Identifier: MIT
// ParticleStore: append, reorder and checkpoint the columns (DESIGN.md "Particle state").
#include "model/particle_store.hpp"

#include <algorithm>
#include <istream>
#include <ostream>
#include <stdexcept>

#include "core/binary_io.hpp"
#include "core/error.hpp"

namespace granulab::model {

namespace {
template <class T>
void permuteColumn(std::vector<T>& col, const std::vector<std::uint32_t>& order) {
    std::vector<T> out(order.size());  // a shorter order selects (particles removed)
    for (std::size_t k = 0; k < order.size(); ++k) {
        GL_ASSERT(order[k] < col.size(), "permutation entry is a slot");
        out[k] = col[order[k]];
    }
    col.swap(out);
}
}  // namespace

bool ParticleStore::consistent() const noexcept {
    bool ok = true;
    forEachColumn([&](const auto& col) { ok = ok && col.size() == size(); });
    return ok;
}

void ParticleStore::reserve(std::size_t n) {
    forEachColumn([n](auto& col) { col.reserve(n); });
}

std::size_t ParticleStore::add(ParticleId pid, Vec2 pos, Vec2 vel, Real angle0, Real omega0, Real r, Real m,
                               Real inertia, std::uint32_t mat, std::uint32_t shapeIndex) {
    x.push_back(pos.x);
    y.push_back(pos.y);
    vx.push_back(vel.x);
    vy.push_back(vel.y);
    angle.push_back(angle0);
    omega.push_back(omega0);
    fx.push_back(0);
    fy.push_back(0);
    torque.push_back(0);
    radius.push_back(r);
    mass.push_back(m);
    invMass.push_back(m > 0 ? 1.0 / m : 0.0);
    invInertia.push_back(inertia > 0 ? 1.0 / inertia : 0.0);
    material.push_back(mat);
    id.push_back(pid);
    shape.push_back(shapeIndex);
    GL_ASSERT(consistent(), "add() fills every column");
    return x.size() - 1;
}

void ParticleStore::permute(const std::vector<std::uint32_t>& order) {
    GL_ASSERT(order.size() == size() && consistent(), "a permutation of all slots");
    forEachColumn([&](auto& col) { permuteColumn(col, order); });
}

void ParticleStore::keep(const std::vector<std::uint32_t>& slots) {
    GL_ASSERT(slots.size() <= size() && consistent(), "a selection of the slots");
    GL_ASSERT(std::is_sorted(slots.begin(), slots.end()), "kept slots ascending");
    forEachColumn([&](auto& col) { permuteColumn(col, slots); });
}

void ParticleStore::save(std::ostream& os) const {
    GL_ASSERT(consistent(), "columns of equal length");
    forEachColumn([&](const auto& col) { writeVector(os, col); });
}

void ParticleStore::load(std::istream& is) {
    forEachColumn([&](auto& col) { readVector(is, col); });
    if (!consistent()) throw std::runtime_error("checkpoint corrupt (particle columns of different lengths)");
}

}  // namespace granulab::model
