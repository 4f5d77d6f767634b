// Progeny: t10 and t_n model, the cumulative progeny distribution, fragment sizes with exact mass,
// fines; issue 3 test 2 (mean t10 and t_n over many events).
#include <gtest/gtest.h>

#include <boost/math/special_functions/beta.hpp>
#include <cmath>

#include "comminute/breakage/progeny/progeny_sizes.hpp"
#include "comminute/core/error.hpp"
#include "comminute/core/units.hpp"
#include "comminute/fracture/progeny_distribution.hpp"
#include "comminute/fracture/t10_model.hpp"

using namespace comminute;
using namespace comminute::breakage;
using namespace comminute::fracture;

namespace {
// Illustrative alpha_n, beta_n (a fit to a typical t-family curve, not published values).
T10Parameters illustrative() {
  T10Parameters p;
  p.a = 50.0;
  p.b_prime = 1.0;
  p.alpha = {0.975, 1.062, 0.918, 0.942, 0.929};
  p.beta = {2.667, 1.955, 0.393, 0.249, 0.183};
  return p;
}
double sphere_mass(double d, double rho) {
  return rho * units::pi / 6 * d * d * d;
}
}  // namespace

TEST(T10Model, FormulaAndIncompleteBeta) {
  T10Model m(illustrative());
  EXPECT_NEAR(m.t10(100.0, 100.0), 50.0 * (1 - std::exp(-1.0)), 1e-12);
  EXPECT_EQ(m.t10(0.0, 100.0), 0.0);
  const auto tn = m.tn(20.0);
  EXPECT_NEAR(tn[0], 100 * boost::math::ibeta(0.975, 2.667, 0.2), 1e-12);
  // The illustrative family is ordered t2 > t4 > t10 > t25 > t50 > t75.
  EXPECT_GT(tn[0], tn[1]);
  EXPECT_GT(tn[1], 20.0);
  EXPECT_GT(20.0, tn[2]);
  EXPECT_GT(tn[2], tn[3]);
  EXPECT_GT(tn[3], tn[4]);
}

TEST(ProgenyDistribution, PassesThroughPointsMonotoneWithPowerTail) {
  T10Model m(illustrative());
  const double d = 0.02, t10 = 25.0;
  const auto tn = m.tn(t10);
  ProgenyDistribution dist(d, t10, tn);
  EXPECT_NEAR(dist.passing(d / 2), tn[0], 1e-9);
  EXPECT_NEAR(dist.passing(d / 4), tn[1], 1e-9);
  EXPECT_NEAR(dist.passing(d / 10), t10, 1e-9);
  EXPECT_NEAR(dist.passing(d / 25), tn[2], 1e-9);
  EXPECT_NEAR(dist.passing(d / 75), tn[4], 1e-9);
  EXPECT_EQ(dist.passing(d), 100.0);
  double prev = 0;
  for (double x = d / 1000; x < d; x *= 1.01) {
    const double p = dist.passing(x);
    EXPECT_GE(p, prev - 1e-12) << x;
    prev = p;
  }
  // Power-law tail: the log-log slope below d/75 equals that between d/75 and d/50.
  const double m_tail = std::log(dist.passing(d / 75) / dist.passing(d / 300)) / std::log(4.0);
  EXPECT_NEAR(m_tail, std::log(tn[3] / tn[4]) / std::log(1.5), 1e-9);
}

TEST(ProgenySizes, MassClosesExactlyAndFinesAreKept) {
  T10Model m(illustrative());
  Rng rng(5, rng_stream::breakage);
  const double rho = 2700, d = 0.01, mass = sphere_mass(d, rho);
  for (FinesRule rule : {FinesRule::particles, FinesRule::mass})
    for (double t10 : {2.0, 15.0, 45.0}) {
      ProgenyDistribution dist(d, t10, m.tn(t10));
      for (int ev = 0; ev < 50; ++ev) {
        const Progeny pr = draw_progeny(dist, mass, rho, d / 20, rule, rng);
        double total = pr.fines_mass;
        for (const auto& f : pr.fragments) {
          total += f.mass;
          EXPECT_GT(f.mass, 0);
          EXPECT_LE(f.diameter, d * (1 + 1e-12));
          if (rule == FinesRule::particles && f.fines) {
            EXPECT_GE(f.diameter, d / 20 * (1 - 1e-12));  // fines particles at least the minimum
          }
        }
        // Mass closes to one rounding of the sum (1e-15 relative, ~5 ulps).
        EXPECT_NEAR(total, mass, 1e-15 * mass);
        if (rule == FinesRule::particles) {
          EXPECT_EQ(pr.fines_mass, 0.0);
        }
      }
    }
}

