// SPDX-License-Identifier: MIT
// Morton numbering of the cell grid (edmd spec section 3.1, AT-5): the 8 x 8 table of Fig. 3.1,
// coords() as the inverse of index(), every aligned block of 2^n numbers is a box (also for
// unequal bits per axis, 3D and padded grids), and realCellsIn() and realBox() against a
// brute-force count.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <stdexcept>

#include "edmd/parallel/morton.hpp"

using namespace granulab;
using edmd::MortonGrid;

namespace {

/// Every cell of the padded grid: index(coords(m)) == m, and coords of distinct numbers differ.
template <int D>
void roundTrips(const MortonGrid<D>& g) {
    std::set<std::array<int, D>> seen;
    for (std::uint64_t m = 0; m < g.paddedCount(); ++m) {
        const std::array<int, D> c = g.coords(m);
        for (int d = 0; d < D; ++d) {
            ASSERT_GE(c[d], 0);
            ASSERT_LT(c[d], 1 << g.bits(d));
        }
        ASSERT_EQ(g.index(c), m);
        ASSERT_TRUE(seen.insert(c).second) << "m = " << m;
        // Real when some cell of the axis maps to this padded coordinate (padding spread evenly).
        bool inside = true;
        for (int d = 0; d < D; ++d) {
            bool hit = false;
            for (int k = 0; k < g.cells()[d]; ++k) {
                std::array<int, D> cell{};
                cell[d] = k;
                hit = hit || g.padded(cell)[d] == c[d];
            }
            inside = inside && hit;
        }
        ASSERT_EQ(g.real(m), inside) << "m = " << m;
    }
}

/// Every aligned block of every size: the cells it holds fill exactly the box blockBox() reports,
/// and realCellsIn() equals the number of real cells counted one by one.
template <int D>
void blocksAreBoxes(const MortonGrid<D>& g) {
    for (int k = 0; k <= g.totalBits(); ++k) {
        const std::uint64_t size = std::uint64_t{1} << k;
        for (std::uint64_t start = 0; start < g.paddedCount(); start += size) {
            std::array<int, D> lo, hi;
            g.blockBox(start, k, lo, hi);
            std::uint64_t volume = 1;
            for (int d = 0; d < D; ++d) {
                ASSERT_LT(lo[d], hi[d]);
                volume *= static_cast<std::uint64_t>(hi[d] - lo[d]);
            }
            ASSERT_EQ(volume, size) << "block " << start << " (2^" << k << ")";
            std::uint64_t realCount = 0;
            for (std::uint64_t m = start; m < start + size; ++m) {
                const std::array<int, D> c = g.coords(m);
                for (int d = 0; d < D; ++d) {
                    ASSERT_GE(c[d], lo[d]) << "m = " << m << " in block " << start << " (2^" << k << ")";
                    ASSERT_LT(c[d], hi[d]) << "m = " << m << " in block " << start << " (2^" << k << ")";
                }
                if (g.real(m)) ++realCount;
            }
            // size distinct cells (round trip) inside a box of volume size: the block is the box.
            ASSERT_EQ(g.realCellsIn(start, k), realCount) << "block " << start << " (2^" << k << ")";
            // realBox(): the real cells whose padded coordinates lie in the block's box.
            std::array<int, D> rlo, rhi;
            g.realBox(start, k, rlo, rhi);
            std::uint64_t inBox = 0;
            std::array<int, D> c{};
            const auto count = [&](auto&& self, int d) -> void {
                if (d < 0) {
                    ++inBox;
                    return;
                }
                for (c[d] = 0; c[d] < g.cells()[d]; ++c[d]) {
                    const std::array<int, D> p = g.padded(c);
                    bool inside = true;
                    for (int e = 0; e < D; ++e) inside = inside && p[e] >= lo[e] && p[e] < hi[e];
                    bool inReal = true;
                    for (int e = 0; e < D; ++e) inReal = inReal && c[e] >= rlo[e] && c[e] < rhi[e];
                    if (d == 0) {
                        ASSERT_EQ(inside, inReal) << "block " << start << " (2^" << k << ")";
                        if (inside) self(self, -1);
                    } else {
                        self(self, d - 1);
                    }
                }
            };
            count(count, D - 1);
            ASSERT_EQ(inBox, realCount) << "block " << start << " (2^" << k << ")";
        }
    }
}

}  // namespace

