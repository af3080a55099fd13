// SPDX-License-Identifier: MIT
// A rank's tables cover its window of cells and map ids through a hash (edmd spec 3.6; issue 15:
// memory per rank about N/P plus halo): CellWindow's index arithmetic, wrap and cut against brute
// force, and IdSlotMap against std::unordered_map under random inserts and erasures.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <set>
#include <unordered_map>

#include "edmd/cell_window.hpp"
#include "edmd/id_slot_map.hpp"

using namespace granulab;
using edmd::CellWindow;
using edmd::IdSlotMap;

TEST(CellWindow, WholeGridIndexIsTheGridIndex) {
    const CellWindow w = CellWindow::whole({5, 4, 3});
    ASSERT_EQ(w.count(), 60u);
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 5; ++x) {
                const std::array<int, 3> c{x, y, z};
                const std::uint32_t index = w.indexOf<3>(c);
                EXPECT_EQ(index, static_cast<std::uint32_t>(x + 5 * (y + 4 * z)));
                EXPECT_EQ(w.coordsOf<3>(index), c);
            }
}

TEST(CellWindow, AroundWrapsOnPeriodicAxesAndIsCutAtWalls) {
    // x periodic with 10 cells: the block [8, 10) grown by one is 7, 8, 9, 0.
    // y walls with 6 cells: [0, 3) grown by one is 0 .. 3 (cut at the wall below).
    const CellWindow w = CellWindow::around<2>({10, 6, 1}, {true, false, false}, {8, 0, 0}, {10, 3, 1}, 1);
    EXPECT_EQ(w.origin[0], 7);
    EXPECT_EQ(w.extent[0], 4);
    EXPECT_EQ(w.origin[1], 0);
    EXPECT_EQ(w.extent[1], 4);
    EXPECT_EQ(w.count(), 16u);
    EXPECT_EQ(w.local(0, 0), 3);
    EXPECT_EQ(w.local(0, 1), -1);
    EXPECT_EQ(w.local(0, 6), -1);
    EXPECT_EQ(w.grid(0, 3), 0);
    EXPECT_EQ(w.local(1, 4), -1);
    EXPECT_EQ(w.indexOf<2>(std::array<int, 2>{1, 0}), CellWindow::kOutside);
    for (std::uint32_t i = 0; i < w.count(); ++i) EXPECT_EQ(w.indexOf<2>(w.coordsOf<2>(i)), i);
    // A block that, grown, covers a periodic axis takes it whole.
    const CellWindow big = CellWindow::around<2>({10, 6, 1}, {true, true, false}, {1, 0, 0}, {9, 5, 1}, 1);
    EXPECT_EQ(big.origin[0], 0);
    EXPECT_EQ(big.extent[0], 10);
    EXPECT_EQ(big.extent[1], 6);
    // An empty block: an empty window.
    EXPECT_EQ(CellWindow::around<2>({10, 6, 1}, {true, true, false}, {3, 2, 0}, {3, 4, 1}, 1).count(), 0u);
}

TEST(CellWindow, ForEachAroundVisitsTheNeighboursInsideTheWindow) {
    // 3D: x periodic (9 cells), y walls (7), z periodic (5); window around a 3 x 2 x 2 block.
    const std::array<int, 3> cells{9, 7, 5};
    const std::array<bool, 3> periodic{true, false, true};
    const CellWindow w = CellWindow::around<3>(cells, periodic, {6, 5, 3}, {9, 7, 5}, 1);
    const auto near = [&](int a, int b, int d) {
        int delta = std::abs(a - b);
        if (periodic[d]) delta = std::min(delta, cells[d] - delta);
        return delta <= 1;
    };
    for (int z = 0; z < 5; ++z)
        for (int y = 0; y < 7; ++y)
            for (int x = 0; x < 9; ++x) {
                const std::array<int, 3> c{x, y, z};
                std::multiset<std::uint32_t> visited;
                w.forEachAround<3>(c, periodic, [&](std::uint32_t index) { visited.insert(index); });
                std::multiset<std::uint32_t> expected;
                for (std::uint32_t i = 0; i < w.count(); ++i) {
                    const auto k = w.coordsOf<3>(i);
                    if (near(k[0], x, 0) && near(k[1], y, 1) && near(k[2], z, 2)) expected.insert(i);
                }
                EXPECT_EQ(visited, expected) << "cell " << x << " " << y << " " << z;
            }
}

TEST(IdSlotMap, AgreesWithAStandardMapUnderRandomInsertsAndErasures) {
    IdSlotMap map;
    std::unordered_map<std::uint32_t, std::uint32_t> reference;
    std::mt19937 rng(15);
    std::uniform_int_distribution<std::uint32_t> id(0, 4999), slot(0, 1u << 30), op(0, 9);
    for (int step = 0; step < 200000; ++step) {
        const std::uint32_t k = id(rng);
        if (op(rng) < 4) {
            map.erase(k);
            reference.erase(k);
        } else {
            const std::uint32_t s = slot(rng);
            map.set(k, s);
            reference[k] = s;
        }
        if (step % 997 == 0) {
            ASSERT_EQ(map.size(), reference.size());
            const IdSlotMap copy = map;  // the rollback copy
            for (std::uint32_t q = 0; q < 5000; ++q) {
                const auto it = reference.find(q);
                const std::uint32_t want = it == reference.end() ? IdSlotMap::kNone : it->second;
                ASSERT_EQ(map.find(q), want) << "id " << q << " after " << step << " operations";
                ASSERT_EQ(copy.find(q), want);
            }
        }
    }
    // Memory follows what is held, not the largest id.
    IdSlotMap few;
    for (std::uint32_t k = 0; k < 100; ++k) few.set(k * 10000000u, k);
    EXPECT_LE(few.memoryBytes(), 256 * sizeof(std::uint64_t));
    for (std::uint32_t k = 0; k < 100; ++k) EXPECT_EQ(few.find(k * 10000000u), k);
}
