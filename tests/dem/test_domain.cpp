// SPDX-License-Identifier: MIT
// The DEM domain decomposition in one process (docs/physics/dem-mpi.md; the runs on several ranks
// are tests/mpi/parallel_dem_run.sh): the slabs, their balancing by weight, and a DomainWorld on
// one rank, which must follow the ordinary World to round-off even when it migrates every
// particle with its contact history at every tenth step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "../support.hpp"
#include "../support/dem_scenes.hpp"
#include "core/communicator.hpp"
#include "dem/parallel/domain_world.hpp"
#include "dem/parallel/slab_partition.hpp"

using namespace granulab;

namespace {

/// P ranks whose collectives are the identity: as if this process held every rank's data (the
/// sums and extrema of balancedSlabs then see exactly what it passes).
class AllRanksHere final : public Communicator {
public:
    explicit AllRanksHere(int ranks) : m_ranks(ranks) {}
    int rank() const noexcept override { return 0; }
    int size() const noexcept override { return m_ranks; }
    void send(int, int, ByteBuffer) override {}
    ByteBuffer receive(int, int) override { return {}; }
    bool probe(int, int) override { return false; }
    void flushSends() override {}
    void barrier() override {}
    void allMin(std::span<double>) override {}
    void allMax(std::span<double>) override {}
    void allSum(std::span<double>) override {}
    void allSum(std::span<std::uint64_t>) override {}
    std::vector<double> allGather(std::span<const double> mine) override {
        return {mine.begin(), mine.end()};
    }
    std::vector<ByteBuffer> gather(ByteBuffer mine) override { return {std::move(mine)}; }
    ByteBuffer broadcast(ByteBuffer data) override { return data; }
    std::vector<ByteBuffer> allToAll(std::vector<ByteBuffer> outgoing) override { return outgoing; }
    void startMin(std::span<const double>) override {}
    std::vector<double> waitMin() override { return {}; }
    [[noreturn]] void abort(int status) override { std::exit(status); }

private:
    int m_ranks;
};

/// The dense rolling bed of tests/support/dem_scenes.hpp.
const std::string& kBed = test::kRollingDiskBed;

/// Positions and velocities by id.
std::map<ParticleId, std::array<Real, 5>> stateById(const model::ParticleStore& s, std::size_t end) {
    std::map<ParticleId, std::array<Real, 5>> m;
    for (std::size_t k = 0; k < end; ++k) m[s.id[k]] = {s.x[k], s.y[k], s.vx[k], s.vy[k], s.omega[k]};
    return m;
}

}  // namespace

TEST(SlabPartition, OwnersAndGhostRanks) {
    const dem::SlabPartition p = dem::uniformSlabs(0, 0.0, 4.0, 4);  // cuts at 1, 2, 3
    ASSERT_EQ(p.ranks(), 4);
    EXPECT_EQ(p.owner(-5.0), 0);
    EXPECT_EQ(p.owner(0.999), 0);
    EXPECT_EQ(p.owner(1.0), 1);  // a cut belongs to the slab above it
    EXPECT_EQ(p.owner(3.5), 3);
    EXPECT_EQ(p.owner(50.0), 3);
    const auto ghosts = [&](Real c, Real halo) {
        std::vector<int> r;
        p.forGhostRanks(c, halo, p.owner(c), [&](int k) { r.push_back(k); });
        return r;
    };
    EXPECT_EQ(ghosts(1.5, 0.2), std::vector<int>{});
    EXPECT_EQ(ghosts(1.1, 0.2), std::vector<int>{0});
    EXPECT_EQ(ghosts(1.9, 0.2), std::vector<int>{2});
    // A halo wider than a slab reaches past the next one.
    EXPECT_EQ(ghosts(1.5, 1.6), (std::vector<int>{0, 2, 3}));
    EXPECT_EQ(ghosts(-10.0, 0.5), std::vector<int>{});
}

