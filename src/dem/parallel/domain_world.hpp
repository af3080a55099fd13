// SPDX-License-Identifier: MIT
// The DEM step on several MPI ranks by domain decomposition (issue 16; docs/physics/dem-mpi.md).
// Each rank runs an ordinary World that holds the particles of its slab (owned, first) and copies
// of the particles within one halo of it (ghosts, after them). Per step: the World's first part
// (predict, walls), the halo update (owners send their ghosts' positions, velocities, angles and
// integrator state), one reduction that decides whether any rank's skin is used up, then the
// exchange when it is (particles migrate to their slab's owner with their contact history,
// ghosts are chosen anew, the slabs rebalanced by contacts), then the forces and the corrector,
// and one sum of the wall forces. A pair of an owned and a ghost particle is evaluated on both
// ranks; each keeps the force on its own particle. Messages go through core's Communicator only.
// Results: the same for a given rank count, bit for bit; across rank counts they agree to
// round-off (each rank adds a particle's contact forces in its own list order).
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/communicator.hpp"
#include "dem/parallel/slab_partition.hpp"
#include "dem/world.hpp"

namespace granulab::dem {

struct DomainConfig {
    /// Move the cuts at an exchange when the busiest rank has more than `balanceTrigger` times
    /// the mean work (work: particles plus contact candidates).
    bool balance = true;
    Real balanceTrigger = 1.05;
};

/// Counters of the decomposition (summary.json "domains").
struct DomainStats {
    std::uint64_t exchanges = 0;   ///< migrations and ghost rebuilds
    std::uint64_t rebalances = 0;  ///< exchanges that moved the cuts
    std::uint64_t owned = 0;       ///< this rank's particles now
    std::uint64_t ghosts = 0;      ///< this rank's ghosts now
    double imbalance = 1;          ///< busiest rank's work / mean work after the last exchange
    double imbalanceSum = 0;       ///< sum over exchanges (mean: / exchanges)
    double haloShare = 0;          ///< all ghosts / all particles after the last exchange
    double haloSeconds = 0;        ///< [s] this rank's halo updates
    double exchangeSeconds = 0;    ///< [s] this rank's exchanges (rebuilds included)
    double reduceSeconds = 0;      ///< [s] this rank's per-step reductions (waiting for the others)
};

class DomainWorld : private World::IterationLink {
public:
    /// `whole`: the scene's world with every particle, initialised or loaded (the same on every
    /// rank); it becomes this rank's part. Collective.
    /// `cuts`: the partition to start from (a checkpoint of the same rank count); otherwise the
    /// cuts are balanced (or uniform) from the particles.
    DomainWorld(Communicator& comm, World whole, DomainConfig config = {},
                const SlabPartition* cuts = nullptr);

    /// One step on every rank; the StepStatus flags of all ranks together. `stop`: this rank
    /// was asked to stop (a signal); stopRequested() then tells every rank after this step.
    /// Collective.
    std::uint32_t step(bool stop = false);
    bool stopRequested() const noexcept { return m_stopRequested; }
    /// A deep overlap of the last step is reported with the next step's reduction; at the end
    /// of an advance this reduction reports it (collective): kStepDeepOverlap or kStepOk.
    std::uint32_t settle();

    const World& local() const noexcept { return m_world; }
    std::int64_t stepIndex() const noexcept { return m_world.stepIndex(); }
    Real time() const noexcept { return m_world.time(); }
    /// All ranks' particles (after the last exchange: sources and outlets change it).
    std::size_t particles() const noexcept { return m_particles; }
    const SlabPartition& partition() const noexcept { return m_partition; }
    const DomainStats& stats() const noexcept { return m_stats; }
    /// An exchange now, with the cuts kept (collective): the local worlds become what a
    /// DomainWorld made from the gathered state and partition() builds, so that a run resumed
    /// from a checkpoint written here continues bit for bit on the same rank count.
    void redistribute() { exchange(false); }
    /// Every rank's engine memory [bytes] (collective).
    std::size_t memoryBytes();

    /// Fills `copy` on the root with every particle, its integrator state and contact history,
    /// the clock and walls of this run, and evaluates its forces for outputs (statistics,
    /// contact log; World::evaluateForOutput). `copy` is a World of the same scene. Collective;
    /// `copy` is untouched elsewhere.
    void gather(World& copy);

private:
    struct Incoming;
    /// Migration, ghosts and the new lists (collective).
    void exchange(bool mayBalance = true);
    /// The particles of this rank's outlets and of every source and inlet: what leaves is not
    /// sent on, what enters is created by its owner; then an exchange (collective).
    void exchangeWithFlow(const std::vector<std::uint32_t>& leaving, const std::vector<NewParticle>& entering,
                          ParticleId firstId, bool mayBalance = true);
    /// Sources and inlets place grains against every rank's particles: the owned ones of all
    /// ranks, in id order (positions, velocities and radii; collective).
    model::ParticleStore everyParticle();
    /// Builds this rank's World from what it received (owned and ghost records, history).
    void assemble(Incoming in, bool countAsBuild);
    /// Owners send their ghosts' state; ghosts take it.
    void updateHalo();
    /// An iterating integrator goes on until every rank accepts; the ghosts follow each iteration.
    bool agree(bool acceptedHere) override;
    /// [m] the ghost layer: every partner a contact candidate can have, and every particle within
    /// the attraction cutoff (particles move at most skin/2 between exchanges).
    Real haloWidth() const noexcept {
        const auto& c = m_world.config();
        const Real attraction = c.attraction ? c.attraction->cutoff + c.skin : 0;
        return std::max(2 * m_world.maxRadius() + c.skin, attraction);
    }
    /// Contact candidates per owned slot, plus one (the work weight of balancing).
    std::vector<Real> workWeights() const;
    /// After an exchange: the busiest rank's work / mean work, all particles and the halo share
    /// (collective, one all-gather).
    void measureDomains();

    Communicator& m_comm;
    World m_world;
    DomainConfig m_config;
    SlabPartition m_partition;
    std::size_t m_particles = 0;
    std::size_t m_owned = 0;
    std::size_t m_integratorColumns = 0;
    /// Owned slots whose state rank r keeps as ghosts, in id order (the order of r's ghosts).
    std::vector<std::vector<std::uint32_t>> m_sendSlots;
    /// Ghost slots owned by rank r: [m_ghostBegin[r], m_ghostBegin[r + 1]).
    std::vector<std::uint32_t> m_ghostBegin;
    /// workWeights() of the lists of the last exchange (measureDomains), for the next one.
    std::vector<Real> m_weights;
    DomainStats m_stats;
    bool m_stopRequested = false;
    bool m_deepOverlap = false;        ///< this rank's last step reached a deep overlap
    bool m_sumWallsEveryStep = false;  ///< a piston needs the total wall force at every step
    bool m_anyLeft = false;
    bool m_stepped = false;  ///< a step since the decomposition (the fluid statistics are this rank's)
    static constexpr int kHaloTag = 0x4841;
};

}  // namespace granulab::dem
