// SPDX-License-Identifier: MIT
// Integrators: velocity Verlet, explicit Euler, the cfddem predictor-corrector iteration and the
// gc2d 6-value Gear predictor-corrector, and their factory.
#include "dem/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <istream>
#include <limits>
#include <ostream>

#include "core/binary_io.hpp"
#include "core/parallel.hpp"

namespace granulab::dem {

void StateColumns::permute(const std::vector<std::uint32_t>& order) {
    for (auto& col : columns) {
        if (col.empty()) continue;            // no step in progress yet
        std::vector<Real> out(order.size());  // a shorter order selects (particles removed)
        for (std::size_t k = 0; k < order.size(); ++k) out[k] = order[k] < col.size() ? col[order[k]] : 0.0;
        col.swap(out);
    }
}

std::size_t StateColumns::bytes() const noexcept {
    std::size_t b = 0;
    for (const auto& c : columns) b += c.capacity() * sizeof(Real);
    return b;
}

namespace {
/// The three degrees of freedom of a 2D particle (x, y, phi) as parallel column pointers:
/// position, velocity, generalised force and inverse inertia of each.
struct Dofs {
    Real* pos[3];
    Real* vel[3];
    const Real* force[3];
    const Real* inv[3];
    explicit Dofs(model::ParticleStore& s) noexcept
        : pos{s.x.data(), s.y.data(), s.angle.data()},
          vel{s.vx.data(), s.vy.data(), s.omega.data()},
          force{s.fx.data(), s.fy.data(), s.torque.data()},
          inv{s.invMass.data(), s.invMass.data(), s.invInertia.data()} {}
};

/// Largest |v|^2 over the slots [begin, end); NaN propagates so that the caller sees a blow-up.
Real maxSquaredSpeed(const model::ParticleStore& s, std::size_t begin, std::size_t end) noexcept {
    const Real* __restrict vx = s.vx.data();
    const Real* __restrict vy = s.vy.data();
    Real maxV2 = 0;
    Real nanSeen = 0;  // a double flag: an int flag kept the loop scalar (GCC 12)
#pragma omp simd reduction(max : maxV2) reduction(max : nanSeen)  // see VelocityVerlet::predict
    for (std::size_t i = begin; i < end; ++i) {
        const Real v2 = vx[i] * vx[i] + vy[i] * vy[i];
        maxV2 = v2 > maxV2 ? v2 : maxV2;
        nanSeen = v2 == v2 ? nanSeen : 1.0;
    }
    return nanSeen > 0 ? std::numeric_limits<Real>::quiet_NaN() : maxV2;
}

/// Largest |v| of the store (NaN wins).
Real maxSpeed(const model::ParticleStore& s, int threads, const std::vector<std::uint32_t>* cuts) noexcept {
    return std::sqrt(parallelMax(threads, cuts, s.size(), [&](std::size_t begin, std::size_t end) {
        return maxSquaredSpeed(s, begin, end);
    }));
}
}  // namespace

// ------------------------------------------------------------------ velocity Verlet

namespace {
/// Velocity Verlet's first half step over the slots [begin, end): half-step velocities into
/// `half`, positions at t + dt, velocities predicted at t + dt; returns the largest |v_half|^2
/// (NaN wins).
Real verletPredictSlots(model::ParticleStore& s, Real* const half[3], Real dt, std::size_t begin,
                        std::size_t end) noexcept {
    Real* __restrict x = s.x.data();
    Real* __restrict y = s.y.data();
    Real* __restrict vx = s.vx.data();
    Real* __restrict vy = s.vy.data();
    Real* __restrict a = s.angle.data();
    Real* __restrict w = s.omega.data();
    Real* __restrict hvx = half[0];
    Real* __restrict hvy = half[1];
    Real* __restrict hw = half[2];
    const Real* __restrict fx = s.fx.data();
    const Real* __restrict fy = s.fy.data();
    const Real* __restrict tq = s.torque.data();
    const Real* __restrict im = s.invMass.data();
    const Real* __restrict ii = s.invInertia.data();
    const Real h = 0.5 * dt;
    Real maxV2 = 0;
    // A max reduction vectorizes only when the compiler may reorder it (exact for a maximum), and
    // NaN is flagged apart in a double: with an int flag (`|=`) GCC 12 kept the loop scalar, 10 %
    // of the settled disk bed.
    Real nanSeen = 0;
#pragma omp simd reduction(max : maxV2) reduction(max : nanSeen)
    for (std::size_t i = begin; i < end; ++i) {
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
        maxV2 = v2 > maxV2 ? v2 : maxV2;
        nanSeen = v2 == v2 ? nanSeen : 1.0;  // NaN is seen by the caller
    }
    return nanSeen > 0 ? std::numeric_limits<Real>::quiet_NaN() : maxV2;
}
}  // namespace

Real VelocityVerlet::predict(model::ParticleStore& s, Real dt) noexcept {
    m_half.resize(s.size());  // no-op after the first step
    Real* const half[3] = {m_half[0], m_half[1], m_half[2]};
    return std::sqrt(parallelMax(m_threads, m_slotCuts, s.size(), [&](std::size_t begin, std::size_t end) {
        return verletPredictSlots(s, half, dt, begin, end);
    }));
}

bool VelocityVerlet::correct(model::ParticleStore& s, Real dt, int) noexcept {
    forSlots(s.size(),
             [&](std::size_t begin, std::size_t end, std::size_t) { correctSlots(s, dt, begin, end); });
    return true;
}

void VelocityVerlet::correctSlots(model::ParticleStore& s, Real dt, std::size_t begin,
                                  std::size_t end) noexcept {
    const Real h = 0.5 * dt;
    Real* __restrict vx = s.vx.data();
    Real* __restrict vy = s.vy.data();
    Real* __restrict w = s.omega.data();
    const Real* __restrict hvx = m_half[0];
    const Real* __restrict hvy = m_half[1];
    const Real* __restrict hw = m_half[2];
    const Real* __restrict fx = s.fx.data();
    const Real* __restrict fy = s.fy.data();
    const Real* __restrict tq = s.torque.data();
    const Real* __restrict im = s.invMass.data();
    const Real* __restrict ii = s.invInertia.data();
#pragma omp simd
    for (std::size_t i = begin; i < end; ++i) {
        vx[i] = hvx[i] + h * fx[i] * im[i];
        vy[i] = hvy[i] + h * fy[i] * im[i];
        w[i] = hw[i] + h * tq[i] * ii[i];
    }
}

// ------------------------------------------------------------------ explicit Euler

Real ExplicitEuler::predict(model::ParticleStore& s, Real dt) noexcept {
    const std::size_t n = s.size();
    m_old.resize(n);
    forSlots(n, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t i = begin; i < end; ++i) {
            m_old[0][i] = s.vx[i];
            m_old[1][i] = s.vy[i];
            m_old[2][i] = s.omega[i];
            s.x[i] += dt * s.vx[i];
            s.y[i] += dt * s.vy[i];
            s.angle[i] += dt * s.omega[i];
            s.vx[i] += dt * s.fx[i] * s.invMass[i];
            s.vy[i] += dt * s.fy[i] * s.invMass[i];
            s.omega[i] += dt * s.torque[i] * s.invInertia[i];
        }
    });
    return maxSpeed(s, m_threads, m_slotCuts);
}