TEST(SlabPartition, BalancedCutsShareTheWorkOfAHeap) {
    // A heap's work: weight 1 - |x| on [-1, 1] (a triangle), sampled densely.
    std::vector<Real> x, w;
    for (int k = 0; k <= 20000; ++k) {
        x.push_back(-1.0 + 2.0 * k / 20000.0);
        w.push_back(1.0 - std::abs(x.back()));
    }
    for (const int ranks : {2, 4, 7}) {
        AllRanksHere comm(ranks);
        const dem::SlabPartition p = dem::balancedSlabs(comm, 0, x, w, -1.0, 1.0);
        ASSERT_EQ(p.ranks(), ranks);
        std::vector<double> share(static_cast<std::size_t>(ranks), 0.0);
        double total = 0;
        for (std::size_t k = 0; k < x.size(); ++k) {
            share[static_cast<std::size_t>(p.owner(x[k]))] += w[k];
            total += w[k];
        }
        // Equal shares to the resolution of the histogram (256 bins per rank, interpolated).
        for (const double s : share) EXPECT_NEAR(s / total, 1.0 / ranks, 2e-3) << ranks << " ranks";
        // Equal widths would give the outer slab of 4 ranks 1/8 of the work instead of 1/4.
        if (ranks == 4) {
            EXPECT_LT(p.cuts[0], -0.25);
        }
    }
    // Without any weight (a pile not yet poured) the slabs are equal over the given extent.
    AllRanksHere comm(4);
    const dem::SlabPartition empty = dem::balancedSlabs(comm, 1, {}, {}, 0.0, 8.0);
    EXPECT_EQ(empty.axis, 1);
    EXPECT_EQ(empty.cuts, (std::vector<Real>{2.0, 4.0, 6.0}));
}

TEST(DomainWorld, OneRankFollowsTheWorldThroughMigrations) {
    // The same bed as an ordinary World and as a DomainWorld on one rank that redistributes every
    // particle (a full exchange: records, history by id, new slots and lists) every tenth step.
    // The slot order differs, so the sums differ by round-off; a contact history lost or flipped
    // at an exchange would move the grains by far more (a tangential spring of 0.1 m).
    dem::World ref = test::makeWorldFromToml(kBed);
    SingleProcessCommunicator comm;
    dem::DomainWorld domain(comm, test::makeWorldFromToml(kBed));
    ASSERT_EQ(domain.local().store().size(), ref.store().size());
    for (int k = 0; k < 800; ++k) {
        ASSERT_EQ(ref.step(), dem::kStepOk);
        ASSERT_EQ(domain.step(), dem::kStepOk);
        if (k % 10 == 9) domain.redistribute();
    }
    ASSERT_GT(ref.forceStats().contacts, 600u) << "a bed with contacts";
    const auto a = stateById(ref.store(), ref.store().size());
    const auto b = stateById(domain.local().store(), domain.local().store().size());
    ASSERT_EQ(a.size(), b.size());
    double worstX = 0, worstV = 0;
    for (const auto& [id, va] : a) {
        const auto& vb = b.at(id);
        worstX = std::max({worstX, std::abs(va[0] - vb[0]), std::abs(va[1] - vb[1])});
        worstV =
            std::max({worstV, std::abs(va[2] - vb[2]), std::abs(va[3] - vb[3]), std::abs(va[4] - vb[4])});
    }
    EXPECT_LT(worstX, 1e-9) << "positions [m], radius 0.5 m";
    EXPECT_LT(worstV, 1e-6) << "velocities [m/s], [rad/s]";
    EXPECT_GE(domain.stats().exchanges, 80u);

    // The gathered copy is the whole state: every particle, the same contacts, energies and
    // wall forces to round-off.
    dem::World copy = test::makeWorldFromToml(kBed);
    domain.gather(copy);
    EXPECT_EQ(copy.store().size(), ref.store().size());
    EXPECT_EQ(copy.stepIndex(), ref.stepIndex());
    EXPECT_EQ(copy.forceStats().contacts, ref.forceStats().contacts);
    EXPECT_EQ(copy.forceStats().wallContacts, ref.forceStats().wallContacts);
    const dem::Energies ea = ref.energies(), eb = copy.energies();
    EXPECT_NEAR(eb.kinetic, ea.kinetic, 1e-9 * std::abs(ea.kinetic));
    EXPECT_NEAR(eb.elastic, ea.elastic, 1e-6 * std::abs(ea.elastic));
    ASSERT_EQ(copy.wallForce().size(), ref.wallForce().size());
    for (std::size_t w = 0; w < ref.wallForce().size(); ++w)
        EXPECT_NEAR(copy.wallForce()[w].y, ref.wallForce()[w].y, 1e-6 * std::abs(ref.wallForce()[w].y));
}
