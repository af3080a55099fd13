// SPDX-License-Identifier: MIT
// Velocity Verlet and the integrator factory.
#include "dem/integrator.hpp"

#include <cmath>

namespace granulab::dem {

Real VelocityVerlet::predict(model::ParticleStore& s, Real dt) noexcept {
    const std::size_t n = s.size();
    if (m_halfVx.size() != n) {  // first step or particle count changed (outside the hot loop)
        m_halfVx.resize(n);
        m_halfVy.resize(n);
        m_halfOmega.resize(n);
    }
    const Real h = 0.5 * dt;
    Real* __restrict x = s.x.data();
    Real* __restrict y = s.y.data();
    Real* __restrict vx = s.vx.data();
    Real* __restrict vy = s.vy.data();
    Real* __restrict a = s.angle.data();
    Real* __restrict w = s.omega.data();
    Real* __restrict hvx = m_halfVx.data();
    Real* __restrict hvy = m_halfVy.data();
    Real* __restrict hw = m_halfOmega.data();
    const Real* __restrict fx = s.fx.data();
    const Real* __restrict fy = s.fy.data();
    const Real* __restrict tq = s.torque.data();
    const Real* __restrict im = s.invMass.data();
    const Real* __restrict ii = s.invInertia.data();
    Real maxV2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Real kx = h * fx[i] * im[i], ky = h * fy[i] * im[i], kw = h * tq[i] * ii[i];
        hvx[i] = vx[i] + kx;
        hvy[i] = vy[i] + ky;
        hw[i] = w[i] + kw;
        x[i] += dt * hvx[i];
        y[i] += dt * hvy[i];
        a[i] += dt * hw[i];
        vx[i] = hvx[i] + kx;  // predicted v(t + dt) for velocity-dependent forces
        vy[i] = hvy[i] + ky;
        w[i] = hw[i] + kw;
        const Real v2 = hvx[i] * hvx[i] + hvy[i] * hvy[i];
        maxV2 = (v2 > maxV2 || v2 != v2) ? v2 : maxV2;  // NaN propagates
    }
    return std::sqrt(maxV2);
}

void VelocityVerlet::correct(model::ParticleStore& s, Real dt) noexcept {
    const std::size_t n = s.size();
    const Real h = 0.5 * dt;
    for (std::size_t i = 0; i < n; ++i) {
        s.vx[i] = m_halfVx[i] + h * s.fx[i] * s.invMass[i];
        s.vy[i] = m_halfVy[i] + h * s.fy[i] * s.invMass[i];
        s.omega[i] = m_halfOmega[i] + h * s.torque[i] * s.invInertia[i];
    }
}

void VelocityVerlet::permute(const std::vector<std::uint32_t>& order) {
    if (m_halfVx.size() != order.size()) return;  // no step in progress yet
    for (auto* col : {&m_halfVx, &m_halfVy, &m_halfOmega}) {
        std::vector<Real> out(order.size());
        for (std::size_t k = 0; k < order.size(); ++k) out[k] = (*col)[order[k]];
        col->swap(out);
    }
}

std::unique_ptr<Integrator> makeIntegrator(const std::string& name) {
    if (name == "verlet") return std::make_unique<VelocityVerlet>();
    return nullptr;
}

std::vector<std::string> integratorNames() { return {"verlet"}; }

}  // namespace granulab::dem
