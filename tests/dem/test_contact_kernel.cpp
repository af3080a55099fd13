// SPDX-License-Identifier: MIT
// Unit tests of the per-contact law kernel: Coulomb cap, history reset, restitution mapping.
#include <gtest/gtest.h>

#include "dem/contact/kernel.hpp"

using namespace granulab;
using namespace granulab::dem;

TEST(ContactKernel, CoulombCapHolds) {
    ResolvedLaw<HookeNormal, NoDamping, CundallStrack> law{{1e5}, {}, {2e4, 0, 0, 0.5}, false, {}};
    Real xi = 0, zeta = 0;
    for (int k = 0; k < 1000; ++k) {
        const ContactForce f = evaluateContact(law, {1e-3, 0, 1.0, 1.0, 1e-4, 0.5, 0, 0}, xi, zeta);
        EXPECT_LE(std::abs(f.ft), 0.5 * std::abs(f.fn) * (1 + 1e-12));
    }
    // After sliding, the spring holds exactly the capped force.
    EXPECT_NEAR(2e4 * std::abs(xi), 0.5 * 1e5 * 1e-3, 1e-9);
}

TEST(ContactKernel, RestitutionMappingIsMonotone) {
    EXPECT_DOUBLE_EQ(linearDampingRatio(1.0), 0.0);
    EXPECT_DOUBLE_EQ(linearDampingRatio(0.0), 1.0);
    Real prev = 0;
    for (Real e = 0.99; e > 0.01; e -= 0.01) {
        const Real b = linearDampingRatio(e);
        EXPECT_GT(b, prev);
        prev = b;
    }
}

TEST(ContactKernel, ClipAttractionNeverPulls) {
    ResolvedLaw<HookeNormal, ViscousDamping, NoFriction> law{{1e5}, {100}, {}, true, {}};
    Real xi = 0, zeta = 0;
    const ContactForce f = evaluateContact(law, {1e-6, -10.0, 0, 1.0, 0, 0.5, 0, 0}, xi, zeta);
    EXPECT_EQ(f.fn, 0.0);
}
