// Bond laws against their closed forms: the bilinear cohesive law of Camanho & Dávila with
// Benzeggagh–Kenane mixing (a published check value and hand-derived numbers), and the parallel
// bond of Potyondy & Cundall (2004) (stiffness, failure stress, stored moment turning with it).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "comminute/bonds/bond_law.hpp"
#include "comminute/bonds/mixed_mode.hpp"

using namespace comminute;
using namespace comminute::bonds;

namespace {

// Radius multiplier 1/√π on unit spheres: bond area A = 1 m², so traction = force.
const std::string kUnitArea = "radius_multiplier = 0.5641895835477563\n";

const std::string kCohesive = kUnitArea +
                              "penalty_stiffness = 1e4\nnormal_strength = 100\n"
                              "shear_strength = 100\nmode_I_toughness = 1e3\n"
                              "mode_II_toughness = 2e3\nbk_exponent = 2\n";

std::unique_ptr<BondLaw> make_law(const std::string& name, const std::string& text) {
  const CaseFile f = CaseFile::parse(text);
  auto law = BondLawRegistry::create(name, f.root());
  f.reject_unknown();
  return law;
}

BondState make_bond(const BondLaw& law) {
  Rng rng(1, 7);
  return law.create(1.0, 1.0, 2.0, {1, 0, 0}, rng);
}

// Opening dn and slip ds (along y) set from the bond's start: the slip increment is the change.
BondLoad move_to(const BondLaw& law, BondState& s, double dn, double ds) {
  BondMotion m;
  m.normal = {1, 0, 0};
  m.length = 2.0 + dn;
  m.slip_increment = Vec3{0, ds, 0} - s.slip;
  return law.update(s, m);
}

}  // namespace

TEST(BondLaws, CohesiveModeOneCheckValue) {
  auto law = make_law("bilinear_cohesive", kCohesive);
  BondState s = make_bond(*law);
  const BondLoad load = move_to(*law, s, 0.02, 0.0);
  // NEML2's unit test of BiLinearMixedModeTraction; the law is closed form, so only rounding.
  EXPECT_NEAR(s.damage, 0.5002501250625313, 1e-13);
  EXPECT_NEAR(-load.force.x, 99.94997498749373, 1e-10);
  EXPECT_EQ(s.failed, FailureMode::none);
}

TEST(BondLaws, CohesiveTractionSeparationPathEnergyAndUnloading) {
  auto law = make_law("bilinear_cohesive", kCohesive);
  BondState s = make_bond(*law);
  const double K = 1e4, N = 100, d0 = N / K, df = 2 * 1e3 / N;  // δ0 = 0.01, δf = 20
  const int steps = 40000;
  double reload_check_d = -1;
  for (int k = 1; k <= steps; ++k) {
    const double dn = 1.001 * df * k / steps;
    const BondLoad load = move_to(*law, s, dn, 0.0);
    if (s.failed != FailureMode::none) {
      EXPECT_GE(dn, df * (1 - 1e-12));  // fails only once δ reaches δf
      break;
    }
    const double t = -load.force.x;
    // the bilinear path: elastic rise K δ to N at δ0, then linear softening to 0 at δf
    const double expected = dn <= d0 ? K * dn : N * (df - dn) / (df - d0);
    ASSERT_NEAR(t, expected, 1e-9 * N) << "at opening " << dn;
    if (k == steps / 4) {
      // unloading before full damage is elastic with (1 - d) K, and damage does not change
      reload_check_d = s.damage;
      for (double back : {0.75, 0.5, 0.1}) {
        const BondLoad u = move_to(*law, s, back * dn, 0.0);
        EXPECT_DOUBLE_EQ(s.damage, reload_check_d);
        EXPECT_NEAR(-u.force.x, (1 - reload_check_d) * K * back * dn, 1e-9 * N);
      }
      // compression is never damaged: the full penalty stiffness pushes back
      const BondLoad c = move_to(*law, s, -0.001, 0.0);
      EXPECT_NEAR(-c.force.x, -K * 0.001, 1e-9);
      EXPECT_DOUBLE_EQ(s.damage, reload_check_d);
    }
  }
  ASSERT_EQ(s.failed, FailureMode::tensile);
  EXPECT_DOUBLE_EQ(s.damage, 1.0);
  EXPECT_GT(reload_check_d, 0.4);
  // G_Ic A with A = 1 m²; the dissipation is booked exactly along a fixed mode, so the 1 %
  // the issue allows is far wider than the rounding it has to cover
  EXPECT_NEAR(s.dissipated, 1e3, 1e-2 * 1e3);
  EXPECT_NEAR(s.dissipated, 1e3, 1e-8 * 1e3);
  EXPECT_EQ(s.strain_energy, 0.0);
  // a failed bond carries nothing
  const BondLoad after = move_to(*law, s, 0.0, 0.0);
  EXPECT_EQ(after.force, Vec3{});
}

