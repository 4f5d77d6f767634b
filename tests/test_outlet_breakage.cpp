// Outlets in a breakage run: the outlet takes parents and fragments alike, also a broken parent
// that waits for its replacement (replacement_interval > 1) when it enters the outlet; mass is
// conserved: particles + fines booked as mass + mass removed = mass at the start. (With this
// set-up some waiting parents do leave: before Replacement skipped them, the run threw.)
#include <gtest/gtest.h>

#include <cmath>

#include "breakage_engine_fixture.hpp"
#include "comminute/engine/outlet.hpp"

using namespace comminute;
using namespace comminute::testing;

TEST(OutletBreakage, TakesParentsAndFragmentsAndConservesMass) {
  auto sim = box_gas(0.3, 29);
  std::vector<std::optional<breakage::MaterialBreakage>> mats;
  mats.emplace_back(weak_material(0.02, 0.3, 0.0012, 0.3, breakage::FinesRule::mass, 0.2));
  breakage::BreakageOptions opt;
  opt.replacement_interval = 200;  // broken parents wait up to 200 steps, moving, for replacement
  auto mod = std::make_unique<breakage::BreakageModule>(std::move(mats), opt);
  mod->register_fields(sim->particles);
  const breakage::BreakageModule* breakage = mod.get();
  sim->modules.push_back(std::move(mod));
  OutletSpec o;
  o.name = "corner";
  o.region.lo = {0, 0, 0};
  o.region.hi = {0.0108, 0.0216, 0.0216};  // half of the 21.6 mm box
  auto out = std::make_unique<OutletModule>(std::vector<OutletSpec>{o});
  const OutletModule* outlet = out.get();
  sim->modules.push_back(std::move(out));
  sim->dt = 0.2 * 3.1416 * 0.00018 * std::sqrt(2500 / (5e7 / 2.6)) / (0.1631 * 0.3 + 0.8766);
  const double m0 = sim->particles.total_mass();
  sim->setup();
  sim->run(1500);
  ASSERT_GT(breakage->breakages(), 0u);
  std::uint32_t max_generation = 0;
  for (const auto& r : outlet->log()) max_generation = std::max(max_generation, r.generation);
  EXPECT_GE(max_generation, 1u);  // fragments left through the outlet too
  const double m = sim->particles.total_mass() + fines_total(*breakage) + outlet->removed_mass();
  // sums of ~200 masses in different orders: equal to rounding
  EXPECT_NEAR(m, m0, 1e-12 * m0);
}
