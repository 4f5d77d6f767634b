// The time step of breakage runs follows the particles present (issue 8, point 6): before any
// breakage it is the step of the inserted particles, not cut for the smallest fragment that could
// ever appear; when smaller fragments appear it drops to theirs. The energy ledger closes with a
// changing step, a checkpoint continues exactly across a change, and the product size
// distribution agrees with a run at the fixed small step of the past.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "breakage_engine_fixture.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/engine/time_step_policy.hpp"
#include "comminute/fracture/rayleigh_time.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

constexpr double kDensity = 2500, kYoungs = 5e7, kPoisson = 0.3;  // dem_fixture defaults, box_gas

double rayleigh(double radius) {
  return fracture::rayleigh_time(2 * radius, kDensity, kYoungs / (2 * (1 + kPoisson)), kPoisson);
}

// The radius a particle has at full size: its (physical) mass at the material's density.
double full_radius(const ParticleStore& p, std::size_t i) {
  return std::cbrt(3 * p.physical_mass(i) / (4 * std::numbers::pi * kDensity));
}

// The box gas of 3 mm particles with breakage (fragments >= 0.3 x parent; 3 mm parents and
// fragments >= `min_breakable` break, fines booked as mass); its time step decided by the policy
// as the front end does (time_step_fraction, inserted 3 mm spheres), or fixed at `fixed_dt`.
struct Gas {
  std::unique_ptr<Simulation> sim;
  breakage::BreakageModule* module = nullptr;
  TimeStepPolicy::Decision decision;
};

Gas gas(std::uint64_t seed, double fraction, double fixed_dt = 0, double friction = 0.3,
        double min_breakable = 0.0012, const breakage::BreakageOptions& opt = {}) {
  Gas g;
  g.sim = box_gas(friction, seed);
  std::vector<std::optional<breakage::MaterialBreakage>> mats;
  mats.emplace_back(weak_material(0.02, 0.3, min_breakable, 0.3, breakage::FinesRule::mass, 0.2));
  auto mod = std::make_unique<breakage::BreakageModule>(std::move(mats), opt);
  mod->register_fields(g.sim->particles);
  g.module = mod.get();
  g.sim->modules.push_back(std::move(mod));
  if (fixed_dt > 0) {
    g.sim->dt = fixed_dt;
    return g;
  }
  const CaseFile f =
      CaseFile::parse(fmt::format("[simulation]\ntime_step_fraction = {}\n", fraction));
  TimeStepPolicy policy(f.root().table("simulation"), 1.0);
  policy.add({0.0015, 0, "insert[0]", false});
  g.decision = policy.decide(*g.sim);
  return g;
}

// fraction x the Rayleigh time of particle i at its full size.
double limit_of(const ParticleStore& p, std::size_t i, double fraction) {
  return fraction * rayleigh(std::max(p.radius[i], full_radius(p, i)));
}

}  // namespace

