// SizeDistribution: bases (number, volume, mass), forms (fraction, density, cumulative).
#include <gtest/gtest.h>

#include <cmath>

#include "comminute/analysis/size_distribution.hpp"

using namespace comminute::analysis;

TEST(SizeDistribution, ConvertsBasesAndForms) {
  // Three classes of particles of 1, 8 and 27 µm³ (sizes 1, 2, 3 µm with k_v = 1), 6, 3 and 1
  // particles, density 2000 kg/m³: volumes 6, 24, 27 µm³ (total 57).
  const double um3 = 1e-18;
  const SizeDistribution d({0.5e-6, 1.5e-6, 2.5e-6, 3.5e-6}, {1 * um3, 8 * um3, 27 * um3},
                           {6, 3, 1}, 2000);
  const auto nf = d.fractions(Basis::number), vf = d.fractions(Basis::volume),
             mf = d.fractions(Basis::mass);
  EXPECT_DOUBLE_EQ(nf[0], 0.6);
  EXPECT_NEAR(vf[1], 24.0 / 57, 1e-15);
  EXPECT_NEAR(mf[2], 27.0 / 57, 1e-15);  // one density: mass and volume fractions coincide
  EXPECT_NEAR(d.total(Basis::mass), 2000 * 57 * um3, 1e-27);
  const auto dens = d.density(Basis::number);  // fraction per metre of size (widths 1 µm)
  EXPECT_NEAR(dens[1], 0.3 / 1e-6, 1e-6);
  const auto c = d.cumulative(Basis::volume);
  EXPECT_NEAR(c[0], 6.0 / 57, 1e-15);
  EXPECT_NEAR(c[2], 1.0, 1e-15);
  // Between edges the cumulative is linear in ln d: at the geometric mean of 1.5 and 2.5 µm it
  // is halfway between the passing values at those edges, 6/57 and 30/57.
  EXPECT_NEAR(d.cumulative_at(std::sqrt(1.5e-6 * 2.5e-6), Basis::volume), 18.0 / 57, 1e-14);
  EXPECT_EQ(d.cumulative_at(0.1e-6, Basis::mass), 0.0);
  EXPECT_EQ(d.cumulative_at(9e-6, Basis::mass), 1.0);
}