TEST(BondLaws, BenzeggaghKenaneMixedMode) {
  CohesiveParameters p{1e4, 100, 150, 1e3, 2e3, 2};
  // β = 1: hand-computed in the reference notes (max-stress initiation)
  const MixedMode m = mixed_mode(p, 0.02, 0.02);
  EXPECT_NEAR(m.onset, 0.0141421, 1e-7);  // six digits as printed in the notes
  EXPECT_NEAR(m.toughness, 1250, 1e-9);
  EXPECT_NEAR(m.final, 17.6777, 1e-4);
  EXPECT_EQ(bilinear_damage(mixed_mode(p, 0.009, 0.009)), 0.0);  // below the onset
  const MixedMode twice = mixed_mode(p, 0.02, 0.02);             // δ_m = 2 δ_m0
  EXPECT_NEAR(bilinear_damage(twice), 0.500400, 1e-6);
  // β = 2: B = β²/(1+β²) = 0.8; G_c = G_Ic + (G_IIc - G_Ic) B^η = 1000 + 1000 · 0.64
  const MixedMode two = mixed_mode(p, 0.01, 0.02);
  EXPECT_NEAR(two.shear_ratio, 0.8, 1e-15);
  EXPECT_NEAR(two.toughness, 1640, 1e-9);
  // onset: the shear strength is reached first, δ_m0 = δ_s0 √(1+β²)/β = 0.015 √5 / 2
  EXPECT_NEAR(two.onset, 0.015 * std::sqrt(5.0) / 2, 1e-15);
  // pure shear and compression: B = 1, G_c = G_IIc, δ_m0 = S/K
  const MixedMode shear = mixed_mode(p, -0.01, 0.02);
  EXPECT_EQ(shear.shear_ratio, 1.0);
  EXPECT_NEAR(shear.toughness, 2e3, 1e-9);
  EXPECT_NEAR(shear.onset, 0.015, 1e-15);
}

TEST(BondLaws, CohesiveMixedModePathDissipatesBenzeggaghKenaneToughness) {
  auto law = make_law("bilinear_cohesive", kCohesive);
  BondState s = make_bond(*law);
  // opening and slip grow together at β = 2: G_c = 1000 + 1000 (4/5)² = 1640 J/m²
  const int steps = 20000;
  for (int k = 1; k <= steps && s.failed == FailureMode::none; ++k) {
    const double a = 20.0 * k / steps;
    move_to(*law, s, a, 2 * a);
  }
  ASSERT_EQ(s.failed, FailureMode::shear);  // B = 0.8 > 0.5: shear dominated
  // exact along a fixed mode ratio; 1 % as the issue asks
  EXPECT_NEAR(s.dissipated, 1640, 1e-2 * 1640);
}

namespace {
const std::string kParallel = kUnitArea +
                              "normal_stiffness = 1e6\nshear_stiffness = 4e5\n"
                              "tensile_strength = 1e3\nshear_strength = 2e3\n";
}

TEST(BondLaws, ParallelBondFailsInTensionAtItsStrength) {
  auto law = make_law("parallel_bond", kParallel);
  BondState s = make_bond(*law);
  const double kn = 1e6, sigma_c = 1e3;  // A = 1: σ = kn δ, fails at δ = 1e-3
  double last_intact = 0;
  for (int k = 1; k <= 2000; ++k) {
    const double dn = 1e-6 * (k - 0.5);  // σ_c never falls on a step
    BondMotion m;
    m.normal = {1, 0, 0};
    m.length = 2.0 + dn;
    const BondLoad load = law->update(s, m);
    if (s.failed != FailureMode::none) break;
    EXPECT_NEAR(-load.force.x, kn * dn, 1e-9);
    last_intact = dn;
  }
  ASSERT_EQ(s.failed, FailureMode::tensile);
  // the last intact opening is half a step (1e-6) below σ_c / kn = 1e-3
  EXPECT_NEAR(last_intact, sigma_c / kn - 0.5e-6, 1e-12);
  // the strain energy ½ kn A δ² of the failing step is released and booked as dissipated
  EXPECT_NEAR(s.dissipated, 0.5 * kn * 1.0005e-3 * 1.0005e-3, 1e-12);
}