bool ExplicitEuler::correct(model::ParticleStore&, Real, int) noexcept {
    return true;
}

// ------------------------------------------------------------------ cfddem predictor-corrector

DriftVelocities PredictorCorrector::driftVelocities() const noexcept {
    return {m_state[6], m_state[7], m_state[8]};
}

Real PredictorCorrector::predict(model::ParticleStore& s, Real dt) noexcept {
    const std::size_t n = s.size();
    m_state.resize(n);
    Real* ap[3] = {m_state[0], m_state[1], m_state[2]};
    Real* vn[3] = {m_state[3], m_state[4], m_state[5]};
    Real* drift[3] = {m_state[6], m_state[7], m_state[8]};
    const Dofs dof(s);
    forSlots(n, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (int d = 0; d < 3; ++d)
            for (std::size_t i = begin; i < end; ++i) {
                const Real a = dof.force[d][i] * dof.inv[d][i];  // acceleration accepted at t (Eq. 3.16-3.19)
                ap[d][i] = a;
                vn[d][i] = dof.vel[d][i];
                dof.pos[d][i] += dof.vel[d][i] * dt + 0.5 * a * dt * dt;
                dof.vel[d][i] += a * dt;
                drift[d][i] = m_maxIterations == 0 ? dof.vel[d][i] : 0.5 * (vn[d][i] + dof.vel[d][i]);
            }
    });
    return maxSpeed(s, m_threads, m_slotCuts);
}

