// SPDX-License-Identifier: MIT
// The edmd gas on several MPI ranks (edmd spec section 3; issue 15): edmd::ParallelEngine behind
// the same interface as app/edmd/serial_gas.hpp, so that EdmdSimulation runs either. Every
// member is collective unless it says otherwise: all ranks call them in the same order, and
// what the run loop branches on (time, statistics, stop reasons) is the same on every rank.
// Outputs read the view, which is filled on the root rank only.
#pragma once
#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "app/edmd/gas_view.hpp"
#include "core/communicator.hpp"
#include "edmd/parallel/parallel_engine.hpp"

namespace granulab::app {

template <int D>
class ParallelGas {
public:
    /// The gas at time 0 under `config` (the elastic pre-run's rules until startRun); every
    /// rank passes the same state.
    ParallelGas(Communicator& comm, const edmd::EngineConfig& config, const edmd::ParallelConfig& parallel,
                const edmd::GasState<D>& state)
        : m_comm(comm),
          m_parallel(parallel),
          m_engine(std::make_unique<edmd::ParallelEngine<D>>(comm, config, parallel, state.x, state.v,
                                                             state.radius, state.mass)) {
        refresh();
    }

    // Not collective: values cached at the end of the last collective call.
    bool root() const noexcept { return m_comm.root(); }
    int ranks() const noexcept { return m_comm.size(); }
    Real time() const noexcept { return m_engine->time(); }
    const edmd::EngineStats& stats() const noexcept { return m_globals.stats; }
    std::uint32_t size() const noexcept { return m_engine->particles(); }
    std::size_t memoryBytes() const noexcept { return m_memory; }  ///< all ranks together
    std::array<int, 3> cellsPerAxis() const noexcept { return m_engine->cellsPerAxis(); }
    Real collisionalVirial() const noexcept { return m_globals.virial; }
    Real dissipatedEnergy() const noexcept { return m_globals.dissipated; }
    bool interrupted() const noexcept { return m_engine->interrupted(); }
    edmd::Stall stalled() const noexcept { return m_engine->stalled(); }
    std::uint64_t watchdogWindow() const noexcept { return 16 * std::uint64_t{size()} + (1u << 17); }

    void runUntil(Real tEnd) {
        m_engine->runUntil(tEnd);
        refresh();
    }
    void runCollisions(std::uint64_t collisions, Real tEnd = edmd::kNoEvent) {
        m_engine->runCollisions(collisions, tEnd);
        refresh();
    }

    /// The end of the elastic pre-run (edmd spec 4.2 step 4), as the serial engine's
    /// restartClock: every particle at the current time becomes the state at time 0 (counters
    /// and TC clocks cleared, statistics zero) under the run's rules.
    void startRun(const edmd::EngineConfig& config) {
        if (config.growthRate != 0) throw std::invalid_argument("growing spheres run on one rank only");
        std::vector<edmd::ParticleRecord> all = broadcastRecords(m_engine->gatherNow());
        for (auto& r : all) {
            r.tst = 0;
            r.counter = 0;
            r.lastCollision = -edmd::kNoEvent;
            r.eventKind = 4;  // predicted at time 0; its cell is found from its position
        }
        edmd::EngineGlobals g;
        g.restitution = config.restitution;
        g.wallRestitution = config.wallRestitution;
        g.tc = config.tc;
        m_engine = std::make_unique<edmd::ParallelEngine<D>>(m_comm, config, m_parallel, g, std::move(all));
        m_view = {};
        refresh();
    }

    /// The particles now, on the root (gathered when the engine has moved on).
    const GasView<D>& view() {
        if (m_view.time == time() && m_view.events == stats().events) return m_view;
        const std::vector<edmd::ParticleRecord> all = m_engine->gatherNow();
        m_view.resize(static_cast<std::uint32_t>(all.size()));
        for (std::uint32_t i = 0; i < all.size(); ++i) m_view.setFromRecord(i, all[i], 0, time());
        m_view.time = time();
        m_view.events = stats().events;
        return m_view;
    }

