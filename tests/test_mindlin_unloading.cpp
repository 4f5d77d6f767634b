// Issue 13 test 1 / issue 14 test 4: the Hertz–Mindlin tangential spring must not create energy
// when the contact radius changes under a loaded spring. One contact driven along a prescribed
// path (two 3.5 mm beads, E = 10 MPa, nu = 0.3, restitution 1: no dashpots); the work fed into
// the contact (trapezoid rule) is compared with the change of its stored elastic energy plus the
// energy it booked as dissipated.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "comminute/contact/contact_law.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/particles/material.hpp"

using namespace comminute;

namespace {

// Energies of one contact driven step by step (J).
class DrivenContact {
 public:
  DrivenContact(const std::string& tangential, double friction) {
    materials_.add({"m", 2500, 1e7, 0.3});
    PairInput in;
    in.restitution = 1.0;  // beta = 0: no dashpot
    in.friction = friction;
    materials_.set_pair(0, 0, in);
    const CaseFile c = CaseFile::parse("tangential = \"" + tangential + "\"\n");
    law_ = ContactLawRegistry::create("hertz_mindlin", c.root());
    law_->declare(layout_);
  }

  // One step to overlap `delta` (m, > 0) and tangential displacement `s` (m, along x; the
  // displacement of i relative to j since the contact began), the normal fixed along z.
  void step_to(double delta, double s) {
    ContactKinematics k;
    k.normal = {0, 0, 1};
    k.overlap = delta;
    k.overlap_rate = (delta - delta_) / dt;
    k.tangential_velocity = {(s - s_) / dt, 0, 0};
    k.effective_radius = 0.5 * 0.0035;
    k.effective_mass = 0.5 * 2500 * 4.0 / 3.0 * M_PI * std::pow(0.0035, 3);
    k.dt = dt;
    ContactForces out;
    law_->compute(k, materials_.pair(0, 0), scratch_.ref(), out);
    // work fed into the contact: F_n d(delta) - F_t . ds (forces on i)
    normal_work += 0.5 * (fn_ + out.normal_force) * (delta - delta_);
    tangential_work -= 0.5 * (ft_ + out.tangential_force.x) * (s - s_);
    dissipated += out.damping_dissipation + out.friction_dissipation;
    normal_stored = out.normal_elastic_energy;
    tangential_stored = out.stored_energy - out.normal_elastic_energy;
    tangential_force = out.tangential_force.x;
    fn_ = out.normal_force;
    ft_ = out.tangential_force.x;
    delta_ = delta;
    s_ = s;
  }

  // `n` equal steps from the current (overlap, displacement) to (delta, s).
  void move_to(double delta, double s, int n) {
    const double d0 = delta_, s0 = s_;
    for (int i = 1; i <= n; ++i) step_to(d0 + (delta - d0) * i / n, s0 + (s - s0) * i / n);
  }

  // Mindlin's tangential stiffness 8 G* sqrt(R* delta) (N/m).
  double stiffness(double delta) const {
    return 8.0 * materials_.pair(0, 0).effective_shear_modulus * std::sqrt(0.5 * 0.0035 * delta);
  }
  // Work fed in minus (stored now + dissipated): zero when the ledger closes (J; stored energy
  // is zero before the first step).
  double gap() const {
    return normal_work + tangential_work - normal_stored - tangential_stored - dissipated;
  }

  static constexpr double dt = 1e-6;  // s; only rates depend on it (no dashpot)
  double normal_work = 0, tangential_work = 0, dissipated = 0;
  double normal_stored = 0, tangential_stored = 0, tangential_force = 0;

 private:
  MaterialTable materials_;
  std::unique_ptr<ContactLaw> law_;
  ContactStateStore layout_;
  ContactScratch scratch_;
  double delta_ = 0, s_ = 0, fn_ = 0, ft_ = 0;
};

// The cycle that separates the two tangential laws: load normally to delta1, shear by S,
// load normally to delta2 with the spring held, shear back to 0 at delta2, unload normally to
// delta_end with the spring held. Normal and tangential motions never share a step, so each
// step is either a change of the contact radius at a fixed spring displacement or a shear at a
// fixed stiffness. Friction 10: the contact sticks throughout (at delta_end the spring force,
// ~sqrt(delta), is still 0.2 of the Coulomb limit, ~delta^1.5).
constexpr double delta1 = 2e-5, delta2 = 1e-4, delta_end = 2e-6, S = 4e-6;

void run_cycle(DrivenContact& c) {
  c.move_to(delta1, 0, 200);
  c.move_to(delta1, S, 200);
  c.move_to(delta2, S, 200);
  c.move_to(delta2, 0, 200);
  c.move_to(delta_end, 0, 200);
}

}  // namespace

