// SPDX-License-Identifier: MIT
// mpi/mpi_communicator: every method of MpiCommunicator for P ranks (CTest runs P = 2 and 3; run
// alone the binary is rank 0 of 1 and every test still holds). Each test's checks come after all
// of its communication, so a failing rank does not leave the others waiting; the fixture tells
// rank 0 which other ranks failed.
#include <gtest/gtest.h>
#include <mpi.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/communicator.hpp"
#include "mpi/mpi_communicator.hpp"

using namespace granulab;

namespace {

/// n bytes that depend on the sender and a salt (message number, tag, destination).
ByteBuffer pattern(std::size_t n, int from, int salt) {
    ByteBuffer b(n);
    for (std::size_t i = 0; i < n; ++i) {
        b[i] = static_cast<std::byte>(
            (i * 131 + static_cast<std::size_t>(from) * 17 + static_cast<std::size_t>(salt) * 7) & 0xff);
    }
    return b;
}

/// Polls `condition` for up to 30 s.
template <class Condition>
bool eventually(Condition condition) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (std::chrono::steady_clock::now() < deadline) {
        if (condition()) return true;
    }
    return false;
}

class Mpi : public testing::Test {
protected:
    Communicator& comm = worldCommunicator();
    int rank = comm.rank();
    int size = comm.size();
    int right = (rank + 1) % size;
    int left = (rank + size - 1) % size;

    void TearDown() override {
        // No message of this test is left over (every test receives what it sends).
        // No early return before the collective below: the other ranks would wait for ever.
        comm.flushSends();
        if (auto* mpiComm = dynamic_cast<mpi::MpiCommunicator*>(&comm)) {
            int leftover = 0;
            MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, mpiComm->handle(), &leftover, MPI_STATUS_IGNORE);
            EXPECT_FALSE(leftover) << "a message of this test was not received on rank " << rank;
        } else {
            ADD_FAILURE() << "the world communicator is not an MpiCommunicator";
        }
        // Rank 0 reports the other ranks' failures (their own output is only their assertions).
        int mine = HasFailure() ? 1 : 0;
        std::vector<int> failed(static_cast<std::size_t>(size));
        MPI_Allgather(&mine, 1, MPI_INT, failed.data(), 1, MPI_INT, MPI_COMM_WORLD);
        if (rank != 0) return;
        for (int r = 1; r < size; ++r) {
            if (failed[static_cast<std::size_t>(r)])
                ADD_FAILURE() << "failed on rank " << r << " (its stderr)";
        }
    }
};

}  // namespace

TEST_F(Mpi, WorldIsAnMpiCommunicatorOverADuplicateOfTheWorld) {
    auto* mpiComm = dynamic_cast<mpi::MpiCommunicator*>(&comm);
    ASSERT_NE(mpiComm, nullptr);
    int worldRank = -1;
    int worldSize = -1;
    MPI_Comm_rank(MPI_COMM_WORLD, &worldRank);
    MPI_Comm_size(MPI_COMM_WORLD, &worldSize);
    EXPECT_EQ(rank, worldRank);
    EXPECT_EQ(size, worldSize);
    EXPECT_EQ(comm.root(), worldRank == 0);
    int comparison = MPI_UNEQUAL;
    MPI_Comm_compare(mpiComm->handle(), MPI_COMM_WORLD, &comparison);
    EXPECT_EQ(comparison, MPI_CONGRUENT);  // same group and order, another context
    EXPECT_TRUE(mpi::MpiEnvironment::launchedByMpirun() || size == 1);
}