    /// The root writes the whole state; `out` is not written on the other ranks.
    void saveState(std::ostream& out) {
        GasCheckpoint state;
        state.globals = m_engine->gatherState(state.records);
        state.cells = cellsPerAxis();
        if (root()) writeGasCheckpoint(out, D, state);
    }
    /// Every rank reads the checkpoint (written on any number of ranks). A checkpoint of a run
    /// on another cell grid (another edmd.cell_grid) continues on this engine's grid:
    /// every particle flown to the checkpoint's time and predicted afresh there (the same
    /// physics; not the same bits as a continuation on the old grid, whose cell crossings round
    /// positions elsewhere).
    void loadState(std::istream& in, const edmd::EngineConfig& config) {
        GasCheckpoint state = readGasCheckpoint(in, D);
        if (edmd::ParallelEngine<D>::gridFor(config, state.records) != state.cells)
            for (auto& r : state.records) {
                edmd::flyRecordTo<D>(r, state.globals.now, config);
                r.eventKind = 4;  // predicted now; the cell is found from the position
            }
        m_engine = std::make_unique<edmd::ParallelEngine<D>>(m_comm, config, m_parallel, state.globals,
                                                             std::move(state.records));
        m_view = {};
        refresh();
    }

    /// Per-rank figures (edmd spec 7 item 46) for summary.json, on the root (null elsewhere).
    nlohmann::json rankKeys(double engineSeconds) const {
        const auto& p = m_engine->parallelStats();
        const auto& local = m_engine->localStats();
        const std::array<double, 16> mine{static_cast<double>(local.events),
                                          static_cast<double>(local.collisions),
                                          static_cast<double>(m_engine->ownedCount()),
                                          static_cast<double>(p.sections),
                                          static_cast<double>(p.rollbacks),
                                          static_cast<double>(p.carefulSections),
                                          static_cast<double>(p.steps),
                                          static_cast<double>(p.recordsSent),
                                          static_cast<double>(p.bytesSent),
                                          static_cast<double>(p.eventsUndone),
                                          p.computeSeconds,
                                          p.communicationSeconds,
                                          p.rebuildSeconds,
                                          static_cast<double>(m_engine->memoryBytes()),
                                          static_cast<double>(p.lateRecords),
                                          static_cast<double>(p.slotsReclaimed)};
        const std::vector<double> all = m_comm.allGather(mine);
        if (!root()) return nullptr;
        nlohmann::json ranks = nlohmann::json::array();
        for (int r = 0; r < m_comm.size(); ++r) {
            const double* f = all.data() + static_cast<std::size_t>(r) * mine.size();
            const double events = f[0], rollbacks = f[4], steps = f[6], owned = f[2];
            ranks.push_back({{"rank", r},
                             {"events", f[0]},
                             {"collisions", f[1]},
                             {"particles", owned},
                             {"sections", f[3]},
                             {"rollbacks", rollbacks},
                             {"careful_sections", f[5]},
                             {"communication_steps", steps},
                             {"records_sent", f[7]},
                             {"bytes_sent", f[8]},
                             {"events_undone", f[9]},
                             {"late_records_applied", f[14]},
                             {"slots_reclaimed", f[15]},
                             {"events_between_errors", rollbacks > 0 ? events / rollbacks : events},
                             {"events_between_communications", steps > 0 ? events / steps : events},
                             {"compute_s", f[10]},
                             {"communication_s", f[11]},
                             {"rebuild_s", f[12]},
                             {"communication_share", engineSeconds > 0 ? f[11] / engineSeconds : 0.0},
                             {"memory_bytes", f[13]},
                             {"bytes_per_particle", owned > 0 ? f[13] / owned : 0.0}});
        }
        return {{"ranks", m_comm.size()},
                {"sync_interval_s", m_engine->syncInterval()},
                {"balance_moves", m_engine->parallelStats().balanceMoves},
                {"per_rank", ranks}};
    }

private:
    /// The root's records on every rank.
    std::vector<edmd::ParticleRecord> broadcastRecords(const std::vector<edmd::ParticleRecord>& records) {
        std::vector<edmd::ParticleRecord> all;
        unpackPod(m_comm.broadcast(packPod(std::span<const edmd::ParticleRecord>(records))), all);
        return all;
    }
    /// The summed globals and memory of all ranks (after every collective call).
    void refresh() {
        m_globals = m_engine->globals();
        std::array<double, 1> memory{static_cast<double>(m_engine->memoryBytes())};
        m_comm.allSum(memory);
        m_memory = static_cast<std::size_t>(memory[0]);
    }

    Communicator& m_comm;
    edmd::ParallelConfig m_parallel;
    std::unique_ptr<edmd::ParallelEngine<D>> m_engine;
    edmd::EngineGlobals m_globals;
    std::size_t m_memory = 0;
    GasView<D> m_view;
};

}  // namespace granulab::app