namespace {

// Turns j relative to i about `axis` by steps of `dtheta` until the bond fails; returns the
// angle reached and checks the moment k I θ on the way (k I: the bond's stiffness to it).
double turn_until_failure(const BondLaw& law, BondState& s, const Vec3& axis, double dtheta,
                          double k_inertia) {
  double theta = 0;
  while (s.failed == FailureMode::none) {
    BondMotion m;
    m.normal = {1, 0, 0};
    m.length = 2.0;
    m.rotation_increment = dtheta * axis;
    const BondLoad load = law.update(s, m);
    theta += dtheta;
    if (s.failed == FailureMode::none) {
      EXPECT_NEAR(dot(load.moment, axis), -k_inertia * theta, 1e-9 * k_inertia * theta);
    }
  }
  return theta;
}

}  // namespace

TEST(BondLaws, ParallelBondBendingAndTwistFailAtTheirStresses) {
  auto law = make_law("parallel_bond", kParallel);
  const double r = 0.5641895835477563, inertia = std::numbers::pi * std::pow(r, 4) / 4;
  const double kn = 1e6, ks = 4e5;
  // bending: M = kn I θ; σ = |M| R̄/I = kn R̄ θ reaches σ_c = 1e3 at θ = σ_c/(kn R̄)
  BondState bent = make_bond(*law);
  const double bend_fail = 1e3 / (kn * r), dbend = bend_fail / 1000.5;
  const double bend = turn_until_failure(*law, bent, {0, 1, 0}, dbend, kn * inertia);
  EXPECT_EQ(bent.failed, FailureMode::tensile);
  EXPECT_NEAR(bend, bend_fail, dbend);  // within the step that crossed it
  // twist: M = ks J θ; τ = |M_n| R̄/J = ks R̄ θ reaches τ_c = 2e3 at θ = τ_c/(ks R̄)
  BondState twisted = make_bond(*law);
  const double twist_fail = 2e3 / (ks * r), dtwist = twist_fail / 1000.5;
  const double twist = turn_until_failure(*law, twisted, {1, 0, 0}, dtwist, ks * 2 * inertia);
  EXPECT_EQ(twisted.failed, FailureMode::shear);
  EXPECT_NEAR(twist, twist_fail, dtwist);
}

TEST(BondLaws, ParallelBondStoredMomentTurnsWithTheBond) {
  auto law = make_law("parallel_bond", kParallel);
  BondState s = make_bond(*law);
  BondMotion m;
  m.normal = {1, 0, 0};
  m.length = 2.0;
  m.rotation_increment = {0, 1e-4, 0};
  law->update(s, m);
  const Vec3 bent = s.moment;  // along -y
  // the pair turns rigidly by 90° about z in 1000 steps: no relative motion, the moment follows
  m.rotation_increment = {};
  for (int k = 1; k <= 1000; ++k) {
    const double a = 0.5 * std::numbers::pi * k / 1000;
    m.normal = {std::cos(a), std::sin(a), 0};
    law->update(s, m);
  }
  // rotating -y by 90° about z gives +x; the rotation is exact (Rodrigues), only rounding
  EXPECT_NEAR(s.moment.x, -bent.y, 1e-12 * norm(bent));
  EXPECT_NEAR(s.moment.y, 0, 1e-12 * norm(bent));
  EXPECT_NEAR(norm(s.moment), norm(bent), 1e-12 * norm(bent));
}

TEST(BondLaws, ParallelBondStrengthScatter) {
  auto law = make_law("parallel_bond", kParallel + "tensile_strength_sd = 100\n");
  Rng rng(3, 7);
  const int n = 4000;
  double sum = 0, sum2 = 0;
  for (int k = 0; k < n; ++k) {
    const double v = law->create(1, 1, 2, {1, 0, 0}, rng).tensile_strength;
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  // sample mean within 4 standard errors (100/√4000 = 1.6 Pa); sd within 5 % (its standard
  // error is about 1/√(2n) = 1.1 %)
  EXPECT_NEAR(mean, 1e3, 4 * 100 / std::sqrt(n));
  EXPECT_NEAR(sd, 100, 5);
}
