// The comminution physics shared by DEM breakage and the population balance (src/comminute/
// fracture): fracture-energy distribution, size effect, energy partition, damage, Rayleigh time.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "comminute/core/error.hpp"
#include "comminute/core/units.hpp"
#include "comminute/fracture/damage.hpp"
#include "comminute/fracture/energy_share.hpp"
#include "comminute/fracture/fracture_energy_distribution.hpp"
#include "comminute/fracture/rayleigh_time.hpp"
#include "comminute/fracture/size_effect.hpp"

using namespace comminute;
using namespace comminute::fracture;

namespace {
const double inf = std::numeric_limits<double>::infinity();
}  // namespace

TEST(FractureEnergy, CdfMatchesOracleTable) {
  // Reference values computed independently (docs/models.md eq. F1), sigma = 0.8, E in units of
  // E50 (printed to 6 digits).
  const double e[] = {0.10, 0.25, 0.50, 1.00, 2.00, 4.00};
  const double p5[] = {0.002166, 0.047583, 0.231251, 0.609851, 0.933834, 0.999910};
  const double p10[] = {0.002081, 0.044451, 0.211185, 0.552389, 0.873971, 0.991140};
  const double pinf[] = {0.002000, 0.041560, 0.193126, 0.500000, 0.806874, 0.958440};
  FractureEnergyDistribution d5(1.0, 0.8, 5.0), d10(1.0, 0.8, 10.0), dinf(1.0, 0.8, inf);
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(d5.cdf(e[k]), p5[k], 1e-6);
    EXPECT_NEAR(d10.cdf(e[k]), p10[k], 1e-6);
    EXPECT_NEAR(dinf.cdf(e[k]), pinf[k], 1e-6);
  }
}

TEST(FractureEnergy, QuantileInvertsCdfAndMedianIsReported) {
  FractureEnergyDistribution d(200.0, 0.7, 5.0);
  for (double u : {1e-6, 0.01, 0.3, 0.5, 0.77, 0.999999})
    EXPECT_NEAR(d.cdf(d.quantile(u)), u, 1e-12);
  // The unstarred form: the median is E50 Emax/(Emax + E50) = 200*1000/1200 (docs/models.md).
  EXPECT_NEAR(d.median(), 200.0 * 1000.0 / 1200.0, 1e-9);
  EXPECT_LT(d.quantile(0.999999), d.emax());
}

TEST(FractureEnergy, SizeEffectOracle) {
  // Hand-computed eq. F3: E_inf = 100 J/kg, d0 = 10 mm, phi = 1.
  SizeEffect s{100.0, 0.010, 1.0, 1.0};
  const double d[] = {1, 2, 5, 10, 20, 50, 100};
  const double e50[] = {1100, 600, 300, 200, 150, 120, 110};
  for (int k = 0; k < 7; ++k) EXPECT_NEAR(s.e50(d[k] * 1e-3), e50[k], 1e-9);
}

TEST(FractureEnergy, EnergyShareOracle) {
  // Hand-computed eq. F4-F5: a 70 GPa and a 30 GPa ore against steel, and two equal bodies.
  const double ks = plane_strain_modulus(210e9, 0.30);
  EXPECT_NEAR(energy_share(plane_strain_modulus(70e9, 0.25), ks), 0.755541, 1e-6);
  EXPECT_NEAR(energy_share(plane_strain_modulus(30e9, 0.25), ks), 0.878220, 1e-6);
  EXPECT_DOUBLE_EQ(energy_share(plane_strain_modulus(70e9, 0.25), plane_strain_modulus(70e9, 0.25)),
                   0.5);
}

// One damage law for the DEM criterion and the UFRJ mill: the check values and edge rules both
// relied on (their two former tests merged; the tighter tolerance kept).
TEST(Damage, CheckValuesAndEdgeRules) {
  // Check values of eq. D1 (docs/models.md "Damage"), 6 decimals quoted: tolerance half a unit in
  // the last place.
  EXPECT_NEAR(tavares_king_damage(2, 0.5), 0.358610, 0.5e-6);
  EXPECT_NEAR(tavares_king_damage(3, 0.3), 0.122009, 0.5e-6);
  EXPECT_NEAR(tavares_king_damage(5, 0.9), 0.531877, 0.5e-6);
  EXPECT_NEAR(tavares_king_damage(7, 0.99), 0.805857, 0.5e-6);
  EXPECT_EQ(tavares_king_damage(4, 0.0), 0.0);
  EXPECT_EQ(tavares_king_damage(5, 0.0), 0.0);
  EXPECT_LT(tavares_king_damage(5, 1e-3), 1e-5);  // D -> 0 as E_k/E -> 0
  EXPECT_THROW(tavares_king_damage(4, 1.0), Error);
}

TEST(Damage, RootSatisfiesTheEquation) {
  for (double g : {1.0, 2.5, 6.0})
    for (double r : {0.05, 0.5, 0.95}) {
      const double d = tavares_king_damage(g, r);
      EXPECT_NEAR(d, std::pow(2 * g / (2 * g - 5 * d + 5) * r, 2 * g / 5), 1e-12);
    }
}

TEST(SizeEffect, ZeroLengthSwitchesItOff) {
  for (double phi : {0.0, 0.5, 1.0}) EXPECT_EQ((SizeEffect{100.0, 0.0, phi, 0.5}.e50(1e-3)), 50.0);
}

TEST(RayleighTime, OfAQuartzLikeSphere) {
  // d = 2 mm, rho = 2650, E = 70 GPa, nu = 0.25: G = 28 GPa.
  const double g = 70e9 / (2 * 1.25);
  EXPECT_NEAR(rayleigh_time(2e-3, 2650, g, 0.25),
              units::pi * 1e-3 * std::sqrt(2650 / g) / (0.1631 * 0.25 + 0.8766), 1e-20);
  EXPECT_NEAR(rayleigh_time(2e-3, 2650, g, 0.25), 1.0535e-6, 0.0001e-6);
}
