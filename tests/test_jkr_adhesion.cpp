// Issue 8, point 8: JKR adhesion against the analytic JKR curve and pull-off force (Johnson,
// Kendall & Roberts, Proc. R. Soc. Lond. A 324 (1971) 301).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "comminute/contact/cohesion.hpp"
#include "comminute/contact/jkr_curve.hpp"
#include "comminute/core/error.hpp"
#include "comminute/core/units.hpp"

using namespace comminute;

namespace {
// A 10 um particle pair (R* = 5 um), E* = 1 GPa, Gamma = 0.27 J/m^2 (the mixer study's particles).
const double kR = 5e-6, kE = 1e9, kW = 0.27;
const double pi = units::pi;
// The curve written parametrically in the contact radius a (no root finding).
double delta_of(double a) {
  return a * a / kR - std::sqrt(2 * pi * kW * a / kE);
}
double force_of(double a) {
  return 4 * kE * a * a * a / (3 * kR) - std::sqrt(8 * pi * kW * kE * a * a * a);
}
}  // namespace

// For contact radii on the stable branch (a > a_c, a_c^3 = pi Gamma R*^2 / (8 E*)), at positive
// and negative overlap, the library's inverse returns a and F. Tolerance 1e-9 relative: Newton
// stops at 1e-15 in sqrt(a); near a_c the branch is flat and a is less well conditioned.
TEST(Jkr, ForceOverlapCurve) {
  const double ac = std::cbrt(pi * kW * kR * kR / (8 * kE));
  for (double m : {1.05, 1.3, 2.0, 3.0, 5.0, 20.0}) {
    const double a = m * ac;
    const JkrPoint pt = jkr_point(delta_of(a), kR, kE, kW);
    EXPECT_NEAR(pt.contact_radius, a, 1e-9 * a) << "a/a_c " << m;
    EXPECT_NEAR(pt.force, force_of(a), 1e-9 * std::abs(force_of(a)) + 1e-15) << "a/a_c " << m;
  }
  // Beyond the separation overlap -3 a_c^2/R* there is no contact.
  EXPECT_EQ(jkr_point(-3.01 * ac * ac / kR, kR, kE, kW).force, 0.0);
}

// Pull-off under load control: the most negative force on the curve is -1.5 pi Gamma R*, at
// a^3 = 9 pi Gamma R*^2 / (8 E*); at zero overlap the curve gives -4/3 pi Gamma R*. A scan of the
// overlap over the stable branch finds no force below the pull-off force (1e-9 relative).
TEST(Jkr, PullOffForce) {
  const double pull = 1.5 * pi * kW * kR;
  const double ap = std::cbrt(9 * pi * kW * kR * kR / (8 * kE));
  EXPECT_NEAR(jkr_point(-ap * ap / (3 * kR), kR, kE, kW).force, -pull, 1e-9 * pull);
  EXPECT_NEAR(jkr_point(0.0, kR, kE, kW).force, -4.0 / 3.0 * pi * kW * kR, 1e-9 * pull);
  const double ac = std::cbrt(pi * kW * kR * kR / (8 * kE));
  double lowest = 0;
  for (int k = 0; k <= 2000; ++k) {
    const double d = -3 * ac * ac / kR * (1 - k / 1000.0);
    lowest = std::min(lowest, jkr_point(d, kR, kE, kW).force);
  }
  EXPECT_GE(lowest, -pull * (1 + 1e-9));
  EXPECT_LT(lowest, -pull * (1 - 1e-5));  // the scan's step resolves the minimum to 1e-5
}

// The registered model "jkr" adds to the law's Hertz force what makes the total the JKR curve, and
// books the energy of the curve from zero overlap (trapezoid integration of F, 1e-6 relative).
TEST(Jkr, CohesionModelCompletesHertzToTheCurve) {
  const CaseFile f = CaseFile::parse("model = \"hertz_mindlin\"\n");
  const auto model = CohesionRegistry::create("jkr", f.root());
  PairParameters p;
  p.effective_modulus = kE;
  p.surface_energy = kW;
  const double a0 = std::cbrt(2 * pi * kW * kR * kR / kE);  // a at zero overlap
  for (double m : {1.2, 2.0, 4.0}) {
    const double a = m * a0, delta = delta_of(a);
    ContactKinematics k;
    k.overlap = delta;
    k.effective_radius = kR;
    ContactForces out;
    const double hertz = 4.0 / 3.0 * kE * std::sqrt(kR) * std::pow(delta, 1.5);
    out.normal_force = hertz;
    out.stored_energy = 0.4 * hertz * delta;
    model->compute(k, p, out);
    EXPECT_NEAR(out.normal_force, force_of(a), 1e-9 * std::abs(force_of(a)) + 1e-15);
    double work = 0;
    const int n = 20000;
    for (int s = 0; s < n; ++s) {
      const double d0 = delta * s / n, d1 = delta * (s + 1) / n;
      work += 0.5 * (jkr_point(d0, kR, kE, kW).force + jkr_point(d1, kR, kE, kW).force) * (d1 - d0);
    }
    EXPECT_NEAR(out.stored_energy, work, 1e-6 * std::abs(work) + 1e-22);
  }
  EXPECT_THROW(CohesionRegistry::create(
                   "jkr", CaseFile::parse("model = \"linear_spring_dashpot\"\n").root()),
               InputError);
}