bool PredictorCorrector::correct(model::ParticleStore& s, Real dt, int iteration) noexcept {
    if (m_maxIterations == 0) return true;  // modified explicit Euler: accept the prediction
    const std::size_t n = s.size();
    Real* ap[3] = {m_state[0], m_state[1], m_state[2]};
    Real* vn[3] = {m_state[3], m_state[4], m_state[5]};
    Real* drift[3] = {m_state[6], m_state[7], m_state[8]};
    const Dofs dof(s);
    // Eq. 3.24: the largest |a^c - a^p| over all particles and components.
    const Real worst = parallelMax(m_threads, m_slotCuts, n, [&](std::size_t begin, std::size_t end) {
        Real w = 0;
        for (int d = 0; d < 3; ++d)
            for (std::size_t i = begin; i < end; ++i)
                w = maxOrNaN(w, std::abs(dof.force[d][i] * dof.inv[d][i] - ap[d][i]));
        return w;
    });
    if (worst <= m_tolerance || iteration >= m_maxIterations || worst != worst) return true;
    const Real c = m_corrector;
    forSlots(n, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (int d = 0; d < 3; ++d)
            for (std::size_t i = begin; i < end; ++i) {
                const Real da = dof.force[d][i] * dof.inv[d][i] - ap[d][i];
                dof.pos[d][i] += 0.25 * c * da * dt * dt;  // Eq. 3.25
                dof.vel[d][i] += 0.5 * c * da * dt;        // Eq. 3.26
                ap[d][i] += c * da;                        // Eq. 3.27
                drift[d][i] = 0.5 * (vn[d][i] + dof.vel[d][i]);
            }
    });
    return false;
}

// ------------------------------------------------------------------ gc2d Gear 6-value PC

namespace {
/// Gear predictor (Eq. F.11) of one degree of freedom over [begin, end): separate columns
/// (restrict) and h in a register, so that the loop vectorises with the same operations per
/// element as the scalar loop.
void gearPredictColumn(std::size_t begin, std::size_t end, Real h, Real* __restrict pos, Real* __restrict vel,
                       Real* __restrict r2, Real* __restrict r3, Real* __restrict r4, Real* __restrict r5,
                       Real* __restrict drift) noexcept {
    for (std::size_t i = begin; i < end; ++i) {
        const Real r1 = vel[i] * h;
        // Pascal-matrix predictor (Eq. F.11), each row using the old higher values.
        const Real dr0 = r1 + r2[i] + r3[i] + r4[i] + r5[i];
        pos[i] += dr0;
        vel[i] = (r1 + 2 * r2[i] + 3 * r3[i] + 4 * r4[i] + 5 * r5[i]) / h;
        r2[i] += 3 * r3[i] + 6 * r4[i] + 10 * r5[i];
        r3[i] += 4 * r4[i] + 10 * r5[i];
        r4[i] += 5 * r5[i];
        drift[i] = dr0 / h;
    }
}

/// Gear corrector (Eq. F.13 and Table F.1) of one degree of freedom over [begin, end), as above.
void gearCorrectColumn(std::size_t begin, std::size_t end, Real h, Real c0, Real* __restrict pos,
                       Real* __restrict vel, const Real* __restrict force, const Real* __restrict inv,
                       Real* __restrict r2, Real* __restrict r3, Real* __restrict r4,
                       Real* __restrict r5) noexcept {
    constexpr Real c1 = 251.0 / 360.0, c3 = 11.0 / 18.0, c4 = 1.0 / 6.0, c5 = 1.0 / 60.0;  // Table F.1, p = 2
    for (std::size_t i = begin; i < end; ++i) {
        const Real delta = 0.5 * h * h * force[i] * inv[i] - r2[i];  // Eq. F.13
        pos[i] += c0 * delta;
        vel[i] += c1 * delta / h;
        r2[i] += delta;
        r3[i] += c3 * delta;
        r4[i] += c4 * delta;
        r5[i] += c5 * delta;
    }
}
}  // namespace

