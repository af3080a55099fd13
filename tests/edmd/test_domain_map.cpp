// SPDX-License-Identifier: MIT
// Domain map and dynamic load balancing (edmd spec sections 3.1 and 3.2, AT-5): the worked
// example of the spec (I 0-31, II 32-47, III 48-55, IV 56-63 -> I 0-15, III 16-31, II 32-47,
// IV 48-63), the initial halving for several rank counts on full and padded grids, owner()
// against a scan, cases that must not move, convergence of repeated rebalancing of a clustered
// load, checkpoint encoding and the validation of explicit blocks.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "edmd/parallel/domain_map.hpp"
#include "edmd/parallel/morton.hpp"

using namespace granulab;
using edmd::BalanceMove;
using edmd::DomainBlock;
using edmd::DomainMap;
using edmd::MortonGrid;

namespace {

/// The map is valid (the constructor re-checks alignment, cover and ranks), blocks() is sorted,
/// blockOf() agrees with it, and owner() agrees with a linear scan on every number.
void checkConsistent(const DomainMap& map) {
    ASSERT_NO_THROW(DomainMap(map.totalBits(), map.blocks()));
    const auto& blocks = map.blocks();
    ASSERT_EQ(static_cast<int>(blocks.size()), map.ranks());
    for (std::size_t i = 0; i + 1 < blocks.size(); ++i) ASSERT_LT(blocks[i].start, blocks[i + 1].start);
    for (int r = 0; r < map.ranks(); ++r) ASSERT_EQ(map.blockOf(r).rank, r);
    const std::uint64_t n = std::uint64_t{1} << map.totalBits();
    for (std::uint64_t m = 0; m < n; ++m) {
        int expected = -1;
        for (const DomainBlock& b : blocks)
            if (m >= b.start && m < b.start + (std::uint64_t{1} << b.log2Size)) expected = b.rank;
        ASSERT_EQ(map.owner(m), expected) << "m = " << m;
    }
}

DomainMap specExampleMap() {
    // Spec 3.2 worked example on the 8 x 8 grid of Fig. 3.1: I..IV are ranks 0..3.
    return DomainMap(6, {{0, 5, 0}, {32, 4, 1}, {48, 3, 2}, {56, 3, 3}});
}

/// Exact half loads of every rank from a per-cell load (indexed by Morton number).
std::vector<std::array<double, 2>> halfLoadsOf(const DomainMap& map, const std::vector<double>& cellLoad) {
    std::vector<std::array<double, 2>> half(static_cast<std::size_t>(map.ranks()), {0.0, 0.0});
    for (const DomainBlock& b : map.blocks()) {
        const std::uint64_t size = std::uint64_t{1} << b.log2Size;
        for (std::uint64_t m = b.start; m < b.start + size; ++m)
            half[b.rank][b.log2Size > 0 && m >= b.start + size / 2 ? 1 : 0] += cellLoad[m];
    }
    return half;
}

double maxLoad(const std::vector<std::array<double, 2>>& half) {
    double mx = 0;
    for (const auto& h : half) mx = std::max(mx, h[0] + h[1]);
    return mx;
}

}  // namespace

TEST(DomainMap, SpecWorkedExampleAT5) {
    DomainMap map = specExampleMap();
    checkConsistent(map);
    // I overloaded, III and IV underloaded.
    const std::vector<std::array<double, 2>> half{{50, 50}, {25, 25}, {5, 5}, {5, 5}};
    const std::vector<BalanceMove> moves = map.rebalance(half, 0.9);
    ASSERT_EQ(moves.size(), 1u);
    EXPECT_EQ(moves[0], (BalanceMove{0, 3, 2}));         // heavy I, keeper IV, freed III
    EXPECT_EQ(map.blockOf(0), (DomainBlock{0, 4, 0}));   // I: 0-15
    EXPECT_EQ(map.blockOf(2), (DomainBlock{16, 4, 2}));  // III: 16-31
    EXPECT_EQ(map.blockOf(1), (DomainBlock{32, 4, 1}));  // II: 32-47, unchanged
    EXPECT_EQ(map.blockOf(3), (DomainBlock{48, 4, 3}));  // IV: 48-63
    checkConsistent(map);
    // In cells of Fig. 3.1: III now owns the lower right quarter, IV the upper right one.
    const MortonGrid<2> g({8, 8});
    EXPECT_EQ(map.owner(g.index({7, 0})), 2);
    EXPECT_EQ(map.owner(g.index({4, 7})), 3);
    EXPECT_EQ(map.owner(g.index({0, 3})), 0);
    EXPECT_EQ(map.owner(g.index({0, 7})), 1);
}

