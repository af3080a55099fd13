// SPDX-License-Identifier: MIT
// Time integrators behind one coarse-grained interface (DESIGN.md stages 1 and 7; virtual call
// once per stage per step, never per particle): velocity Verlet, explicit Euler, the cfddem
// seed's predictor-corrector iteration (spec/cfddem.md section 2; modified Euler with 0
// iterations) and the 6-value Gear predictor-corrector of gc2d (spec/gc2d.md section 4).
#pragma once
#include <array>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "core/parallel.hpp"
#include "model/particle_store.hpp"

namespace granulab::dem {

/// Velocities that moved the particles during the current step (the drift velocities): contact
/// laws integrate tangential displacements with them, so that the spring increment matches the
/// integrator (spec/cfddem.md section 3.6). Null pointers: no displacement (set-up).
struct DriftVelocities {
    const Real* vx = nullptr;
    const Real* vy = nullptr;
    const Real* omega = nullptr;
};

struct StateColumns;

/// Parameters of all integrators (each uses its own).
struct IntegratorParams {
    std::string name = "verlet";
    Real tolerance = 1e-5;     ///< pc: |a^c - a^p| threshold [m/s^2, rad/s^2]
    int maxIterations = 10;    ///< pc: corrector iterations (0: modified explicit Euler)
    Real corrector = 0.5;      ///< pc: relaxation factor c in (0, 1]
    Real gearC0 = 3.0 / 16.0;  ///< gear: first corrector coefficient (3/16 for velocity-dependent forces)
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual const char* name() const noexcept = 0;
    /// Stage 1: advance the state to the trial state at t + dt from the accepted state at t and
    /// the forces evaluated there. Returns the largest speed [m/s] (tunnelling guard).
    virtual Real predict(model::ParticleStore& s, Real dt) noexcept = 0;
    /// True if predict's largest speed times dt bounds every particle's displacement in the step
    /// (the neighbour check may then skip its O(N) scan while the sum stays below the skin).
    virtual bool speedBoundsDisplacement() const noexcept { return false; }
    /// Stage 7 after a force evaluation at the trial state: returns true when the step is
    /// accepted; false asks for another force evaluation at the updated trial state.
    virtual bool correct(model::ParticleStore& s, Real dt, int iteration) noexcept = 0;
    /// True if correct() is elementwise, always accepts, and a slot's correction needs nothing but
    /// that slot's own state and forces: World then runs correctSlots() on each thread's slots
    /// inside the force stage's parallel region, as soon as their forces are complete.
    virtual bool correctsBySlots() const noexcept { return false; }
    /// correct() on the slots [begin, end) only (for correctsBySlots() integrators; iteration 0).
    virtual void correctSlots(model::ParticleStore&, Real /*dt*/, std::size_t /*begin*/,
                              std::size_t /*end*/) noexcept {}
    /// The drift velocities of the step in progress (valid between predict and correct).
    virtual DriftVelocities driftVelocities() const noexcept = 0;
    /// True if every step has exactly one force evaluation (contact history is then updated in
    /// place; otherwise trial values are committed once per accepted step).
    virtual bool singleEvaluation() const noexcept { return true; }
    /// Reorders per-particle state after the store was permuted (new k = old order[k]).
    virtual void permute(const std::vector<std::uint32_t>& order) = 0;
    /// Bytes of per-particle integrator state.
    virtual std::size_t memoryBytes() const noexcept = 0;
    /// State that must survive a checkpoint (default: none).
    virtual void save(std::ostream&) const {}
    virtual void load(std::istream&, std::size_t /*particles*/) {}
    /// The per-particle state columns (nullptr: none), for moving particles between ranks.
    virtual StateColumns* state() noexcept { return nullptr; }
    /// gc2d restart: the Gear predictor's scaled derivatives r2..r5 of x, y, phi, 12 per particle
    /// in slot order (model::ParticleDef::gear). False for an integrator without such state.
    virtual bool restoreDerivatives(const std::vector<Real>& /*perSlot*/) { return false; }
    /// The same state for a gso: 12 per particle in slot order; empty when there is none (another
    /// integrator, or a Gear predictor before its first step).
    virtual std::vector<Real> derivatives() const { return {}; }
    const StateColumns* state() const noexcept { return const_cast<Integrator*>(this)->state(); }
    /// Threads of predict and correct (elementwise loops: the results do not depend on them).
    void setThreads(int threads) noexcept { m_threads = threads > 1 ? threads : 1; }
    /// The slot ranges of the threads (parallelSlots; the force split's, so that a thread integrates
    /// the particles whose forces it summed); nullptr: equal blocks. The vector must outlive the
    /// integrator's steps (World's ForceWorkspace).
    void setSlotCuts(const std::vector<std::uint32_t>* cuts) noexcept { m_slotCuts = cuts; }

protected:
    /// parallelSlots over the store's n slots on the integrator's threads and ranges.
    template <class Fn>
    void forSlots(std::size_t n, Fn&& fn) const noexcept {
        parallelSlots(m_threads, m_slotCuts, n, fn);
    }
    int m_threads = 1;
    const std::vector<std::uint32_t>* m_slotCuts = nullptr;
};

/// Columns of per-particle integrator state, reordered and sized together.
struct StateColumns {
    std::vector<std::vector<Real>> columns;
    explicit StateColumns(std::size_t count) : columns(count) {}
    void resize(std::size_t n) {
        for (auto& c : columns) c.resize(n);
    }
    /// Copies row k to out[0 .. columns.size()) (0 where a column does not reach k: before the
    /// first step sized it).
    void copyRow(std::size_t k, Real* out) const noexcept {
        for (std::size_t c = 0; c < columns.size(); ++c) out[c] = k < columns[c].size() ? columns[c][k] : 0.0;
    }
    /// Sets row k where the columns reach it.
    void setRow(std::size_t k, const Real* in) noexcept {
        for (std::size_t c = 0; c < columns.size(); ++c)
            if (k < columns[c].size()) columns[c][k] = in[c];
    }
    void permute(const std::vector<std::uint32_t>& order);
    std::size_t bytes() const noexcept;
    Real* operator[](std::size_t k) noexcept { return columns[k].data(); }
    const Real* operator[](std::size_t k) const noexcept { return columns[k].data(); }
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
    /// x(t + dt) = x(t) + dt v(t + dt/2), and predict returns the largest |v(t + dt/2)|.
    bool speedBoundsDisplacement() const noexcept override { return true; }
    bool correct(model::ParticleStore& s, Real dt, int iteration) noexcept override;
    bool correctsBySlots() const noexcept override { return true; }
    void correctSlots(model::ParticleStore& s, Real dt, std::size_t begin, std::size_t end) noexcept override;
    DriftVelocities driftVelocities() const noexcept override { return {m_half[0], m_half[1], m_half[2]}; }
    StateColumns* state() noexcept override { return &m_half; }
    void permute(const std::vector<std::uint32_t>& order) override { m_half.permute(order); }
    std::size_t memoryBytes() const noexcept override { return m_half.bytes(); }

private:
    StateColumns m_half{3};  ///< v(t + dt/2): vx, vy [m/s], omega [rad/s]
};

/// Explicit (forward) Euler: x += v dt, v += a dt with the forces at t. First order; for
/// comparison and teaching, not for production runs.
class ExplicitEuler final : public Integrator {
public:
    const char* name() const noexcept override { return "euler"; }
    Real predict(model::ParticleStore& s, Real dt) noexcept override;
    bool correct(model::ParticleStore& s, Real dt, int iteration) noexcept override;
    DriftVelocities driftVelocities() const noexcept override { return {m_old[0], m_old[1], m_old[2]}; }
    StateColumns* state() noexcept override { return &m_old; }
    void permute(const std::vector<std::uint32_t>& order) override { m_old.permute(order); }
    std::size_t memoryBytes() const noexcept override { return m_old.bytes(); }

private:
    StateColumns m_old{3};  ///< v(t) that moved the particles during the step
};

/// The cfddem seed's predictor-corrector iteration (spec section 2.4): Taylor predictor with the
/// last acceleration, then relaxed corrections r += c Da dt^2/4, v += c Da dt/2, a += c Da until
/// every |Da| <= tolerance or maxIterations; the converged scheme is the trapezoidal (Newmark
/// beta = 1/4, gamma = 1/2) rule. maxIterations = 0 is the seed's "modified explicit Euler".
/// Tangential springs grow with the trapezoidal increment dt (v_n + v^p)/2 when iterating, and
/// with v^p dt for modified Euler (spec section 3.6).
class PredictorCorrector final : public Integrator {
public:
    PredictorCorrector(Real tolerance, int maxIterations, Real corrector)
        : m_tolerance(tolerance), m_maxIterations(maxIterations), m_corrector(corrector) {}
    const char* name() const noexcept override { return "pc"; }
    Real predict(model::ParticleStore& s, Real dt) noexcept override;
    bool correct(model::ParticleStore& s, Real dt, int iteration) noexcept override;
    DriftVelocities driftVelocities() const noexcept override;
    bool singleEvaluation() const noexcept override { return m_maxIterations == 0; }
    StateColumns* state() noexcept override { return &m_state; }
    void permute(const std::vector<std::uint32_t>& order) override { m_state.permute(order); }
    std::size_t memoryBytes() const noexcept override { return m_state.bytes(); }

private:
    Real m_tolerance;
    int m_maxIterations;
    Real m_corrector;
    /// a^p (3), v_n (3), drift (3): accelerations [m/s^2, rad/s^2], velocities [m/s, rad/s].
    StateColumns m_state{9};
};

/// Gear predictor-corrector with 6 values per degree of freedom (gc2d Appendix F, Eq. F.10-F.13):
/// scaled derivatives r_n = dt^n/n! d^n r/dt^n, Pascal-matrix predictor, one force evaluation at
/// the predicted position and velocity, corrector r_n += c_n (dt^2/2 a - r_2) with
/// c = (c0, 251/360, 1, 11/18, 1/6, 1/60), c0 = 3/16 by default (velocity-dependent forces).
class GearPredictorCorrector final : public Integrator {
public:
    explicit GearPredictorCorrector(Real c0) : m_c0(c0) {}
    const char* name() const noexcept override { return "gear"; }
    Real predict(model::ParticleStore& s, Real dt) noexcept override;
    bool correct(model::ParticleStore& s, Real dt, int iteration) noexcept override;
    bool correctsBySlots() const noexcept override { return true; }
    void correctSlots(model::ParticleStore& s, Real dt, std::size_t begin, std::size_t end) noexcept override;
    DriftVelocities driftVelocities() const noexcept override {
        return {m_state[12], m_state[13], m_state[14]};
    }
    StateColumns* state() noexcept override { return &m_state; }
    void permute(const std::vector<std::uint32_t>& order) override { m_state.permute(order); }
    std::size_t memoryBytes() const noexcept override { return m_state.bytes(); }
    void save(std::ostream& os) const override;
    void load(std::istream& is, std::size_t particles) override;
    bool restoreDerivatives(const std::vector<Real>& perSlot) override;
    std::vector<Real> derivatives() const override;

private:
    /// Scaled derivatives r2..r5 of degree of freedom d (0 x, 1 y, 2 phi).
    std::array<Real*, 4> higherDerivatives(int d) noexcept {
        return {m_state[4 * d], m_state[4 * d + 1], m_state[4 * d + 2], m_state[4 * d + 3]};
    }
    Real m_c0;
    bool m_started = false;  ///< r2..r5 initialised from the first forces
    /// r2..r5 for x, y, phi (columns 4 d + k, d = 0..2, k = 0..3, scaled [m] or [rad]), then the
    /// drift velocities of the step (12..14).
    StateColumns m_state{15};
};

std::unique_ptr<Integrator> makeIntegrator(const IntegratorParams& params);
std::vector<std::string> integratorNames();

}  // namespace granulab::dem