TEST(Morton, Fig31Table) {
    // Spec Fig. 3.1, rows printed from y = 7 (top) to y = 0 (bottom).
    const int table[8][8] = {
        {42, 43, 46, 47, 58, 59, 62, 63}, {40, 41, 44, 45, 56, 57, 60, 61}, {34, 35, 38, 39, 50, 51, 54, 55},
        {32, 33, 36, 37, 48, 49, 52, 53}, {10, 11, 14, 15, 26, 27, 30, 31}, {8, 9, 12, 13, 24, 25, 28, 29},
        {2, 3, 6, 7, 18, 19, 22, 23},     {0, 1, 4, 5, 16, 17, 20, 21},
    };
    const MortonGrid<2> g({8, 8});
    EXPECT_EQ(g.totalBits(), 6);
    EXPECT_EQ(g.paddedCount(), 64u);
    for (int row = 0; row < 8; ++row) {
        const int y = 7 - row;
        for (int x = 0; x < 8; ++x) {
            EXPECT_EQ(g.index({x, y}), static_cast<std::uint64_t>(table[row][x]))
                << "x = " << x << ", y = " << y;
            EXPECT_EQ(g.coords(static_cast<std::uint64_t>(table[row][x])), (std::array<int, 2>{x, y}));
        }
    }
}

TEST(Morton, SpecUnitValues) {
    const MortonGrid<2> g({8, 8});
    EXPECT_EQ(g.index({0, 6}), 40u);
    EXPECT_EQ(g.index({7, 7}), 63u);
    EXPECT_EQ(g.index({4, 0}), 16u);
}

TEST(Morton, EqualBits3DFollowsSpecOrder) {
    // z[k] y[k] x[k] ... z[1] y[1] x[1], x least significant.
    const MortonGrid<3> g({4, 4, 4});
    EXPECT_EQ(g.index({1, 0, 0}), 1u);
    EXPECT_EQ(g.index({0, 1, 0}), 2u);
    EXPECT_EQ(g.index({0, 0, 1}), 4u);
    EXPECT_EQ(g.index({2, 0, 0}), 8u);
    EXPECT_EQ(g.index({0, 2, 0}), 16u);
    EXPECT_EQ(g.index({0, 0, 2}), 32u);
    EXPECT_EQ(g.index({3, 3, 3}), 63u);
}

TEST(Morton, UnequalBitsSkipUsedUpAxes) {
    // 16 x 4 cells: x has 4 bits, y 2; positions 0:x0 1:y0 2:x1 3:y1 4:x2 5:x3.
    const MortonGrid<2> g({16, 4});
    EXPECT_EQ(g.bits(0), 4);
    EXPECT_EQ(g.bits(1), 2);
    EXPECT_EQ(g.totalBits(), 6);
    EXPECT_EQ(g.index({1, 0}), 1u);
    EXPECT_EQ(g.index({0, 1}), 2u);
    EXPECT_EQ(g.index({2, 0}), 4u);
    EXPECT_EQ(g.index({0, 2}), 8u);
    EXPECT_EQ(g.index({4, 0}), 16u);
    EXPECT_EQ(g.index({8, 0}), 32u);
    EXPECT_EQ(g.index({15, 3}), 63u);
    // 2 x 8 x 1 cells (3D): x 1 bit, y 3, z 0: positions 0:x0 1:y0 2:y1 3:y2.
    const MortonGrid<3> h({2, 8, 1});
    EXPECT_EQ(h.totalBits(), 4);
    EXPECT_EQ(h.index({1, 0, 0}), 1u);
    EXPECT_EQ(h.index({0, 1, 0}), 2u);
    EXPECT_EQ(h.index({0, 2, 0}), 4u);
    EXPECT_EQ(h.index({0, 4, 0}), 8u);
}

TEST(Morton, PaddingBits) {
    const MortonGrid<2> g({5, 3});
    EXPECT_EQ(g.bits(0), 3);
    EXPECT_EQ(g.bits(1), 2);
    EXPECT_EQ(g.paddedCount(), 32u);
    EXPECT_EQ(g.cells(), (std::array<int, 2>{5, 3}));
    const MortonGrid<3> one({1, 1, 1});
    EXPECT_EQ(one.totalBits(), 0);
    EXPECT_EQ(one.paddedCount(), 1u);
    EXPECT_EQ(one.index({0, 0, 0}), 0u);
    EXPECT_EQ(one.realCellsIn(0, 0), 1u);
}