TEST_F(Mpi, RingOfEmptyOneByteAndOneMegabyteMessages) {
    // All sends first, then the receives: blocking sends of 1 MB would deadlock in a ring.
    const std::vector<std::size_t> sizes{0, 1, std::size_t{1} << 20};
    for (std::size_t k = 0; k < sizes.size(); ++k)
        comm.send(right, 100 + static_cast<int>(k), pattern(sizes[k], rank, 0));
    std::vector<ByteBuffer> received;
    for (std::size_t k = 0; k < sizes.size(); ++k)
        received.push_back(comm.receive(left, 100 + static_cast<int>(k)));
    comm.flushSends();
    EXPECT_EQ(static_cast<mpi::MpiCommunicator&>(comm).pendingSends(), 0u);
    for (std::size_t k = 0; k < sizes.size(); ++k) {
        ASSERT_EQ(received[k].size(), sizes[k]) << "message " << k;
        EXPECT_TRUE(received[k] == pattern(sizes[k], left, 0)) << "message " << k;
    }
}

TEST_F(Mpi, ProbeIsFalseBeforeAndTrueAfterArrival) {
    const bool before = comm.probe(left, 200) || comm.probe(left, 201);
    comm.barrier();  // nobody sends before every rank has probed
    comm.send(right, 200, pattern(64, rank, 1));
    comm.send(right, 201, pattern(std::size_t{1} << 20, rank, 2));
    const bool arrived = eventually([&] { return comm.probe(left, 200) && comm.probe(left, 201); });
    const ByteBuffer small = arrived ? comm.receive(left, 200) : ByteBuffer{};
    const bool smallGone = !comm.probe(left, 200);
    const ByteBuffer large = arrived ? comm.receive(left, 201) : ByteBuffer{};
    const bool largeGone = !comm.probe(left, 201);
    EXPECT_FALSE(before);
    ASSERT_TRUE(arrived) << "probe never saw the messages of rank " << left;
    EXPECT_TRUE(small == pattern(64, left, 1));
    EXPECT_TRUE(large == pattern(std::size_t{1} << 20, left, 2));
    EXPECT_TRUE(smallGone);
    EXPECT_TRUE(largeGone);
}

TEST_F(Mpi, SeveralMessagesWithOneTagArriveInOrder) {
    // Sizes on both sides of the eager/rendezvous switch: MPI's order holds across protocols.
    const std::vector<std::size_t> sizes{5, 0, 300000, 17, 1, 70000, 0, 3};
    for (std::size_t k = 0; k < sizes.size(); ++k)
        comm.send(right, 300, pattern(sizes[k], rank, static_cast<int>(k)));
    std::vector<ByteBuffer> received;
    for (std::size_t k = 0; k < sizes.size(); ++k) received.push_back(comm.receive(left, 300));
    for (std::size_t k = 0; k < sizes.size(); ++k) {
        EXPECT_TRUE(received[k] == pattern(sizes[k], left, static_cast<int>(k))) << "message " << k;
    }
}

TEST_F(Mpi, MessagesWithDifferentTagsAreReceivedOutOfOrder) {
    comm.send(right, 401, pattern(10, rank, 401));
    comm.send(right, 402, pattern(300000, rank, 402));
    comm.send(right, 403, pattern(0, rank, 403));
    const ByteBuffer third = comm.receive(left, 403);
    const ByteBuffer first = comm.receive(left, 401);
    const ByteBuffer second = comm.receive(left, 402);
    EXPECT_TRUE(first == pattern(10, left, 401));
    EXPECT_TRUE(second == pattern(300000, left, 402));
    EXPECT_TRUE(third.empty());
}

TEST_F(Mpi, SendToSelf) {
    comm.send(rank, 501, pattern(3, rank, 501));
    comm.send(rank, 502, pattern(std::size_t{1} << 20, rank, 502));
    const bool seen = eventually([&] { return comm.probe(rank, 501) && comm.probe(rank, 502); });
    const ByteBuffer second = comm.receive(rank, 502);
    const ByteBuffer first = comm.receive(rank, 501);
    const bool gone = !comm.probe(rank, 501) && !comm.probe(rank, 502);
    EXPECT_TRUE(seen);
    EXPECT_TRUE(first == pattern(3, rank, 501));
    EXPECT_TRUE(second == pattern(std::size_t{1} << 20, rank, 502));
    EXPECT_TRUE(gone);
}

