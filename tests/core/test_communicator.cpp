// SPDX-License-Identifier: MIT
// core/communicator: SingleProcessCommunicator (rank 0 of 1: self messages queued in order per
// tag, every collective the identity) and the world communicator. The MPI implementation is
// tested under mpirun by tests/mpi/ (granulab_mpi_tests, CTest MpiCommunicator.np2/np3).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <stdexcept>
#include <vector>

#include "core/communicator.hpp"

using namespace granulab;

namespace {

ByteBuffer bytes(std::initializer_list<int> values) {
    ByteBuffer b;
    for (const int v : values) b.push_back(static_cast<std::byte>(v));
    return b;
}

}  // namespace

TEST(SingleProcessCommunicator, IsRankZeroOfOne) {
    SingleProcessCommunicator comm;
    EXPECT_EQ(comm.rank(), 0);
    EXPECT_EQ(comm.size(), 1);
    EXPECT_TRUE(comm.root());
}

TEST(SingleProcessCommunicator, SelfMessagesAreReceivedInOrderPerTag) {
    SingleProcessCommunicator comm;
    EXPECT_FALSE(comm.probe(0, 7));
    comm.send(0, 7, bytes({1}));
    comm.send(0, 9, bytes({10}));
    comm.send(0, 7, bytes({2, 2}));
    comm.send(0, 7, ByteBuffer{});
    comm.send(0, 9, bytes({20}));
    EXPECT_TRUE(comm.probe(0, 7));
    EXPECT_TRUE(comm.probe(0, 9));
    EXPECT_FALSE(comm.probe(0, 8));
    // Tag 9 first: the other tag's messages wait.
    EXPECT_EQ(comm.receive(0, 9), bytes({10}));
    EXPECT_EQ(comm.receive(0, 7), bytes({1}));
    EXPECT_EQ(comm.receive(0, 7), bytes({2, 2}));
    EXPECT_EQ(comm.receive(0, 9), bytes({20}));
    EXPECT_FALSE(comm.probe(0, 9));
    EXPECT_TRUE(comm.probe(0, 7));
    EXPECT_TRUE(comm.receive(0, 7).empty());
    EXPECT_FALSE(comm.probe(0, 7));
    comm.flushSends();
}

TEST(SingleProcessCommunicator, ReceiveWithNothingQueuedThrows) {
    SingleProcessCommunicator comm;
    EXPECT_THROW(comm.receive(0, 3), std::logic_error);
    comm.send(0, 4, bytes({1}));
    EXPECT_THROW(comm.receive(0, 3), std::logic_error);  // another tag does not match
    EXPECT_EQ(comm.receive(0, 4), bytes({1}));
    EXPECT_THROW(comm.receive(0, 4), std::logic_error);
}

TEST(SingleProcessCommunicator, OtherRanksDoNotExist) {
    SingleProcessCommunicator comm;
    EXPECT_THROW(comm.send(1, 0, bytes({1})), std::logic_error);
    EXPECT_THROW(comm.receive(1, 0), std::logic_error);
    EXPECT_THROW(comm.probe(-1, 0), std::logic_error);
}

TEST(SingleProcessCommunicator, CollectivesAreTheIdentity) {
    SingleProcessCommunicator comm;
    comm.barrier();
    std::vector<double> v{3.5, -1.0, 0.0};
    comm.allMin(v);
    EXPECT_EQ(v, (std::vector<double>{3.5, -1.0, 0.0}));
    comm.allMax(v);
    EXPECT_EQ(v, (std::vector<double>{3.5, -1.0, 0.0}));
    comm.allSum(v);
    EXPECT_EQ(v, (std::vector<double>{3.5, -1.0, 0.0}));
    std::vector<std::uint64_t> u{0, 1, std::uint64_t{1} << 63};
    comm.allSum(u);
    EXPECT_EQ(u, (std::vector<std::uint64_t>{0, 1, std::uint64_t{1} << 63}));
    EXPECT_EQ(comm.allGather(v), v);
    EXPECT_TRUE(comm.allGather(std::vector<double>{}).empty());
    EXPECT_EQ(comm.broadcast(bytes({5, 6})), bytes({5, 6}));
    EXPECT_TRUE(comm.broadcast({}).empty());
}

TEST(SingleProcessCommunicator, GatherAndAllToAllReturnOneEntry) {
    SingleProcessCommunicator comm;
    const auto gathered = comm.gather(bytes({1, 2, 3}));
    ASSERT_EQ(gathered.size(), 1u);
    EXPECT_EQ(gathered[0], bytes({1, 2, 3}));
    const auto empty = comm.gather({});
    ASSERT_EQ(empty.size(), 1u);
    EXPECT_TRUE(empty[0].empty());
    std::vector<ByteBuffer> out{bytes({4, 5})};
    const auto in = comm.allToAll(out);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_EQ(in[0], bytes({4, 5}));
}

TEST(SingleProcessCommunicator, StartMinWaitMinReturnsTheValues) {
    SingleProcessCommunicator comm;
    const std::vector<double> v{2.0, -7.5};
    comm.startMin(v);
    comm.send(0, 1, bytes({1}));  // other traffic while the reduction is "in flight"
    EXPECT_EQ(comm.receive(0, 1), bytes({1}));
    EXPECT_EQ(comm.waitMin(), v);
    comm.startMin(std::vector<double>{1.0});
    EXPECT_EQ(comm.waitMin(), std::vector<double>{1.0});
}

TEST(SingleProcessCommunicator, AbortExitsWithTheStatusAfterFlushing) {
    EXPECT_EXIT(
        {
            std::fputs("flushed before exit", stderr);
            SingleProcessCommunicator comm;
            comm.abort(5);
        },
        testing::ExitedWithCode(5), "flushed before exit");
}

TEST(WorldCommunicator, IsSingleProcessUnlessSetAndCanBeReplaced) {
    Communicator& initial = worldCommunicator();
    EXPECT_EQ(initial.size(), 1);
    EXPECT_NE(dynamic_cast<SingleProcessCommunicator*>(&initial), nullptr);

    auto replacement = std::make_unique<SingleProcessCommunicator>();
    Communicator* installed = replacement.get();
    setWorldCommunicator(std::move(replacement));
    EXPECT_EQ(&worldCommunicator(), installed);
    worldCommunicator().send(0, 2, bytes({9}));
    EXPECT_EQ(worldCommunicator().receive(0, 2), bytes({9}));

    setWorldCommunicator(nullptr);  // back to a fresh single-process one
    EXPECT_NE(dynamic_cast<SingleProcessCommunicator*>(&worldCommunicator()), nullptr);
    EXPECT_EQ(worldCommunicator().size(), 1);
}