TEST(DomainMap, KeeperIsTheHeavierSibling) {
    DomainMap map = specExampleMap();
    const std::vector<std::array<double, 2>> half{{50, 50}, {25, 25}, {6, 6}, {2, 2}};
    const std::vector<BalanceMove> moves = map.rebalance(half, 0.9);
    ASSERT_EQ(moves.size(), 1u);
    EXPECT_EQ(moves[0], (BalanceMove{0, 2, 3}));  // III keeps 48-63, IV takes 16-31
    EXPECT_EQ(map.blockOf(2), (DomainBlock{48, 4, 2}));
    EXPECT_EQ(map.blockOf(3), (DomainBlock{16, 4, 3}));
    EXPECT_EQ(map.blockOf(0), (DomainBlock{0, 4, 0}));
    checkConsistent(map);
}

TEST(DomainMap, BelowThresholdDoesNotMove) {
    // The same map with I only mildly overloaded: after the move III+IV would carry 60 > 0.9 * 60.
    DomainMap map = specExampleMap();
    const std::vector<std::array<double, 2>> half{{30, 30}, {20, 20}, {15, 15}, {15, 15}};
    EXPECT_TRUE(map.rebalance(half, 0.9).empty());
    EXPECT_EQ(map.blocks(), specExampleMap().blocks());
}

TEST(DomainMap, ConcurrentMovesInvolveDisjointRanks) {
    DomainMap map(
        6, {{0, 4, 0}, {16, 4, 1}, {32, 3, 2}, {40, 3, 3}, {48, 2, 4}, {52, 2, 5}, {56, 2, 6}, {60, 2, 7}});
    const std::vector<std::array<double, 2>> half{{40, 40}, {35, 35}, {5, 5}, {5, 5},
                                                  {5, 5},   {5, 5},   {5, 5}, {5, 5}};
    const std::vector<BalanceMove> moves = map.rebalance(half, 0.9);
    ASSERT_EQ(moves.size(), 2u);
    EXPECT_EQ(moves[0], (BalanceMove{0, 3, 2}));
    EXPECT_EQ(moves[1], (BalanceMove{1, 5, 4}));
    const std::vector<DomainBlock> expected{{0, 3, 0},  {8, 3, 2},  {16, 3, 1}, {24, 3, 4},
                                            {32, 4, 3}, {48, 3, 5}, {56, 2, 6}, {60, 2, 7}};
    EXPECT_EQ(map.blocks(), expected);
    checkConsistent(map);
}

TEST(DomainMap, TwoRanksNeverMove) {
    DomainMap map(6, {{0, 5, 0}, {32, 5, 1}});
    const std::vector<std::array<double, 2>> half{{100, 100}, {0, 0}};
    EXPECT_TRUE(map.rebalance(half, 0.9).empty());
    EXPECT_EQ(map.blockOf(0), (DomainBlock{0, 5, 0}));
    EXPECT_EQ(map.blockOf(1), (DomainBlock{32, 5, 1}));
    DomainMap one = DomainMap::initial(1, 6, [](std::uint64_t, int k) { return std::ldexp(1.0, k); });
    const std::vector<std::array<double, 2>> single{{100, 0}};
    EXPECT_TRUE(one.rebalance(single, 0.9).empty());
}

TEST(DomainMap, BalancedMapDoesNotMove) {
    const MortonGrid<2> g({8, 8});
    for (int ranks : {3, 4, 5, 8}) {
        DomainMap map = DomainMap::initial(
            ranks, g.totalBits(), [&](std::uint64_t s, int k) { return double(g.realCellsIn(s, k)); });
        const std::vector<DomainBlock> before = map.blocks();
        // Load proportional to cells: as balanced as blocks of 2^n cells allow.
        std::vector<std::array<double, 2>> half;
        for (int r = 0; r < ranks; ++r) {
            const double cells = std::ldexp(1.0, map.blockOf(r).log2Size);
            half.push_back({cells / 2, cells / 2});
        }
        EXPECT_TRUE(map.rebalance(half, 0.9).empty()) << ranks << " ranks";
        EXPECT_EQ(map.blocks(), before);
    }
}