// Before any breakage the step is 0.2 t_R of the 3 mm particles present (the past policy cut it
// up front to 0.2 t_R of the smallest fragment breakage could make, 0.3 x 1.2 mm: 8.3 x smaller).
// Once fragments appear it is 0.2 t_R of the smallest particle present, each at its full size, so
// every contact is resolved: after each step, every pair that overlaps and every particle on a
// wall was integrated with a step no larger than 0.2 t_R of its smallest particle (brute force
// over all pairs). The relative 1e-12 covers the cube root in the full radius (a few ulp); the
// rest is the one formula.
TEST(AdaptiveTimeStep, FollowsTheParticlesPresent) {
  Gas g = gas(29, 0.2);
  Simulation& sim = *g.sim;
  const double ceiling = 0.2 * rayleigh(0.0015);
  EXPECT_EQ(g.decision.dt, ceiling);  // exact: one formula
  EXPECT_TRUE(sim.step_control.has_value()) << g.decision.note;
  EXPECT_NE(g.decision.note.find("follows the particles present"), std::string::npos)
      << g.decision.note;
  sim.setup();
  std::uint64_t steps = 0;
  while (g.module->breakages() == 0 && steps < 5000) {
    sim.step();
    ++steps;
    if (g.module->breakages() == 0) {
      ASSERT_EQ(sim.dt, ceiling) << "step " << steps;
    }
  }
  ASSERT_GT(g.module->breakages(), 0u);
  double smallest_dt = sim.dt;
  std::uint64_t checked_contacts = 0;
  for (int k = 0; k < 400; ++k) {
    // the smallest particle present at full size, computed here
    double expected = ceiling;
    for (std::size_t i = 0; i < sim.particles.size(); ++i)
      expected = std::min(expected, limit_of(sim.particles, i, 0.2));
    const std::uint64_t born = sim.particles.next_id();  // fragments made at the step's end
    sim.step();
    const auto& p = sim.particles;
    ASSERT_NEAR(sim.dt, expected, 1e-12 * expected) << "step " << steps + k;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 1; j < p.size(); ++j) {
        if (p.id[i] >= born || p.id[j] >= born) continue;  // not integrated yet
        const double reach = p.radius[i] + p.radius[j];
        if (norm2(p.x[i] - p.x[j]) >= reach * reach) continue;
        ++checked_contacts;
        const double lim = std::min(limit_of(p, i, 0.2), limit_of(p, j, 0.2));
        ASSERT_LE(sim.dt, lim * (1 + 1e-12)) << "step " << steps + k << ", pair " << i << " " << j;
      }
    for (const auto& c : sim.wall_contacts()) {  // slots as of the forces: before replacement
      if (c.particle < p.size() && p.id[c.particle] == c.id) {
        ASSERT_LE(sim.dt, limit_of(p, c.particle, 0.2) * (1 + 1e-12)) << "step " << steps + k;
      }
    }
    smallest_dt = std::min(smallest_dt, sim.dt);
  }
  ASSERT_GT(checked_contacts, 0u);
  // fragments of 3 mm parents are >= 0.9 mm: the step fell below that of 1.5 mm, never below
  // that of the smallest fragment possible (0.36 mm)
  EXPECT_LT(smallest_dt, ceiling);
  EXPECT_GE(smallest_dt, 0.2 * rayleigh(0.00018) * (1 - 1e-12));
  RecordProperty("steps_before_first_breakage", std::to_string(steps));
  RecordProperty("smallest_dt_s", fmt::format("{:.4g}", smallest_dt));
}

namespace {
// Energy in the particles plus every joule booked out, minus the walls' work (J): constant when
// the ledger closes.
double energy_balance(const Simulation& sim) {
  const Observables o = sim.observe();
  return o.kinetic_translational + o.kinetic_rotational + o.potential_gravity + o.elastic +
         o.ledger.damping + o.ledger.friction + o.ledger.removed - o.ledger.wall_work;
}

// Drift (J) of the energy balance over the same simulated time in the frictionless gas with the
// step following the particles present at `fraction`, and the energy breakage removed (J).
std::pair<double, double> adaptive_balance_drift(double fraction, double end_time) {
  Gas g = gas(29, fraction, 0, 0.0);
  Simulation& sim = *g.sim;
  sim.setup();
  const double b0 = energy_balance(sim);
  double dt_max = 0, dt_min = 1;
  while (sim.time < end_time) {
    sim.step();
    dt_max = std::max(dt_max, sim.dt);
    dt_min = std::min(dt_min, sim.dt);
  }
  EXPECT_GT(dt_max, 2 * dt_min) << "the step did not change";
  return {energy_balance(sim) - b0, sim.ledger.removed};
}
}  // namespace

