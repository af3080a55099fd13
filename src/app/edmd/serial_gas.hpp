// SPDX-License-Identifier: MIT
// The edmd gas on one process (edmd spec section 2): the serial engine edmd::Engine<D, Queue>
// behind the interface that EdmdSimulation drives (app/edmd/edmd_simulation.cpp); its MPI twin
// is app/edmd/parallel_gas.hpp. Checkpoints are records (app/edmd/gas_view.hpp), so a serial
// run resumes a parallel run's checkpoint and the other way round.
#pragma once
#include <memory>
#include <nlohmann/json.hpp>
#include <utility>

#include "app/edmd/gas_view.hpp"
#include "edmd/engine.hpp"
#include "edmd/initial_state.hpp"

namespace granulab::app {

template <int D, class Queue>
class SerialGas {
public:
    using EngineType = edmd::Engine<D, Queue>;

    /// The gas at time 0 under `config` (the elastic pre-run's rules until startRun).
    SerialGas(const edmd::EngineConfig& config, edmd::GasState<D> state)
        : m_engine(std::make_unique<EngineType>(config, std::move(state.x), std::move(state.v),
                                                std::move(state.radius), std::move(state.mass))) {}

    bool root() const noexcept { return true; }
    int ranks() const noexcept { return 1; }
    Real time() const noexcept { return m_engine->time(); }
    const edmd::EngineStats& stats() const noexcept { return m_engine->stats(); }
    std::uint32_t size() const noexcept { return m_engine->size(); }
    std::size_t memoryBytes() const noexcept { return m_engine->memoryBytes(); }
    std::array<int, 3> cellsPerAxis() const noexcept { return m_engine->cellsPerAxis(); }
    Real collisionalVirial() const noexcept { return m_engine->collisionalVirial(); }
    Real dissipatedEnergy() const noexcept { return m_engine->dissipatedEnergy(); }

    void runUntil(Real tEnd) { m_engine->runUntil(tEnd); }
    void runCollisions(std::uint64_t collisions, Real tEnd = edmd::kNoEvent) {
        m_engine->runCollisions(collisions, tEnd);
    }
    bool interrupted() const noexcept { return m_engine->interrupted(); }
    edmd::Stall stalled() const noexcept { return m_engine->stalled(); }
    std::uint64_t watchdogWindow() const noexcept { return m_engine->watchdogWindow(); }

    /// The end of the elastic pre-run (edmd spec 4.2 step 4): time 0, counters cleared, the
    /// run's collision rules and growth from now on.
    void startRun(const edmd::EngineConfig& config) {
        m_engine->restartClock();
        m_engine->setGrowthRate(config.growthRate);
        m_engine->setCollisionRules(config.restitution, config.wallRestitution, config.tc);
        m_view = {};
    }

    /// The particles now (refreshed when the engine has moved on).
    const GasView<D>& view() {
        const auto& st = m_engine->stats();
        if (m_view.time == m_engine->time() && m_view.events == st.events) return m_view;
        const std::uint32_t n = m_engine->size();
        m_view.resize(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            m_view.x[i] = m_engine->positionNow(i);
            m_view.v[i] = m_engine->velocityNow(i);
            m_view.omega[i] = m_engine->omega(i);
            m_view.radius[i] = m_engine->radius(i);
            m_view.mass[i] = m_engine->mass(i);
            m_view.collisions[i] = static_cast<std::uint32_t>(m_engine->collisions(i));
        }
        m_view.time = m_engine->time();
        m_view.events = st.events;
        return m_view;
    }

    void saveState(std::ostream& out) const {
        writeGasCheckpoint(out, D, {m_engine->globals(), m_engine->cellsPerAxis(), m_engine->records(false)});
    }
    /// Continues event for event from a checkpoint written on any number of ranks.
    void loadState(std::istream& in, const edmd::EngineConfig& config) {
        GasCheckpoint state = readGasCheckpoint(in, D);
        m_engine = std::make_unique<EngineType>(config, edmd::DomainLayout::serial(state.cells),
                                                state.globals, std::move(state.records));
        m_view = {};
    }

    /// Per-rank figures of a parallel run; none here.
    nlohmann::json rankKeys(double engineSeconds) const {
        (void)engineSeconds;
        return nullptr;
    }

private:
    std::unique_ptr<EngineType> m_engine;
    GasView<D> m_view;
};

}  // namespace granulab::app