TEST(DomainMap, EquallyHeavyRanksSplitTogether) {
    // The spec's clustered start (Fig. 3.1 scaled to 16 x 16 cells): a dense upper right quarter
    // (20 per cell) on a dilute background (1 per cell), 8 ranks of 32 cells each. The quarter is
    // shared by two ranks (640 each); no single move lowers the largest load, two moves do.
    const MortonGrid<2> g({16, 16});
    std::vector<double> cellLoad(g.paddedCount());
    for (std::uint64_t m = 0; m < g.paddedCount(); ++m) {
        const auto c = g.coords(m);
        cellLoad[m] = c[0] >= 8 && c[1] >= 8 ? 20.0 : 1.0;
    }
    DomainMap map = DomainMap::initial(8, g.totalBits(),
                                       [&](std::uint64_t s, int k) { return double(g.realCellsIn(s, k)); });
    EXPECT_EQ(maxLoad(halfLoadsOf(map, cellLoad)), 640.0);
    const std::vector<BalanceMove> moves = map.rebalance(halfLoadsOf(map, cellLoad), 0.9);
    ASSERT_EQ(moves.size(), 2u);
    EXPECT_EQ(moves[0], (BalanceMove{6, 1, 0}));  // ranks 0 and 1 merge 0-63, 0 takes 208-223
    EXPECT_EQ(moves[1], (BalanceMove{7, 3, 2}));  // ranks 2 and 3 merge 64-127, 2 takes 240-255
    checkConsistent(map);
    EXPECT_EQ(maxLoad(halfLoadsOf(map, cellLoad)), 320.0);
    // 320 is the best aligned blocks allow here (the quarter needs blocks of <= 16 cells, and
    // at most 6 ranks can go there); no further move.
    EXPECT_TRUE(map.rebalance(halfLoadsOf(map, cellLoad), 0.9).empty());
}

TEST(DomainMap, RepeatedRebalancingConverges) {
    // A strongly clustered load on 32 x 32 cells (a dense Gaussian cluster on a dilute
    // background), starting from equal blocks, rebalanced with exact half loads until nothing
    // moves: the largest load falls on every call that moves, and the calls stop.
    const MortonGrid<2> g({32, 32});
    struct Case {
        int ranks;
        double cx, cy;  // cluster centre [cells]
    };
    for (const Case& tc :
         {Case{8, 25.0, 23.0}, Case{8, 7.3, 20.6}, Case{16, 16.0, 16.0}, Case{32, 5.5, 9.2}}) {
        std::vector<double> cellLoad(g.paddedCount());
        for (std::uint64_t m = 0; m < g.paddedCount(); ++m) {
            const auto c = g.coords(m);
            const double r2 =
                (c[0] + 0.5 - tc.cx) * (c[0] + 0.5 - tc.cx) + (c[1] + 0.5 - tc.cy) * (c[1] + 0.5 - tc.cy);
            cellLoad[m] = 1.0 + 300.0 * std::exp(-r2 / 18.0);
        }
        DomainMap map = DomainMap::initial(
            tc.ranks, g.totalBits(), [&](std::uint64_t s, int k) { return double(g.realCellsIn(s, k)); });
        const double initialMax = maxLoad(halfLoadsOf(map, cellLoad));
        double previous = initialMax;
        int rounds = 0;
        bool stopped = false;
        for (; rounds < 100; ++rounds) {
            const std::vector<DomainBlock> before = map.blocks();
            const std::vector<BalanceMove> moves = map.rebalance(halfLoadsOf(map, cellLoad), 0.9);
            checkConsistent(map);
            if (moves.empty()) {
                EXPECT_EQ(map.blocks(), before);
                stopped = true;
                break;
            }
            // The half loads are exact here, so the estimate is the outcome: a real improvement.
            const double now = maxLoad(halfLoadsOf(map, cellLoad));
            EXPECT_LT(now, 0.9 * previous) << tc.ranks << " ranks, round " << rounds;
            previous = now;
        }
        EXPECT_TRUE(stopped) << tc.ranks << " ranks";
        EXPECT_GE(rounds, 1) << tc.ranks << " ranks";                    // the cluster did trigger moves
        EXPECT_LT(previous, 0.85 * initialMax) << tc.ranks << " ranks";  // and they helped
        // Stopped for good: the same loads give no further move.
        EXPECT_TRUE(map.rebalance(halfLoadsOf(map, cellLoad), 0.9).empty());
    }
}