// The ledger closes with a changing step (velocity Verlet takes the new step from the next half
// kick on; contact increments use the step of their own step). As in
// BreakageEngine.EnergyLedgerClosesThroughBreakage: the damping ledger is integrated to first
// order in dt, a booking leak does not shrink with dt; so a step four times finer must cut the
// drift at least in half, and the fine drift must stay below 1e-3 of the energy breakage removed.
TEST(AdaptiveTimeStep, EnergyLedgerClosesWithAChangingStep) {
  const double end_time = 3000 * 0.2 * rayleigh(0.00018);  // the old test's 3000 fixed steps
  const auto [coarse, removed] = adaptive_balance_drift(0.2, end_time);
  const double fine = adaptive_balance_drift(0.05, end_time).first;
  ASSERT_GT(removed, 0.0);
  EXPECT_LE(std::abs(fine), 0.5 * std::abs(coarse));
  EXPECT_LE(std::abs(fine), 1e-3 * removed);
  RecordProperty("drift_coarse_J", std::to_string(coarse));
  RecordProperty("drift_fine_J", std::to_string(fine));
  RecordProperty("removed_J", std::to_string(removed));
}

// A checkpoint taken before the step changes, continued in a fresh simulation, takes the same
// steps and reproduces the uninterrupted run bit for bit (the step is a function of the saved
// particle state; same thread count).
TEST(AdaptiveTimeStep, CheckpointContinuesExactlyAcrossAStepChange) {
  Gas a = gas(29, 0.2);
  a.sim->setup();
  a.sim->run(5);
  const double dt_saved = a.sim->dt;
  Archive ar;
  a.sim->save(ar);
  std::vector<double> steps_a, steps_b;
  for (int k = 0; k < 600; ++k) {
    a.sim->step();
    steps_a.push_back(a.sim->dt);
  }
  Gas b = gas(29, 0.2);
  b.sim->load(ar);
  for (int k = 0; k < 600; ++k) {
    b.sim->step();
    steps_b.push_back(b.sim->dt);
  }
  ASSERT_GT(a.module->breakages(), 0u);
  EXPECT_LT(*std::min_element(steps_a.begin(), steps_a.end()), dt_saved) << "no change to cross";
  EXPECT_EQ(steps_a, steps_b);
  EXPECT_EQ(a.sim->time, b.sim->time);
  EXPECT_EQ(a.module->breakages(), b.module->breakages());
  ASSERT_EQ(a.sim->particles.size(), b.sim->particles.size());
  for (std::size_t i = 0; i < a.sim->particles.size(); ++i) {
    ASSERT_EQ(a.sim->particles.id[i], b.sim->particles.id[i]);
    EXPECT_EQ(a.sim->particles.x[i], b.sim->particles.x[i]);
    EXPECT_EQ(a.sim->particles.v[i], b.sim->particles.v[i]);
    EXPECT_EQ(a.sim->particles.radius[i], b.sim->particles.radius[i]);
  }
  EXPECT_EQ(a.module->fines_mass(), b.module->fines_mass());
}

namespace {
// Mass fraction (particles at full size + fines booked as mass) finer than each sieve.
std::vector<double> fraction_passing(const Gas& g, const std::vector<double>& sieves) {
  const auto& p = g.sim->particles;
  double total = fines_total(*g.module);
  std::vector<double> passing(sieves.size(), total);
  for (std::size_t i = 0; i < p.size(); ++i) {
    total += p.physical_mass(i);
    const double d = 2 * std::max(p.radius[i], full_radius(p, i));
    for (std::size_t s = 0; s < sieves.size(); ++s)
      if (d <= sieves[s]) passing[s] += p.physical_mass(i);
  }
  for (double& v : passing) v /= total;
  return passing;
}
}  // namespace