TEST(MindlinUnloading, RescaledSpringClosesTheLedgerToRoundOffOverALoadShearUnloadCycle) {
  DrivenContact c("mindlin_rescale_force", 10.0);
  run_cycle(c);
  const double k1 = c.stiffness(delta1), k2 = c.stiffness(delta2);
  // The force is kept while the radius grows (k1 S at delta2), so the shear back to 0 leaves
  // -S (1 - k1/k2) on the spring: the contact takes in 1/2 k1 S^2 + 1/2 k2 S^2 (1 - 2 k1/k2)
  // = 1/2 (k2 - k1) S^2 of tangential work (exact: the shears are at a fixed stiffness, where
  // the trapezoid rule integrates a linear spring exactly).
  const double expected = 0.5 * (k2 - k1) * S * S;
  ASSERT_GT(expected, 0.0);
  EXPECT_NEAR(c.tangential_work, expected, 1e-12 * expected);  // round-off of 1000 steps
  // Tangential ledger: work in = stored now + booked as released (friction). The normal force
  // is Hertz's, whose potential is (2/5) k_n delta^2; its trapezoid work is kept out (second
  // order in the step, not round-off).
  EXPECT_NEAR(c.tangential_work, c.tangential_stored + c.dissipated, 1e-12 * expected);
  EXPECT_GT(c.dissipated, 0.0);
  // The spring left at the end: -S (1 - k1/k2), scaled with the radius on unloading.
  const double k_end = c.stiffness(delta_end);
  EXPECT_NEAR(c.tangential_force, k_end * S * (1 - k1 / k2), 1e-12 * k2 * S);
}

TEST(MindlinUnloading, TotalFormSpringGivesBackMoreWorkThanItTookIn) {
  // The published total form (LAMMPS `mindlin`, F_t = -8 G* a xi): the spring held at S while
  // the radius grows gains 1/2 (k2 - k1) S^2 from nothing, and the shear back to 0 returns it:
  // over a cycle that leaves the contact unloaded (xi = 0) the contact has done net work on the
  // bodies, 1/2 (k2 - k1) S^2, and booked nothing: the energy the drum ledger found missing.
  DrivenContact c("mindlin", 10.0);
  run_cycle(c);
  const double k1 = c.stiffness(delta1), k2 = c.stiffness(delta2);
  const double created = 0.5 * (k2 - k1) * S * S;
  EXPECT_NEAR(c.tangential_work, -created, 1e-12 * created);  // round-off of 1000 steps
  EXPECT_EQ(c.tangential_stored, 0.0);
  EXPECT_EQ(c.dissipated, 0.0);
}

namespace {

// An oblique cycle: overlap and shear grow together to (delta2, S) in n steps, then the overlap
// shrinks to 1e-7 m while the shear goes on to 3 S in n steps, friction 0.5: the spring follows
// the radius and the contact slides once mu F_n (~delta^1.5) falls below the spring force
// (~delta^0.5). Returns the ledger gap (J); `work` gets the work fed in (J).
double oblique_gap(const std::string& tangential, int n, double& work) {
  DrivenContact c(tangential, 0.5);
  c.move_to(delta2, S, n);
  c.move_to(1e-7, 3 * S, n);
  work = c.normal_work + c.tangential_work;
  std::printf(
      "oblique cycle (%s), %d steps per leg: work in %.9g J, dissipated %.9g J, gap %.3g J\n",
      tangential.c_str(), n, work, c.dissipated, c.gap());
  return c.gap();
}

}  // namespace

TEST(MindlinUnloading, ObliqueLoadUnloadWithSlidingCreatesNoEnergy) {
  // Normal and tangential motions share every step here, so the ledger closes only up to the
  // time discretisation (trapezoid work against the per-step booking, first order in the step
  // of the path): the gap must shrink in proportion as the steps are refined.
  double work = 0;
  const double coarse = oblique_gap("mindlin_rescale_force", 1000, work);
  const double fine = oblique_gap("mindlin_rescale_force", 8000, work);
  // first order: 8 times the steps, an eighth of the gap (measured 3.25e-10 -> 4.08e-11 J;
  // allowing a quarter)
  EXPECT_LT(std::abs(fine), std::abs(coarse) / 4);
  // never energy gained: the discretisation loses energy (a sliding step truncates the spring
  // by more than the friction work it books, by 1/2 k_t (slip)^2), it does not create it
  EXPECT_GE(coarse, 0.0);
  EXPECT_GE(fine, 0.0);
  // and small against the work in at the finer step (measured 3.2e-4)
  EXPECT_LT(std::abs(fine), 1e-3 * work);
  // The total form on the same path: the spring loses 1/2 xi^2 |dk_t| unbooked as the radius
  // shrinks under it (measured 43 % of the work in, the same at both steps): a modelling error,
  // not a discretisation one.
  const double total_form = oblique_gap("mindlin", 8000, work);
  EXPECT_GT(std::abs(total_form), 0.2 * work);
}
