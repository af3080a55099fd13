// SPDX-License-Identifier: MIT
// Displacement, strain and plane-strain elastic constants (gc2d spec section 7 item 10,
// Eq. 4.2-4.5, 4.11) on a homogeneous affine deformation with a known stress.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/dem_strain.hpp"
#include "dem_lattice.hpp"

namespace granulab {
namespace {

TEST(DemStrain, AffineDeformationGivesBackNuAndE) {
    const Real E = 1.5e5, nu = 0.3, exx = 1e-3, ezz = 3e-3;  // [N/m], [1], compressive strains
    const Real lam = E / ((1 + nu) * (1 - 2 * nu));
    const Real sxx = lam * ((1 - nu) * exx + nu * ezz), szz = lam * ((1 - nu) * ezz + nu * exx);
    // Loaded grains on a square lattice of spacing a; the reference state is stretched back:
    // x_ref = x + (exx x, ezz y), so u = x_ref - x = (exx x, ezz y).
    const Real a = 1e-3;
    analysis::GrainFrame loaded, reference;
    for (int j = 0; j < 40; ++j)
        for (int i = 0; i < 40; ++i) {
            const Real x = (i + 0.5) * a, y = (j + 0.5) * a;
            test::addDisk(loaded, x, y, 0.5 * a, 1);
            test::addDisk(reference, x * (1 + exx), y * (1 + ezz), 0.5 * a, 1);
        }
    std::swap(reference.x[0], reference.x[1]);  // ids, not order, match the grains
    std::swap(reference.y[0], reference.y[1]);
    std::swap(reference.id[0], reference.id[1]);
    analysis::StressGrid s;
    s.grid = {0, 0, 8 * a, 8 * a, 4 * a, 4 * a, 9, 9};
    s.sigmaXx.assign(s.grid.count(), sxx);
    s.sigmaZz.assign(s.grid.count(), szz);
    const analysis::StrainGrid st = analysis::strainGrid(reference, loaded, s);
    std::size_t interior = 0;
    for (std::size_t j = 0; j < s.grid.ny; ++j)
        for (std::size_t i = 0; i < s.grid.nx; ++i) {
            const std::size_t k = s.grid.index(i, j);
            EXPECT_NEAR(st.ux[k], exx * s.grid.centre(k).x, 1e-15);
            if (i == 0 || j == 0 || i + 1 == s.grid.nx || j + 1 == s.grid.ny) {
                EXPECT_TRUE(std::isnan(st.nu[k]));
                continue;
            }
            ++interior;
            EXPECT_NEAR(st.uxx[k], exx, 1e-12);
            EXPECT_NEAR(st.uzz[k], ezz, 1e-12);
            EXPECT_NEAR(st.nu[k], nu, 1e-9);
            EXPECT_NEAR(st.E[k] / E, 1, 1e-9);
            EXPECT_NEAR(st.K[k] / (E / (2 * (1 + nu) * (1 - 2 * nu))), 1, 1e-9);
        }
    EXPECT_EQ(interior, 49u);
    EXPECT_NEAR(st.nuMean, nu, 1e-9);
    EXPECT_NEAR(st.EMean / E, 1, 1e-9);
    const analysis::Table t = analysis::strainTable(st, s);
    EXPECT_EQ(t.name, "elastic");
    ASSERT_EQ(t.columns.size(), 11u);
    EXPECT_EQ(t.columns[8].name, "nu");
    EXPECT_EQ(t.notes[0].rfind("nu_avg = 0.3 +- ", 0), 0u) << t.notes[0];
}

TEST(DemStrain, RejectsMismatchedStressGrid) {
    analysis::GrainFrame f;
    test::addDisk(f, 0, 0, 1, 1);
    analysis::StressGrid s;
    s.grid = {0, 0, 1, 1, 1, 1, 2, 2};
    EXPECT_THROW(analysis::strainGrid(f, f, s), std::invalid_argument);
}

}  // namespace
}  // namespace granulab
