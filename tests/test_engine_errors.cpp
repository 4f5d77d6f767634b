// Issue 2, test 6 (run-time part): a NaN appearing in a run stops it with the particle id and time.
#include <gtest/gtest.h>

#include <limits>

#include "comminute/core/error.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

TEST(EngineErrors, NonFiniteVelocityStopsTheRunNamingParticleAndTime) {
  DemSetup s;
  auto sim = make_simulation(s);
  add_sphere(*sim, {0, 0, 0}, 0.001);
  const auto bad = add_sphere(*sim, {0.01, 0, 0}, 0.001);
  sim->dt = 1e-5;
  sim->setup();
  sim->run(10);
  sim->particles.v[slot_of(*sim, bad)].y = std::numeric_limits<double>::quiet_NaN();
  try {
    sim->step();
    FAIL() << "no error";
  } catch (const SimulationError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("particle id 2 "), std::string::npos) << m;
    EXPECT_NE(m.find("t = 0.00011 s"), std::string::npos) << m;
  }
}