TEST(DomainMap, InitialOnFullGrid) {
    const MortonGrid<2> g({8, 8});
    auto weight = [&](std::uint64_t s, int k) { return double(g.realCellsIn(s, k)); };
    for (int ranks : {1, 2, 3, 4, 5, 8}) {
        const DomainMap map = DomainMap::initial(ranks, g.totalBits(), weight);
        EXPECT_EQ(map.ranks(), ranks);
        EXPECT_EQ(map.totalBits(), 6);
        checkConsistent(map);
        for (int r = 0; r < ranks; ++r) {
            EXPECT_EQ(map.blocks()[r].rank, r);  // rank r has the r-th block in Morton order
            EXPECT_GT(g.realCellsIn(map.blockOf(r).start, map.blockOf(r).log2Size), 0u);
        }
    }
    // Halving the heaviest block, ties to the lower start.
    EXPECT_EQ(DomainMap::initial(3, 6, weight).blocks(),
              (std::vector<DomainBlock>{{0, 4, 0}, {16, 4, 1}, {32, 5, 2}}));
    EXPECT_EQ(DomainMap::initial(5, 6, weight).blocks(),
              (std::vector<DomainBlock>{{0, 3, 0}, {8, 3, 1}, {16, 4, 2}, {32, 4, 3}, {48, 4, 4}}));
    const DomainMap eight = DomainMap::initial(8, 6, weight);
    for (const DomainBlock& b : eight.blocks()) EXPECT_EQ(b.log2Size, 3);
}

TEST(DomainMap, InitialOnPaddedGrid) {
    // 5 x 3 cells padded to 8 x 4 (32 numbers, 15 real cells): every block holds real cells.
    // (Not possible for every P: with 15 ranks each block would need exactly one real cell, but
    // the block of numbers 8-11, cells (0-1, 2-3), holds two real cells, both in its first half.)
    const MortonGrid<2> g({5, 3});
    auto weight = [&](std::uint64_t s, int k) { return double(g.realCellsIn(s, k)); };
    for (int ranks : {1, 2, 3, 4, 5, 6, 8}) {
        const DomainMap map = DomainMap::initial(ranks, g.totalBits(), weight);
        EXPECT_EQ(map.ranks(), ranks);
        checkConsistent(map);
        for (const DomainBlock& b : map.blocks())
            EXPECT_GT(g.realCellsIn(b.start, b.log2Size), 0u) << ranks << " ranks, block at " << b.start;
    }
    // 3D, padded: 6 x 6 x 3 cells (256 numbers, 108 real cells).
    const MortonGrid<3> h({6, 6, 3});
    auto weight3 = [&](std::uint64_t s, int k) { return double(h.realCellsIn(s, k)); };
    for (int ranks : {2, 5, 7, 16}) {
        const DomainMap map = DomainMap::initial(ranks, h.totalBits(), weight3);
        checkConsistent(map);
        for (const DomainBlock& b : map.blocks())
            EXPECT_GT(h.realCellsIn(b.start, b.log2Size), 0u) << ranks << " ranks, block at " << b.start;
    }
}

TEST(DomainMap, InitialErrors) {
    auto one = [](std::uint64_t, int) { return 1.0; };
    EXPECT_THROW(DomainMap::initial(0, 6, one), std::invalid_argument);
    EXPECT_THROW(DomainMap::initial(65, 6, one), std::invalid_argument);
    EXPECT_THROW(DomainMap::initial(2, 63, one), std::invalid_argument);
    EXPECT_THROW(DomainMap::initial(2, 6, [](std::uint64_t, int) { return -1.0; }), std::invalid_argument);
    // Every cell its own rank is possible; all-zero weights still give P blocks.
    EXPECT_EQ(DomainMap::initial(64, 6, one).ranks(), 64);
    EXPECT_EQ(DomainMap::initial(5, 6, [](std::uint64_t, int) { return 0.0; }).ranks(), 5);
    EXPECT_EQ(DomainMap::initial(1, 0, one).ranks(), 1);
}

