// SPDX-License-Identifier: MIT
// ParticleStore columns (DESIGN.md "Particle state"): the one column visitor covers every column
// (bytes per particle), reserve and permute reach all columns, and save() writes the checkpoint
// layout of the DEM world (each column as size + raw values, in declaration order), so that old
// and new checkpoints resume bit for bit.
#include <gtest/gtest.h>

#include <sstream>

#include "core/binary_io.hpp"
#include "model/particle_store.hpp"

using namespace granulab;
using namespace granulab::model;

namespace {
ParticleStore threeParticles() {
    ParticleStore s;
    s.add(7, {0.1, 0.2}, {1.0, -1.0}, 0.3, 4.0, 0.01, 2.0, 0.5, 1);
    s.add(9, {0.4, 0.5}, {2.0, -2.0}, 0.6, 5.0, 0.02, 3.0, 0.0, 0, 3);
    s.add(8, {0.7, 0.8}, {3.0, -3.0}, 0.9, 6.0, 0.03, 0.0, 0.25, 2);
    s.fx = {1, 2, 3};
    s.fy = {4, 5, 6};
    s.torque = {7, 8, 9};
    return s;
}
}  // namespace

TEST(ParticleStore, VisitorCoversEveryColumn) {
    const ParticleStore s = threeParticles();
    std::size_t columns = 0, bytes = 0;
    s.forEachColumn([&](const auto& col) {
        ++columns;
        bytes += sizeof(col[0]);
        EXPECT_EQ(col.size(), 3u);
    });
    EXPECT_EQ(columns, 16u);
    EXPECT_EQ(bytes, ParticleStore::kBytesPerParticle);
    static_assert(ParticleStore::kBytesPerParticle ==
                  13 * sizeof(Real) + 2 * sizeof(std::uint32_t) + sizeof(ParticleId));
    // The visitor reaches every data member: the store holds nothing but its columns.
    EXPECT_EQ(sizeof(ParticleStore), columns * sizeof(std::vector<Real>));
    EXPECT_TRUE(s.consistent());
}

TEST(ParticleStore, ReserveReachesEveryColumn) {
    ParticleStore s;
    s.reserve(100);
    s.forEachColumn([](const auto& col) { EXPECT_GE(col.capacity(), 100u); });
}

TEST(ParticleStore, PermuteMovesEveryColumn) {
    ParticleStore s = threeParticles();
    const ParticleStore before = s;
    const std::vector<std::uint32_t> order{2, 0, 1};
    s.permute(order);
    EXPECT_TRUE(s.consistent());
    for (std::size_t k = 0; k < order.size(); ++k) {
        EXPECT_EQ(s.id[k], before.id[order[k]]);
        EXPECT_EQ(s.x[k], before.x[order[k]]);
        EXPECT_EQ(s.vy[k], before.vy[order[k]]);
        EXPECT_EQ(s.torque[k], before.torque[order[k]]);
        EXPECT_EQ(s.invInertia[k], before.invInertia[order[k]]);
        EXPECT_EQ(s.material[k], before.material[order[k]]);
        EXPECT_EQ(s.shape[k], before.shape[order[k]]);
    }
}

TEST(ParticleStore, SaveWritesTheCheckpointLayout) {
    const ParticleStore s = threeParticles();
    std::ostringstream viaStore;
    s.save(viaStore);
    // The layout of the DEM checkpoints written before the visitor (dem::World::saveState).
    std::ostringstream legacy;
    for (const auto* col : {&s.x, &s.y, &s.vx, &s.vy, &s.angle, &s.omega, &s.fx, &s.fy, &s.torque, &s.radius,
                            &s.mass, &s.invMass, &s.invInertia})
        writeVector(legacy, *col);
    writeVector(legacy, s.material);
    writeVector(legacy, s.id);
    writeVector(legacy, s.shape);
    EXPECT_EQ(viaStore.str(), legacy.str());
}

TEST(ParticleStore, LoadRestoresBitForBit) {
    const ParticleStore s = threeParticles();
    std::stringstream buf;
    s.save(buf);
    ParticleStore r;
    r.load(buf);
    EXPECT_TRUE(r.consistent());
    std::ostringstream again;
    r.save(again);
    EXPECT_EQ(again.str(), buf.str());
    EXPECT_EQ(r.id, s.id);
    EXPECT_EQ(r.x, s.x);
}

TEST(ParticleStore, LoadRejectsATruncatedStream) {
    const ParticleStore s = threeParticles();
    std::ostringstream out;
    s.save(out);
    std::string bytes = out.str();
    bytes.resize(bytes.size() - 5);
    std::istringstream in(bytes);
    ParticleStore r;
    EXPECT_THROW(r.load(in), std::runtime_error);
}
