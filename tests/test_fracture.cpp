// The comminution physics shared by DEM breakage and the population balance (src/comminute/
// fracture): fracture-energy distribution, size effect, energy partition, damage, Rayleigh time.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "comminute/core/error.hpp"
#include "comminute/core/units.hpp"
#include "comminute/fracture/breaking_median.hpp"
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
// rely on, for both forms of eq. D1.
TEST(Damage, CheckValuesAndEdgeRules) {
  const auto with = DamageForm::one_minus_d, without = DamageForm::no_factor;
  // Check values of eq. D1 (docs/models.md "Damage"), 6 decimals quoted: tolerance half a unit in
  // the last place. Each was confirmed independently by the explicit inverse r(D) below.
  EXPECT_NEAR(tavares_king_damage(2, 0.5, with), 0.266353, 0.5e-6);
  EXPECT_NEAR(tavares_king_damage(3, 0.3, with), 0.105705, 0.5e-6);
  EXPECT_NEAR(tavares_king_damage(5, 0.9, with), 0.243862, 0.5e-6);  // issue 8: 0.244
  EXPECT_NEAR(tavares_king_damage(7, 0.99, with), 0.234109, 0.5e-6);
  EXPECT_NEAR(tavares_king_damage(2, 0.5, without), 0.358610, 0.5e-6);
  EXPECT_NEAR(tavares_king_damage(3, 0.3, without), 0.122009, 0.5e-6);
  EXPECT_NEAR(tavares_king_damage(5, 0.9, without), 0.531877, 0.5e-6);  // issue 8: 0.532
  EXPECT_NEAR(tavares_king_damage(7, 0.99, without), 0.805857, 0.5e-6);
  for (auto form : {with, without}) {
    EXPECT_EQ(tavares_king_damage(4, 0.0, form), 0.0);
    EXPECT_EQ(tavares_king_damage(5, 0.0, form), 0.0);
    EXPECT_LT(tavares_king_damage(5, 1e-3, form), 1e-5);  // D -> 0 as E_k/E -> 0
    EXPECT_THROW(tavares_king_damage(4, 1.0, form), Error);
  }
  EXPECT_EQ(read_damage_law(CaseFile::parse("").root()).form, with);  // the default form
}

// Independent check without any iteration: each form solved for r gives r(D) explicitly,
//   one_minus_d: r = D^(5/(2g)) (2g - 5D + 5) / (2g (1 - D)),
//   no_factor:   r = D^(5/(2g)) (2g - 5D + 5) / (2g),
// so the library must return D for r(D). For no_factor D is taken on the rising branch of r(D)
// (dr/dD > 0), where it is the smallest root. Tolerance 1e-12: bisection and fixed point stop at
// 1e-15, and r(D) is well conditioned away from r -> 1.
TEST(Damage, BothFormsInvertTheExplicitEnergyRatio) {
  for (double g : {1.0, 2.5, 5.0, 6.0}) {
    const double a = 5.0 / (2 * g);
    for (double d : {1e-4, 0.05, 0.2, 0.35}) {
      const double r1 = std::pow(d, a) * (2 * g - 5 * d + 5) / (2 * g * (1 - d));
      if (r1 < 1) {
        EXPECT_NEAR(tavares_king_damage(g, r1, DamageForm::one_minus_d), d, 1e-12)
            << "g " << g << " D " << d;
      }
      const double r2 = std::pow(d, a) * (2 * g - 5 * d + 5) / (2 * g);
      const double slope = a * std::pow(d, a - 1) * (2 * g - 5 * d + 5) - 5 * std::pow(d, a);
      if (r2 < 1 && slope > 0) {
        EXPECT_NEAR(tavares_king_damage(g, r2, DamageForm::no_factor), d, 1e-12)
            << "g " << g << " D " << d;
      }
    }
  }
}

// Issue 8, point 2: E50b, the median fracture energy of the particles that break at E (eq. P1b).
// For the plain lognormal P(E) = 1/2 erfc(-ln(E/E50) / (sqrt2 sigma)); the test solves
// P(E') = P(E)/2 by its own bisection in ln E' (no use of the library's quantile) and compares.
// Tolerance 1e-9 relative: the bisection runs to 1e-13 in ln E', the library's inverse erf is
// accurate to a few ulps.
TEST(BreakingMedian, TruncatedMedianOfThePlainLognormal) {
  const double e50 = 100.0, sigma = 0.8;
  const FractureEnergyDistribution dist(e50, sigma, inf);
  auto p = [&](double e) { return 0.5 * std::erfc(-std::log(e / e50) / (std::sqrt(2.0) * sigma)); };
  for (double ratio : {0.2, 0.5, 1.0, 2.0, 5.0}) {
    const double e = ratio * e50, target = p(e) / 2;
    double lo = std::log(e50) - 20 * sigma, hi = std::log(e);
    while (hi - lo > 1e-13) {
      const double mid = 0.5 * (lo + hi);
      (p(std::exp(mid)) < target ? lo : hi) = mid;
    }
    const double expect = std::exp(0.5 * (lo + hi));
    EXPECT_NEAR(breaking_median(dist, e), expect, 1e-9 * expect) << "E/E50 " << ratio;
    EXPECT_LT(breaking_median(dist, e), e);  // the particles that break are weaker than E
  }
  // E = E50: P = 1/2, so E50b is the lower quartile, E50 exp(sigma z_0.25), z_0.25 = -0.6744898.
  EXPECT_NEAR(breaking_median(dist, e50), e50 * std::exp(-0.6744897501960817 * sigma), 1e-9 * e50);
  // Far above E50 every particle breaks: E50b -> E50 (P(20 E50) = 1 - 9e-5 for sigma = 0.8).
  EXPECT_NEAR(breaking_median(dist, 1e4 * e50), e50, 1e-9 * e50);
  // Truncated at Emax = 5 E50: at and above Emax E50b is the distribution's median.
  const FractureEnergyDistribution trunc(e50, sigma, 5.0);
  EXPECT_DOUBLE_EQ(breaking_median(trunc, 5 * e50), trunc.median());
  EXPECT_DOUBLE_EQ(breaking_median(trunc, 7 * e50), trunc.median());
  // The class rule gives the E50 parameter whatever E.
  EXPECT_EQ(t10_median_energy(dist, 0.3 * e50, E50bRule::class_median), e50);
  EXPECT_EQ(t10_median_energy(dist, 0.3 * e50, E50bRule::breaking),
            breaking_median(dist, 0.3 * e50));
  EXPECT_EQ(read_e50b_rule(CaseFile::parse("").root()), E50bRule::breaking);  // the default
  EXPECT_EQ(read_e50b_rule(CaseFile::parse("e50b = \"class\"").root()), E50bRule::class_median);
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