TEST(Morton, CoordsInvertIndex) {
    roundTrips(MortonGrid<2>({8, 8}));
    roundTrips(MortonGrid<2>({16, 4}));
    roundTrips(MortonGrid<2>({5, 3}));
    roundTrips(MortonGrid<2>({1, 8}));
    roundTrips(MortonGrid<3>({6, 6, 3}));
    roundTrips(MortonGrid<3>({2, 8, 1}));
    roundTrips(MortonGrid<3>({7, 2, 5}));
    // A large grid, on a few cells.
    const MortonGrid<3> big({1 << 20, 1000, 3});
    for (const std::array<int, 3> c : {std::array<int, 3>{0, 0, 0}, std::array<int, 3>{(1 << 20) - 1, 999, 2},
                                       std::array<int, 3>{123456, 789, 1}})
        EXPECT_EQ(big.coords(big.index(c)), c);
}

TEST(Morton, AlignedBlocksAreBoxes) {
    blocksAreBoxes(MortonGrid<2>({8, 8}));
    blocksAreBoxes(MortonGrid<2>({16, 4}));
    blocksAreBoxes(MortonGrid<2>({4, 32}));
    blocksAreBoxes(MortonGrid<2>({5, 3}));
    blocksAreBoxes(MortonGrid<2>({1, 8}));
    blocksAreBoxes(MortonGrid<3>({8, 8, 8}));
    blocksAreBoxes(MortonGrid<3>({6, 6, 3}));
    blocksAreBoxes(MortonGrid<3>({2, 8, 1}));
    blocksAreBoxes(MortonGrid<3>({7, 2, 5}));
}

TEST(Morton, BlockSideRatios) {
    // Spec 3.1: with equal bits a block is a box with side ratios 1:1:1, 1:1:2 or 1:2:2.
    const MortonGrid<3> g({8, 8, 8});
    for (int k = 0; k <= g.totalBits(); ++k) {
        std::array<int, 3> lo, hi;
        g.blockBox(0, k, lo, hi);
        std::array<int, 3> side{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
        std::sort(side.begin(), side.end());
        EXPECT_TRUE(side[2] == side[0] || side[2] == 2 * side[0]) << "k = " << k;
    }
}

TEST(Morton, RealCellsInClosedForm) {
    // 5 x 3 cells padded to 8 x 4: real x at padded 0, 1, 3, 4, 6; real y at 0, 1, 2.
    const MortonGrid<2> g({5, 3});
    EXPECT_EQ(g.padded({4, 2}), (std::array<int, 2>{6, 2}));
    EXPECT_EQ(g.padded({2, 1}), (std::array<int, 2>{3, 1}));
    EXPECT_EQ(g.realCellsIn(0, 5), 15u);
    EXPECT_EQ(g.realCellsIn(0, 4), 9u);   // padded x 0-3, y 0-3: real x 0, 1, 3
    EXPECT_EQ(g.realCellsIn(16, 4), 6u);  // padded x 4-7: real x 4, 6
    EXPECT_EQ(g.realCellsIn(24, 3), 2u);  // padded x 4-7, y 2-3
    EXPECT_EQ(g.realCellsIn(28, 2), 1u);  // padded x 6-7, y 2-3
    EXPECT_EQ(g.realCellsIn(g.index({4, 2}), 0), 1u);
    EXPECT_EQ(g.realCellsIn(g.index({5, 2}), 0), 0u);
    EXPECT_EQ(g.realCellsIn(g.index({4, 3}), 0), 0u);
    EXPECT_EQ(g.indexOfCell({4, 2}), g.index({6, 2}));
    // Equal halves of a long axis hold equal numbers of real cells.
    const MortonGrid<2> wide({1618, 1});
    EXPECT_EQ(wide.realCellsIn(0, 10), 809u);
    EXPECT_EQ(wide.realCellsIn(1024, 10), 809u);
    const MortonGrid<3> h({6, 6, 3});
    EXPECT_EQ(h.realCellsIn(0, h.totalBits()), 108u);
}

TEST(Morton, InvalidGridsThrow) {
    EXPECT_THROW(MortonGrid<2>({0, 4}), std::invalid_argument);
    EXPECT_THROW(MortonGrid<3>({4, -1, 4}), std::invalid_argument);
    EXPECT_THROW(MortonGrid<3>({1 << 21, 1 << 21, 1 << 21}), std::invalid_argument);  // 63 bits
    EXPECT_NO_THROW(MortonGrid<3>({1 << 20, 1 << 21, 1 << 21}));                      // 62 bits
}