// Issue 8, point 5: a 10 mm parent with a 1 mm minimum has its last class [1, 1.25] mm, narrower
// than 2^(1/3); closing it with two equal halves gave fragments down to 0.99 mm. Every resolved
// fragment must now be at least the minimum (relative 1e-12: the last fragment's mass is the
// remainder of a sum, exact to rounding), and the mass still closes (1e-12 relative).
TEST(ProgenySizes, NoFragmentBelowTheMinimumSize) {
  const double d = 0.01, rho = 2700, min_size = 1e-3, mass = sphere_mass(d, rho);
  T10Model model(illustrative());
  Rng rng(11, 0);
  double smallest = d;
  for (double t10 : {10.0, 20.0, 35.0, 45.0})
    for (int k = 0; k < 400; ++k) {
      const ProgenyDistribution dist(d, t10, model.tn(t10));
      const Progeny pr = draw_progeny(dist, mass, rho, min_size, FinesRule::mass, rng);
      double sum = pr.fines_mass;
      for (const auto& f : pr.fragments) {
        sum += f.mass;
        smallest = std::min(smallest, f.diameter);
      }
      ASSERT_NEAR(sum, mass, 1e-12 * mass);
    }
  EXPECT_GE(smallest, min_size * (1 - 1e-12));
}

TEST(ProgenySizes, MinimumSizeAboveParentGivesAllFines) {
  T10Model m(illustrative());
  Rng rng(1);
  ProgenyDistribution dist(0.001, 20.0, m.tn(20.0));
  const Progeny pr = draw_progeny(dist, 1e-6, 2700, 0.002, FinesRule::mass, rng);
  EXPECT_TRUE(pr.fragments.empty());
  EXPECT_EQ(pr.fines_mass, 1e-6);
}

// A state no run makes (a checkpoint whose radius was corrupted to 1e180 m: the density is 0 and
// every fragment would weigh nothing) is refused with an Error instead of looping forever.
TEST(ProgenySizes, ParticleOfZeroDensityIsRefused) {
  T10Model m(illustrative());
  Rng rng(1);
  ProgenyDistribution dist(1e180, 20.0, m.tn(20.0));
  EXPECT_THROW(draw_progeny(dist, 1e-6, 0.0, 2e179, FinesRule::mass, rng), Error);
}

// Issue 3, test 2: over many events at energy E, the mean t10 measured on the drawn fragments
// (mass fraction finer than d/10, fines included) equals A[1 - exp(-b' E/E50)] within 2 %, and the
// measured t_n follow the incomplete-beta model. Tolerance: the class-filling sampler reproduces
// each class mass exactly except for mass passed on from classes too small for one fragment and
// the two-halves closure, both bounded by one fragment mass at a class edge; 2 % (the issue's
// bound) covers that. Observed agreement with this seed: better than 1e-4 relative.
TEST(ProgenySizes, MeanT10AndTnMatchTheModel) {
  T10Model m(illustrative());
  Rng rng(2024, rng_stream::breakage);
  const double rho = 2700, d = 0.01, mass = sphere_mass(d, rho), e50 = 150.0;
  for (double energy : {0.3 * e50, e50, 3.0 * e50}) {
    const double t10 = m.t10(energy, e50);
    const auto tn = m.tn(t10);
    ProgenyDistribution dist(d, t10, tn);
    const double n_sizes[] = {2, 4, 10, 25, 50, 75};
    const double model[] = {tn[0], tn[1], t10, tn[2], tn[3], tn[4]};
    double measured[6] = {};
    const int events = 100;
    for (int ev = 0; ev < events; ++ev) {
      const Progeny pr = draw_progeny(dist, mass, rho, d / 100, FinesRule::mass, rng);
      for (int k = 0; k < 6; ++k) {
        double passing = pr.fines_mass;
        for (const auto& f : pr.fragments)
          if (f.diameter <= d / n_sizes[k]) passing += f.mass;
        measured[k] += 100.0 * passing / mass / events;
      }
    }
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(measured[k], model[k], 0.02 * model[k])
          << "E/E50 " << energy / e50 << " n " << n_sizes[k];
  }
}
