// A rotating drum at steady state: the mean shaft power equals the total dissipation rate
// (issue 14, rig test 4), for the linear spring-dashpot law and for Hertz–Mindlin.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "drum_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

double stored(const Observables& o) {
  return o.kinetic_translational + o.kinetic_rotational + o.potential_gravity + o.elastic;
}

double dissipated(const Observables& o) {
  return o.ledger.damping + o.ledger.friction;
}

// Mean rates over the window (W).
struct DrumBalance {
  double power = 0;        // work done by the shell / window
  double dissipation = 0;  // (damping + friction) / window
  double change = 0;       // change of the stored energy / window
};

// The books of a stretch of run: its mean work, dissipated and stored energy (J) and time (s)
// over `samples` samples, one every `every` steps.
struct Books {
  double work = 0, dissipated = 0, stored = 0, time = 0;
};
Books mean_books(Simulation& sim, int samples, int every) {
  Books m;
  for (int k = 0; k < samples; ++k) {
    sim.run(every);
    const Observables o = sim.observe();
    m.work += o.ledger.wall_work / samples;
    m.dissipated += dissipated(o) / samples;
    m.stored += stored(o) / samples;
    m.time += o.time / samples;
  }
  return m;
}

// The drum of drum_fixture.hpp: 1.5 s spin-up (about 1.2 turns, the bed has settled into its
// profile), then a 5 s window; step 5e-5 s. The window's ends are averages over its first and
// last 0.5 s (a hundred samples each): the stored energy at one instant carries the cascade's
// fluctuation (a few mJ, 2-3 % of the window's work in single-instant ends), its mean over half
// a second much less; the mean rates are those between the ends' mean times (4.5 s apart).
DrumBalance drum_balance(const DemSetup& s, const char* label) {
  auto sim = make_drum(s);  // drum_fixture.hpp
  EXPECT_EQ(sim->particles.size(), 300u);
  sim->setup();
  sim->run(30000);
  const Books a = mean_books(*sim, 100, 100);
  sim->run(80000);
  const Books b = mean_books(*sim, 100, 100);
  const double window = b.time - a.time;
  DrumBalance d;
  d.power = (b.work - a.work) / window;
  d.dissipation = (b.dissipated - a.dissipated) / window;
  d.change = (b.stored - a.stored) / window;
  std::printf(
      "drum (%s): shaft power %.6g W, dissipation rate %.6g W (%+.2f %%), stored-energy change "
      "rate %.4g W, balance residual %.3g W\n",
      label, d.power, d.dissipation, 100 * (d.dissipation / d.power - 1), d.change,
      d.power - d.dissipation - d.change);
  return d;
}

}  // namespace

TEST(DrumPower, MeanShaftPowerEqualsTheDissipationRateAtSteadyState) {
  // The linear spring-dashpot law (k_n = 2000 N/m, contact time ~1.5 ms, overlaps ~1 % of r, a
  // thirtieth of the contact time per step): its tangential spring has a constant stiffness, so
  // its stored energy 1/2 k_t xi^2 is a true potential.
  DemSetup s;
  s.law = "linear_spring_dashpot";
  s.linear_stiffness = 2000;
  const DrumBalance d = drum_balance(s, "linear_spring_dashpot");
  ASSERT_GT(d.power, 0.0);
  // Energy balance: work in = dissipated + change of stored (kinetic + potential + elastic)
  // energy, up to the integration error. At steady state the stored energy only fluctuates, by
  // about the kinetic energy of the cascading layer (a few mJ here), while the work grows with
  // the window (about 0.07 W x 4.5 s = 0.33 J); with the ends averaged over half a second the
  // change over the window stayed within 1 % of the work (-0.1 to +1.0 % with spin-ups of 1.5,
  // 2, 2.5 and 3.5 s), and the integration error of the dashpot work is another 0.5-1 % at this
  // step (dissipation against power: -0.25 to +0.84 % in those runs), so the 3 % holds
  // with a margin.
  EXPECT_NEAR(d.dissipation, d.power, 0.03 * d.power);
  // the residual itself is the change of stored energy: bounded likewise
  EXPECT_LT(std::abs(d.change), 0.03 * d.power);
}

TEST(DrumPower, HertzMindlinMeanShaftPowerEqualsTheDissipationRateAtSteadyState) {
  // Hertz–Mindlin with its default tangential law (E = 10 MPa, nu = 0.3: contact time about
  // 1 ms at 0.2 m/s, 20 steps; 0.17 of the Rayleigh time per step).
  DemSetup s;
  s.law = "hertz_mindlin";
  const DrumBalance d = drum_balance(s, "hertz_mindlin");
  ASSERT_GT(d.power, 0.0);
  // The same reasons as for the linear law (fluctuation of the stored energy within 1 %,
  // integration error of the dashpot work 1.4 %): measured +1.1 to +2.2 % with spin-ups of 1.5,
  // 2, 2.5 and 3.5 s (single-instant ends gave up to +3.9 %, by the cascade's fluctuation). The
  // total-form spring (tangential = "mindlin") booked +4.3 % here, +5.1 % at half the step (with
  // single-instant ends): the energy its loaded springs gain as the contact radius grows does not
  // fall with the step.
  EXPECT_NEAR(d.dissipation, d.power, 0.03 * d.power);
  EXPECT_LT(std::abs(d.change), 0.03 * d.power);
  // The drift of the energy balance (work in - dissipated - change of stored energy) is the
  // integration error, first order in the step: measured -1.5 % of the work at this step,
  // -0.7 % at half the step (the total form: -4.6 % and -3.3 %, not converging).
  EXPECT_LT(std::abs(d.power - d.dissipation - d.change), 0.03 * d.power);
}