TEST_F(Mpi, CompletedSendsAreReleasedWithoutFlush) {
    auto& mpiComm = static_cast<mpi::MpiCommunicator&>(comm);
    for (int k = 0; k < 10; ++k) comm.send(right, 550, pattern(100, rank, k));
    for (int k = 0; k < 10; ++k) comm.receive(left, 550);
    comm.barrier();  // every message has been received: every send can complete
    const bool released = eventually([&] {
        comm.probe(left, 551);  // any call releases what has completed
        return mpiComm.pendingSends() == 0;
    });
    EXPECT_TRUE(released) << mpiComm.pendingSends() << " sends still pending";
}

TEST_F(Mpi, ReductionsOfDoubles) {
    const auto r = static_cast<double>(rank);
    const auto p = static_cast<double>(size);
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<double> mine{r + 1.0, -0.5 * r, rank == size - 1 ? -1e300 : 7.0, rank == 0 ? inf : 2.0};
    std::vector<double> lo = mine, hi = mine, sum = mine;
    comm.allMin(lo);
    comm.allMax(hi);
    comm.allSum(sum);
    std::vector<double> empty;
    comm.allSum(empty);
    EXPECT_EQ(lo, (std::vector<double>{1.0, -0.5 * (p - 1.0), -1e300, size == 1 ? inf : 2.0}));
    EXPECT_EQ(hi, (std::vector<double>{p, 0.0, size == 1 ? -1e300 : 7.0, inf}));
    // Sums of small integers and halves are exact in any order.
    EXPECT_EQ(sum[0], p * (p + 1.0) / 2.0);
    EXPECT_EQ(sum[1], -0.25 * p * (p - 1.0));
    EXPECT_EQ(sum[3], inf);
    EXPECT_TRUE(empty.empty());
}

TEST_F(Mpi, SumOfUnsigned64) {
    const auto r = static_cast<std::uint64_t>(rank);
    const auto p = static_cast<std::uint64_t>(size);
    std::vector<std::uint64_t> values{r + 1, (std::uint64_t{1} << 40) * (r + 1),
                                      rank == 0 ? std::uint64_t{1} << 62 : 1};
    comm.allSum(values);
    EXPECT_EQ(values[0], p * (p + 1) / 2);
    EXPECT_EQ(values[1], (std::uint64_t{1} << 40) * (p * (p + 1) / 2));
    EXPECT_EQ(values[2], (std::uint64_t{1} << 62) + p - 1);
}

TEST_F(Mpi, AllGatherConcatenatesInRankOrder) {
    const auto r = static_cast<double>(rank);
    const std::vector<double> all = comm.allGather(std::vector<double>{r, r + 0.25, -r});
    const std::vector<double> none = comm.allGather(std::vector<double>{});
    ASSERT_EQ(all.size(), 3u * static_cast<std::size_t>(size));
    for (int s = 0; s < size; ++s) {
        const auto k = 3 * static_cast<std::size_t>(s);
        EXPECT_EQ(all[k], s);
        EXPECT_EQ(all[k + 1], s + 0.25);
        EXPECT_EQ(all[k + 2], -s);
    }
    EXPECT_TRUE(none.empty());
}

TEST_F(Mpi, GatherOfVaryingSizesIncludingEmpty) {
    const auto sizeOf = [](int r) {
        return r == 0 ? std::size_t{0} : r == 1 ? std::size_t{1} : 70000 * static_cast<std::size_t>(r);
    };
    const std::vector<ByteBuffer> gathered = comm.gather(pattern(sizeOf(rank), rank, 600));
    const std::vector<ByteBuffer> empties = comm.gather(ByteBuffer{});
    if (rank != 0) {
        EXPECT_TRUE(gathered.empty());
        EXPECT_TRUE(empties.empty());
        return;
    }
    ASSERT_EQ(gathered.size(), static_cast<std::size_t>(size));
    ASSERT_EQ(empties.size(), static_cast<std::size_t>(size));
    for (int s = 0; s < size; ++s) {
        EXPECT_TRUE(gathered[static_cast<std::size_t>(s)] == pattern(sizeOf(s), s, 600)) << "from rank " << s;
        EXPECT_TRUE(empties[static_cast<std::size_t>(s)].empty());
    }
}