TEST(DomainMap, EncodeDecodeRoundTrip) {
    DomainMap map = specExampleMap();
    const std::vector<std::array<double, 2>> half{{50, 50}, {25, 25}, {5, 5}, {5, 5}};
    map.rebalance(half, 0.9);
    const std::vector<std::uint64_t> data = map.encode();
    EXPECT_EQ(data, (std::vector<std::uint64_t>{6, 0, 4, 0, 16, 4, 2, 32, 4, 1, 48, 4, 3}));
    const DomainMap back = DomainMap::decode(data);
    EXPECT_EQ(back.totalBits(), map.totalBits());
    EXPECT_EQ(back.blocks(), map.blocks());
    for (int r = 0; r < map.ranks(); ++r) EXPECT_EQ(back.blockOf(r), map.blockOf(r));

    EXPECT_THROW(DomainMap::decode(std::vector<std::uint64_t>{}), std::invalid_argument);
    EXPECT_THROW(DomainMap::decode(std::vector<std::uint64_t>{6, 0, 6}), std::invalid_argument);
    EXPECT_THROW(DomainMap::decode(std::vector<std::uint64_t>{63, 0, 63, 0}), std::invalid_argument);
    EXPECT_THROW(DomainMap::decode(std::vector<std::uint64_t>{6, 0, 100, 0}), std::invalid_argument);
    EXPECT_THROW(DomainMap::decode(std::vector<std::uint64_t>{6, 0, 6, std::uint64_t{1} << 40}),
                 std::invalid_argument);
    EXPECT_EQ(DomainMap::decode(std::vector<std::uint64_t>{6, 0, 6, 0}).ranks(), 1);
}

TEST(DomainMap, InvalidExplicitBlocksThrow) {
    using Blocks = std::vector<DomainBlock>;
    EXPECT_THROW(DomainMap(6, Blocks{}), std::invalid_argument);                        // none
    EXPECT_THROW(DomainMap(63, Blocks{{0, 63, 0}}), std::invalid_argument);             // bits
    EXPECT_THROW(DomainMap(6, Blocks{{0, 7, 0}}), std::invalid_argument);               // too big
    EXPECT_THROW(DomainMap(6, Blocks{{0, 5, 0}, {32, -1, 1}}), std::invalid_argument);  // size < 0
    EXPECT_THROW(DomainMap(6, Blocks{{0, 5, 0}, {32, 4, 1}}), std::invalid_argument);   // gap at end
    EXPECT_THROW(DomainMap(6, Blocks{{0, 4, 0}, {32, 5, 1}}), std::invalid_argument);   // gap
    EXPECT_THROW(DomainMap(6, Blocks{{0, 5, 0}, {16, 4, 1}, {32, 5, 2}}), std::invalid_argument);  // overlap
    EXPECT_THROW(DomainMap(6, Blocks{{0, 5, 0}, {32, 5, 0}}), std::invalid_argument);   // rank twice
    EXPECT_THROW(DomainMap(6, Blocks{{0, 5, 0}, {32, 5, 2}}), std::invalid_argument);   // rank range
    EXPECT_THROW(DomainMap(6, Blocks{{0, 5, -1}, {32, 5, 1}}), std::invalid_argument);  // rank < 0
    // 0-15 (2^4), 16-23 (2^3), 24-55 (2^5: not aligned), 56-63 (2^3).
    EXPECT_THROW(DomainMap(6, Blocks{{0, 4, 0}, {16, 3, 1}, {24, 5, 2}, {56, 3, 3}}), std::invalid_argument);
    // Any order of the input is fine.
    EXPECT_NO_THROW(DomainMap(6, Blocks{{56, 3, 3}, {0, 5, 0}, {48, 3, 2}, {32, 4, 1}}));
}

TEST(DomainMap, RebalanceRejectsBadInput) {
    DomainMap map = specExampleMap();
    const std::vector<std::array<double, 2>> three{{1, 1}, {1, 1}, {1, 1}};
    EXPECT_THROW(map.rebalance(three, 0.9), std::invalid_argument);
    const std::vector<std::array<double, 2>> negative{{1, 1}, {1, 1}, {1, -1}, {1, 1}};
    EXPECT_THROW(map.rebalance(negative, 0.9), std::invalid_argument);
    const std::vector<std::array<double, 2>> nan{{1, 1}, {1, 1}, {1, std::nan("")}, {1, 1}};
    EXPECT_THROW(map.rebalance(nan, 0.9), std::invalid_argument);
    const std::vector<std::array<double, 2>> ok{{1, 1}, {1, 1}, {1, 1}, {1, 1}};
    EXPECT_THROW(map.rebalance(ok, 0.0), std::invalid_argument);
    EXPECT_EQ(map.blocks(), specExampleMap().blocks());
}
