// SPDX-License-Identifier: MIT
// ParticleStore: append and reorder (DESIGN.md "Particle state").
#include "model/particle_store.hpp"

namespace granulab::model {

namespace {
template <class... Columns>
void reserveAll(std::size_t n, Columns&... cols) {
    (cols.reserve(n), ...);
}

template <class T>
void permuteColumn(std::vector<T>& col, const std::vector<std::uint32_t>& order) {
    std::vector<T> out(col.size());
    for (std::size_t k = 0; k < order.size(); ++k) out[k] = col[order[k]];
    col.swap(out);
}
}  // namespace

void ParticleStore::reserve(std::size_t n) {
    reserveAll(n, x, y, vx, vy, angle, omega, fx, fy, torque, radius, mass, invMass, invInertia,
               material, id, shape);
}

std::size_t ParticleStore::add(ParticleId pid, Vec2 pos, Vec2 vel, Real angle0, Real omega0, Real r,
                               Real m, Real inertia, std::uint32_t mat, std::uint32_t shapeIndex) {
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
    return x.size() - 1;
}

void ParticleStore::permute(const std::vector<std::uint32_t>& order) {
    permuteColumn(x, order);
    permuteColumn(y, order);
    permuteColumn(vx, order);
    permuteColumn(vy, order);
    permuteColumn(angle, order);
    permuteColumn(omega, order);
    permuteColumn(fx, order);
    permuteColumn(fy, order);
    permuteColumn(torque, order);
    permuteColumn(radius, order);
    permuteColumn(mass, order);
    permuteColumn(invMass, order);
    permuteColumn(invInertia, order);
    permuteColumn(material, order);
    permuteColumn(id, order);
    permuteColumn(shape, order);
}

}  // namespace granulab::model