TEST_F(Mpi, BroadcastOfTheRootsData) {
    // The argument of the other ranks is ignored, whatever its size.
    const ByteBuffer big = comm.broadcast(rank == 0 ? pattern(100000, 0, 700) : pattern(5, rank, 701));
    const ByteBuffer empty = comm.broadcast(rank == 0 ? ByteBuffer{} : pattern(9, rank, 702));
    EXPECT_TRUE(big == pattern(100000, 0, 700));
    EXPECT_TRUE(empty.empty());
}

TEST_F(Mpi, AllToAllOfVaryingSizesIncludingEmpty) {
    // From s to d: ((s + 2 d) mod 3) * 40001 bytes; some pairs (self included for P = 2, 3) send nothing.
    const auto bytesFrom = [](int s, int d) { return static_cast<std::size_t>((s + 2 * d) % 3) * 40001; };
    std::vector<ByteBuffer> outgoing;
    for (int d = 0; d < size; ++d) outgoing.push_back(pattern(bytesFrom(rank, d), rank, d));
    const std::vector<ByteBuffer> incoming = comm.allToAll(std::move(outgoing));
    const std::vector<ByteBuffer> nothing =
        comm.allToAll(std::vector<ByteBuffer>(static_cast<std::size_t>(size)));
    EXPECT_THROW(comm.allToAll(std::vector<ByteBuffer>(static_cast<std::size_t>(size) + 1)),
                 std::invalid_argument);
    ASSERT_EQ(incoming.size(), static_cast<std::size_t>(size));
    for (int s = 0; s < size; ++s) {
        EXPECT_TRUE(incoming[static_cast<std::size_t>(s)] == pattern(bytesFrom(s, rank), s, rank))
            << "from rank " << s;
    }
    ASSERT_EQ(nothing.size(), static_cast<std::size_t>(size));
    for (const ByteBuffer& b : nothing) EXPECT_TRUE(b.empty());
}

TEST_F(Mpi, StartMinOverlapsASendAndReceive) {
    const auto r = static_cast<double>(rank);
    const auto p = static_cast<double>(size);
    comm.startMin(std::vector<double>{r + 1.0, 10.0 - r, rank == size - 1 ? -3.0 : 0.0});
    EXPECT_THROW(comm.startMin(std::vector<double>{1.0}), std::logic_error);  // one in flight at a time
    comm.send(right, 800, pattern(std::size_t{1} << 20, rank, 800));
    const ByteBuffer received = comm.receive(left, 800);
    const std::vector<double> minima = comm.waitMin();
    EXPECT_THROW(comm.waitMin(), std::logic_error);  // nothing in flight
    // A second round reuses the state.
    comm.startMin(std::vector<double>{-r});
    comm.barrier();
    const std::vector<double> second = comm.waitMin();
    EXPECT_TRUE(received == pattern(std::size_t{1} << 20, left, 800));
    EXPECT_EQ(minima, (std::vector<double>{1.0, 11.0 - p, -3.0}));
    EXPECT_EQ(second, std::vector<double>{-(p - 1.0)});
}

TEST_F(Mpi, BarrierWaitsForTheLastRank) {
    comm.barrier();
    const auto start = std::chrono::steady_clock::now();
    if (rank == 0) std::this_thread::sleep_for(std::chrono::milliseconds(500));
    comm.barrier();
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Rank 0 entered 0.5 s after leaving the first barrier; the others left it at most a little
    // later than rank 0 did (margin for an oversubscribed machine).
    EXPECT_GT(waited, 0.25) << "rank " << rank;
}
