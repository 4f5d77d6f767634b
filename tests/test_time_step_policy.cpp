// The time-step policy: the one place dt is set, from the case, the inserted sizes, the sizes
// modules announce, and the contact law's own limit.
#include <gtest/gtest.h>

#include "comminute/core/error.hpp"
#include "comminute/engine/time_step_policy.hpp"
#include "comminute/fracture/rayleigh_time.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {
class Announces final : public Module {
 public:
  explicit Announces(double radius) : radius_(radius) {}
  std::string name() const override { return "announces"; }
  void announce_sizes(std::vector<ParticleSize>& s, const Simulation&) const override {
    s.push_back({radius_, 0, "a fragment", true});
  }

 private:
  double radius_;
};

double rayleigh(const Simulation& sim, double radius) {
  const Material& m = sim.materials.material(0);
  return fracture::rayleigh_time(2 * radius, m.density, m.shear_modulus(), m.poisson_ratio);
}
}  // namespace

// The step is the fraction of the smallest Rayleigh time of the inserted sizes; sizes a module
// announces (fragments) do not cut it up front: they make it follow the particles present
// (time_step_control.hpp; its behaviour in a breaking run: test_adaptive_time_step.cpp).
TEST(TimeStepPolicy, FractionOfTheInsertedRayleighTimeFollowingAnnouncedSizes) {
  auto sim = make_simulation({});
  const CaseFile f = CaseFile::parse("[simulation]\ntime_step_fraction = 0.1\n");
  TimeStepPolicy policy(f.root().table("simulation"), 1.0);
  policy.add({1e-3, 0, "insert[0]", false});
  policy.add({2e-3, 0, "insert[1]", false});
  EXPECT_EQ(policy.decide(*sim).dt, 0.1 * rayleigh(*sim, 1e-3));  // exact: one formula
  EXPECT_FALSE(sim->step_control.has_value());  // nothing smaller can appear: a fixed step
  sim->modules.push_back(std::make_unique<Announces>(1e-4));
  const auto d = policy.decide(*sim);
  EXPECT_EQ(d.dt, 0.1 * rayleigh(*sim, 1e-3));
  EXPECT_EQ(sim->dt, d.dt);
  ASSERT_TRUE(sim->step_control.has_value());
  EXPECT_EQ(sim->step_control->ceiling(), d.dt);
  EXPECT_EQ(sim->step_control->fraction(), 0.1);
  EXPECT_NE(d.note.find("follows the particles present"), std::string::npos) << d.note;
  // with only the inserted particles present the control keeps the inserted step
  add_sphere(*sim, {0, 0, 0}, 1e-3, {});
  add_sphere(*sim, {0.01, 0, 0}, 2e-3, {});
  EXPECT_EQ(sim->step_control->decide(sim->particles, sim->materials), d.dt);
  // a particle of the announced size brings it down to that size's step
  add_sphere(*sim, {0.02, 0, 0}, 1e-4, {});
  EXPECT_EQ(sim->step_control->decide(sim->particles, sim->materials), 0.1 * rayleigh(*sim, 1e-4));
}

TEST(TimeStepPolicy, AGivenStepTooLargeForAnnouncedSizesIsRefusedNamingTheKey) {
  auto sim = make_simulation({});
  sim->modules.push_back(std::make_unique<Announces>(1e-5));
  const CaseFile f = CaseFile::parse("[simulation]\ntime_step = 1e-6\n");
  TimeStepPolicy policy(f.root().table("simulation"), 1.0);
  policy.add({1e-3, 0, "insert[0]", false});
  try {
    policy.decide(*sim);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("simulation.time_step"), std::string::npos) << e.what();
  }
}

TEST(TimeStepPolicy, TheLinearLawWarnsWhenItsContactTimeIsUnderResolved) {
  // linear law, k_n = 10 N/m, 1 mm spheres of 2500 kg/m3: t_c = pi sqrt(m/2 / k_n) = 2.3 ms; a
  // given step of 1 ms resolves it with ~2 steps (< 10): warned. 1e-5 s (227 steps) is not.
  DemSetup s;
  s.law = "linear_spring_dashpot";
  s.linear_stiffness = 10;
  for (double dt : {1e-3, 1e-5}) {
    auto sim = make_simulation(s);
    const CaseFile f = CaseFile::parse("[simulation]\ntime_step = " + std::to_string(dt) + "\n");
    TimeStepPolicy policy(f.root().table("simulation"), 1.0);
    policy.add({1e-3, 0, "insert[0]", false});
    const auto d = policy.decide(*sim);
    bool warned = false;
    for (const auto& w : d.warnings) warned |= w.find("linear contact time") != std::string::npos;
    EXPECT_EQ(warned, dt > 1e-4) << dt;
  }
}

// A step that follows the particles present can fall to the smallest announced size: the step
// count guard (a unit mistake) counts the run at that step. Here 10 steps at the inserted step
// become 10^10 at the step of an announced 1e-12 m fragment (t_R is linear in the radius).
TEST(TimeStepPolicy, TheStepCountGuardCountsAtTheSmallestStepAFollowingStepCanReach) {
  auto sim = make_simulation({});
  sim->modules.push_back(std::make_unique<Announces>(1e-12));
  const double end_time = 10 * 0.2 * rayleigh(*sim, 1e-3);
  const CaseFile f = CaseFile::parse("[simulation]\n");
  TimeStepPolicy policy(f.root().table("simulation"), end_time);
  policy.add({1e-3, 0, "insert[0]", false});
  try {
    policy.decide(*sim);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("simulation.end_time"), std::string::npos) << e.what();
  }
}