// Product size distribution: the gas run to the same time with the step following the particles
// present, and at the fixed step of the past (0.2 t_R of the smallest fragment possible, 0.36
// mm), over 6 lattice seeds each. The runs are chaotic, so single runs differ; what must agree is
// the mean fraction passing each sieve, within three standard errors of the difference of two
// means (sqrt(s_a^2/n + s_f^2/n), s from the 6 runs of each kind): a two-sample test that a real
// bias of the step (a resolved vs. an under-resolved contact) would fail.
TEST(AdaptiveTimeStep, ProductSizeDistributionAgreesWithTheFixedSmallStep) {
  const std::vector<double> sieves = {0.0006, 0.0009, 0.0012, 0.0018, 0.0024};
  const double fixed_dt = 0.2 * rayleigh(0.00018);
  const double end_time = 2000 * fixed_dt;
  const std::uint64_t seeds[] = {29, 6, 8, 11, 13, 17};
  const std::size_t n = std::size(seeds), ns = sieves.size();
  std::vector<std::vector<double>> a(ns), f(ns);
  std::uint64_t steps_adaptive = 0, steps_fixed = 0;
  for (std::uint64_t seed : seeds)
    for (int kind = 0; kind < 2; ++kind) {
      Gas g = kind == 0 ? gas(seed, 0.2) : gas(seed, 0.2, fixed_dt);
      g.sim->setup();
      while (g.sim->time < end_time - 0.5 * g.sim->dt) g.sim->step();
      (kind == 0 ? steps_adaptive : steps_fixed) += g.sim->step_count;
      const auto passing = fraction_passing(g, sieves);
      for (std::size_t s = 0; s < ns; ++s) (kind == 0 ? a : f)[s].push_back(passing[s]);
    }
  auto mean = [](const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m += x;
    return m / static_cast<double>(v.size());
  };
  auto variance = [&](const std::vector<double>& v) {
    const double m = mean(v);
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return s / static_cast<double>(v.size() - 1);
  };
  bool some_breakage = false;
  for (std::size_t s = 0; s < ns; ++s) {
    const double se = std::sqrt((variance(a[s]) + variance(f[s])) / static_cast<double>(n));
    EXPECT_LE(std::abs(mean(a[s]) - mean(f[s])), 3 * se + 1e-12)
        << "sieve " << sieves[s] << " m: adaptive " << mean(a[s]) << ", fixed " << mean(f[s]);
    some_breakage = some_breakage || mean(f[s]) > 0.05;
    RecordProperty(fmt::format("passing_{:.1f}mm", 1e3 * sieves[s]),
                   fmt::format("{:.4f} vs {:.4f} +- {:.4f}", mean(a[s]), mean(f[s]), se));
  }
  EXPECT_TRUE(some_breakage);
  EXPECT_LT(steps_adaptive, steps_fixed);
  RecordProperty("steps_adaptive", std::to_string(steps_adaptive));
  RecordProperty("steps_fixed", std::to_string(steps_fixed));
}

namespace {
// The gas with a time-step floor of `floor` x the inserted particles' step, kept by `rule`, run
// for 600 steps past its first breakage. Returns the smallest step taken.
struct FloorRun {
  Gas g;
  double initial_mass = 0;
  double smallest_dt = 1;
};
FloorRun floor_run(double floor, breakage::FloorRule rule, double fraction = 0.2) {
  breakage::BreakageOptions opt;
  opt.time_step_floor = floor;
  opt.floor_rule = rule;
  FloorRun r{gas(29, fraction, 0, 0.0, 0.0012, opt)};
  Simulation& sim = *r.g.sim;
  sim.setup();
  r.initial_mass = sim.particles.total_mass();
  int after = 0;
  while (after < 600 && sim.step_count < 20000) {
    sim.step();
    r.smallest_dt = std::min(r.smallest_dt, sim.dt);
    if (r.g.module->breakages() > 0) ++after;
  }
  EXPECT_GT(r.g.module->breakages(), 0u);
  return r;
}
}  // namespace

// Without a floor the gas's fragments (>= 0.9 mm from 3 mm parents, >= 0.36 mm from 1.2 mm ones)
// take the step below 0.4 of the inserted particles' step; with time_step_floor = 0.4 and the
// default rule (fines) the fragments below d_f = 0.4 x 3 mm = 1.2 mm (t_R is proportional to d)
// become fines: the step never falls below 0.4 x the ceiling, no particle is smaller than d_f,
// and the mass closes (particles + fines). 1e-12: the formula's round-off.
TEST(AdaptiveTimeStep, FloorTurnsFinerFragmentsIntoFines) {
  const double ceiling = 0.2 * rayleigh(0.0015);
  const FloorRun free = floor_run(0.0, breakage::FloorRule::fines);
  EXPECT_LT(free.smallest_dt, 0.4 * ceiling) << "the floor would not bind";
  const FloorRun r = floor_run(0.4, breakage::FloorRule::fines);
  EXPECT_GE(r.smallest_dt, 0.4 * ceiling * (1 - 1e-12));
  const auto& p = r.g.sim->particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    ASSERT_GE(2 * std::max(p.radius[i], full_radius(p, i)), 0.0012 * (1 - 1e-12)) << i;
  EXPECT_GT(fines_total(*r.g.module), 0.0) << "no fragment was below the floor";
  // mass: sums of a few hundred doubles
  EXPECT_NEAR(p.total_mass() + fines_total(*r.g.module), r.initial_mass, 1e-12 * r.initial_mass);
}

