// SPDX-License-Identifier: MIT
// The slot ranges that the force split hands to the per-particle stages (core/parallel.hpp
// parallelSlots; docs/physics/dem-threads.md, "Performance"): every item is visited once, range k
// is the part k of the cuts, cuts that do not fit the items fall back to equal blocks, and the
// maximum over the ranges is the exact maximum (NaN wins) whatever the ranges.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/parallel.hpp"

using namespace granulab;

namespace {

/// Visits of each item and the part that visited it, from parallelSlots on `threads` threads.
struct Visits {
    std::vector<int> count;
    std::vector<int> part;
};

Visits visit(int threads, const std::vector<std::uint32_t>* cuts, std::size_t n) {
    Visits v{std::vector<int>(n, 0), std::vector<int>(n, -1)};
    parallelSlots(threads, cuts, n, [&](std::size_t begin, std::size_t end, std::size_t part) {
        for (std::size_t i = begin; i < end; ++i) {
            ++v.count[i];  // each item belongs to one range: no two threads write it
            v.part[i] = static_cast<int>(part);
        }
    });
    return v;
}

}  // namespace

TEST(ParallelSlots, TheRangesAreTheCutsAndCoverEveryItemOnce) {
    const std::vector<std::uint32_t> cuts{0, 700, 1000, 5000};  // uneven, as after a force split
    const Visits v = visit(3, &cuts, 5000);
    for (std::size_t i = 0; i < 5000; ++i) {
        ASSERT_EQ(v.count[i], 1) << "item " << i;
        const int expected = i < 700 ? 0 : (i < 1000 ? 1 : 2);
        ASSERT_EQ(v.part[i], expected) << "item " << i;
    }
}

TEST(ParallelSlots, CutsThatDoNotFitTheItemsOrTheTeamFallBackToEqualBlocks) {
    const std::vector<std::uint32_t> stale{0, 700, 1000};       // cut for 1000 items, the store has 6000
    const std::vector<std::uint32_t> otherTeam{0, 3000, 6000};  // two parts for a team of three
    for (const auto* cuts : {&stale, &otherTeam}) {
        const Visits v = visit(3, cuts, 6000);
        for (std::size_t i = 0; i < 6000; ++i) ASSERT_EQ(v.count[i], 1) << "item " << i;
        // Equal blocks of parallelBlocks: 3 blocks of 2000 (6000 items >= 2 x kMinParallelBlock).
        EXPECT_EQ(v.part[1999], 0);
        EXPECT_EQ(v.part[2000], 1);
        EXPECT_EQ(v.part[5999], 2);
    }
    const Visits serial = visit(1, nullptr, 10);
    for (int c : serial.count) EXPECT_EQ(c, 1);
}

TEST(ParallelSlots, TheMaximumOverTheRangesIsExactAndNaNWins) {
    std::vector<double> value(4096);
    for (std::size_t i = 0; i < value.size(); ++i) value[i] = std::sin(0.37 * static_cast<double>(i)) + 1.0;
    double expected = 0;
    for (double x : value) expected = x > expected ? x : expected;
    const auto maxOf = [&](std::size_t begin, std::size_t end) {
        double m = 0;
        for (std::size_t i = begin; i < end; ++i) m = maxOrNaN(m, value[i]);
        return m;
    };
    const std::vector<std::uint32_t> cuts{0, 1, 4096};
    EXPECT_EQ(parallelMax(2, &cuts, value.size(), maxOf), expected);
    EXPECT_EQ(parallelMax(2, nullptr, value.size(), maxOf), expected);
    EXPECT_EQ(parallelMax(1, value.size(), maxOf), expected);
    value[4000] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(std::isnan(parallelMax(2, &cuts, value.size(), maxOf)));
    EXPECT_EQ(parallelMax(2, &cuts, 0, maxOf), 0.0) << "no items";
}
