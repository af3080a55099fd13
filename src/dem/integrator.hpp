// SPDX-License-Identifier: MIT
// Time integrators behind one coarse-grained interface (DESIGN.md stages 1 and 7; virtual call
// once per stage per step). Velocity Verlet now; Euler, predictor-corrector and Gear come with
// issue 3 through the same interface.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "model/particle_store.hpp"

namespace granulab::dem {

/// Velocities that moved the particles during the current step (the drift velocities): contact
/// laws integrate tangential displacements with them. Null pointers: no displacement (set-up).
struct DriftVelocities {
    const Real* vx = nullptr;
    const Real* vy = nullptr;
    const Real* omega = nullptr;
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual const char* name() const noexcept = 0;
    /// Stage 1: advance positions to t + dt using the forces of the last evaluation.
    /// Returns the largest speed [m/s] seen (for the tunnelling guard).
    virtual Real predict(model::ParticleStore& s, Real dt) noexcept = 0;
    /// Stage 7: complete the step with the forces at t + dt.
    virtual void correct(model::ParticleStore& s, Real dt) noexcept = 0;
    /// The drift velocities of the step in progress (valid between predict and correct).
    virtual DriftVelocities driftVelocities() const noexcept = 0;
    /// Reorders per-particle integrator state after the store was permuted (new k = old order[k]).
    virtual void permute(const std::vector<std::uint32_t>& order) = 0;
    /// Bytes of per-particle integrator state.
    virtual std::size_t memoryBytes() const noexcept = 0;
};

/// Velocity Verlet (kick-drift-kick), second order and symplectic for conservative forces.
/// Velocity-dependent forces (damping) are evaluated with the predicted full-step velocity
/// v(t+dt) ~ v(t+dt/2) + dt/2 a(t), which keeps the restitution of a damped contact second-order
/// accurate (with the half-step velocity that LAMMPS uses the error is first order: 3e-3 instead
/// of 8e-4 at 50 steps per contact and e = 0.7, docs/physics/contact-laws.md). Positions, and
/// hence conservative dynamics, are exactly those of standard velocity Verlet.
class VelocityVerlet final : public Integrator {
public:
    const char* name() const noexcept override { return "verlet"; }
    Real predict(model::ParticleStore& s, Real dt) noexcept override;
    void correct(model::ParticleStore& s, Real dt) noexcept override;
    DriftVelocities driftVelocities() const noexcept override {
        return {m_halfVx.data(), m_halfVy.data(), m_halfOmega.data()};
    }
    void permute(const std::vector<std::uint32_t>& order) override;
    std::size_t memoryBytes() const noexcept override {
        return (m_halfVx.capacity() + m_halfVy.capacity() + m_halfOmega.capacity()) * sizeof(Real);
    }

private:
    std::vector<Real> m_halfVx, m_halfVy, m_halfOmega;  ///< [m/s], [rad/s] v(t + dt/2)
};

std::unique_ptr<Integrator> makeIntegrator(const std::string& name);
std::vector<std::string> integratorNames();

}  // namespace granulab::dem