// With floor_rule = density_scaling the fragments below d_f stay particles and move with their
// inertia scaled by s = (t_f / t_R(d))^2: each particle's mass_scale is that (or 1), its inertial
// mass is s times the solid sphere's, the step is held at exactly 0.4 x the ceiling once such a
// fragment exists, and the physical mass closes (round-off tolerances as above).
TEST(AdaptiveTimeStep, DensityScalingHoldsTheStepAtTheFloor) {
  const double ceiling = 0.2 * rayleigh(0.0015);
  const FloorRun r = floor_run(0.4, breakage::FloorRule::density_scaling);
  const auto& p = r.g.sim->particles;
  const double t_floor = 0.4 * rayleigh(0.0015);
  std::size_t scaled = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double radius = std::max(p.radius[i], full_radius(p, i));
    const double t = rayleigh(radius);
    const double s = t < t_floor ? (t_floor / t) * (t_floor / t) : 1.0;
    ASSERT_NEAR(p.mass_scale(i), s, 1e-12 * s) << i;
    ASSERT_NEAR(p.mass[i], s * kDensity * 4.0 / 3.0 * std::numbers::pi * std::pow(radius, 3),
                1e-12 * p.mass[i])
        << i;
    if (s > 1) ++scaled;
  }
  ASSERT_GT(scaled, 0u) << "no fragment was below the floor";
  EXPECT_NEAR(r.smallest_dt, 0.4 * ceiling, 1e-12 * ceiling);
  EXPECT_NEAR(p.total_mass() + fines_total(*r.g.module), r.initial_mass, 1e-12 * r.initial_mass);
}

// The energy ledger closes under density scaling: the kinetic energy a fragment gains or loses by
// its scale at birth is booked with the parent's (replacement), and the dynamics use the inertial
// masses throughout. Same criterion as EnergyLedgerClosesWithAChangingStep: the damping ledger is
// first order in dt while a booking leak does not shrink with dt, so over the same simulated time
// a step four times finer must cut the drift at least in half.
TEST(AdaptiveTimeStep, EnergyLedgerClosesWithDensityScaling) {
  auto drift = [](double fraction) {
    breakage::BreakageOptions opt;
    opt.time_step_floor = 0.4;
    opt.floor_rule = breakage::FloorRule::density_scaling;
    Gas g = gas(29, fraction, 0, 0.0, 0.0012, opt);
    Simulation& sim = *g.sim;
    sim.setup();
    const double b0 = energy_balance(sim);
    while (sim.time < 3000 * 0.2 * rayleigh(0.00018)) sim.step();
    EXPECT_GT(g.module->breakages(), 0u);
    return std::pair{energy_balance(sim) - b0, sim.ledger.removed};
  };
  const auto [coarse, removed] = drift(0.2);
  const double fine = drift(0.05).first;
  ASSERT_GT(removed, 0.0);
  EXPECT_LE(std::abs(fine), 0.5 * std::abs(coarse));
  // Magnitude: measured 1.5e-3 of the removed energy at 0.05 with either floor rule (fines: the
  // same), 3e-4 at 0.0125 — the floor keeps the step 2.5x above the no-floor test's, so its
  // 1e-3 bound becomes 2e-3 here; the leak check is the halving above.
  EXPECT_LE(std::abs(fine), 2e-3 * removed);
  RecordProperty("drift_coarse_J", std::to_string(coarse));
  RecordProperty("drift_fine_J", std::to_string(fine));
  RecordProperty("removed_J", std::to_string(removed));
}