Real GearPredictorCorrector::predict(model::ParticleStore& s, Real dt) noexcept {
    const std::size_t n = s.size();
    m_state.resize(n);
    const Dofs dof(s);
    std::array<std::array<Real*, 4>, 3> higher;
    for (int d = 0; d < 3; ++d) higher[static_cast<std::size_t>(d)] = higherDerivatives(d);
    const bool start = !m_started;
    // The largest speed of each range right after its prediction, in the same parallel region.
    const Real maxV2 = parallelMax(m_threads, m_slotCuts, n, [&](std::size_t begin, std::size_t end) {
        for (int d = 0; d < 3; ++d) {
            auto [r2, r3, r4, r5] = higher[static_cast<std::size_t>(d)];
            if (start)  // start from the forces at t = 0, higher derivatives zero
                for (std::size_t i = begin; i < end; ++i) {
                    r2[i] = 0.5 * dt * dt * dof.force[d][i] * dof.inv[d][i];
                    r3[i] = r4[i] = r5[i] = 0;
                }
            gearPredictColumn(begin, end, dt, dof.pos[d], dof.vel[d], r2, r3, r4, r5, m_state[12 + d]);
        }
        return maxSquaredSpeed(s, begin, end);
    });
    m_started = true;
    return std::sqrt(maxV2);
}

bool GearPredictorCorrector::correct(model::ParticleStore& s, Real dt, int) noexcept {
    forSlots(s.size(),
             [&](std::size_t begin, std::size_t end, std::size_t) { correctSlots(s, dt, begin, end); });
    return true;
}

void GearPredictorCorrector::correctSlots(model::ParticleStore& s, Real dt, std::size_t begin,
                                          std::size_t end) noexcept {
    const Dofs dof(s);
    for (int d = 0; d < 3; ++d) {
        auto [r2, r3, r4, r5] = higherDerivatives(d);
        gearCorrectColumn(begin, end, dt, m_c0, dof.pos[d], dof.vel[d], dof.force[d], dof.inv[d], r2, r3, r4,
                          r5);
    }
}

void GearPredictorCorrector::save(std::ostream& os) const {
    writePod<std::uint8_t>(os, m_started ? 1 : 0);
    for (int k = 0; k < 12; ++k) writeVector(os, m_state.columns[static_cast<std::size_t>(k)]);
}

bool GearPredictorCorrector::restoreDerivatives(const std::vector<Real>& perSlot) {
    const std::size_t n = perSlot.size() / 12;
    for (std::size_t k = 0; k < 15; ++k) m_state.columns[k].assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < 12; ++k) m_state.columns[k][i] = perSlot[12 * i + k];
    m_started = true;
    return true;
}

std::vector<Real> GearPredictorCorrector::derivatives() const {
    if (!m_started) return {};
    const std::size_t n = m_state.columns[0].size();
    std::vector<Real> out(12 * n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < 12; ++k) out[12 * i + k] = m_state.columns[k][i];
    return out;
}

void GearPredictorCorrector::load(std::istream& is, std::size_t particles) {
    m_started = readPod<std::uint8_t>(is) != 0;
    for (int k = 0; k < 12; ++k) readVector(is, m_state.columns[static_cast<std::size_t>(k)]);
    m_state.columns[12].resize(particles);
    m_state.columns[13].resize(particles);
    m_state.columns[14].resize(particles);
}

// ------------------------------------------------------------------ factory

std::unique_ptr<Integrator> makeIntegrator(const IntegratorParams& p) {
    if (p.name == "verlet") return std::make_unique<VelocityVerlet>();
    if (p.name == "euler") return std::make_unique<ExplicitEuler>();
    if (p.name == "pc")
        return std::make_unique<PredictorCorrector>(p.tolerance, p.maxIterations, p.corrector);
    if (p.name == "gear") return std::make_unique<GearPredictorCorrector>(p.gearC0);
    return nullptr;
}

std::vector<std::string> integratorNames() {
    return {"auto", "verlet", "euler", "pc", "gear"};
}

}  // namespace granulab::dem
