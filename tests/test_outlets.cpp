// Outlets and sampling planes: removal conserves mass particle by particle and logs each removed
// particle once; the removed energy keeps the energy balance closed; a sampling plane counts the
// crossings of a known ballistic stream exactly; the product size distribution of a time window
// matches a direct count of the particles that vanished in that window; counts and logs survive a
// checkpoint.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <set>

#include "comminute/analysis/product_size.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/engine/outlet.hpp"
#include "comminute/engine/sampling_plane.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

// n spheres of random radius on a widely spaced grid (no two ever touch), falling under gravity.
std::map<std::uint64_t, double> add_falling_stream(Simulation& sim, int n, double z0,
                                                   std::uint64_t seed) {
  Rng rng(seed, 0);
  std::map<std::uint64_t, double> mass;
  for (int k = 0; k < n; ++k) {
    const double r = 0.5e-3 + 0.5e-3 * rng.uniform();
    const Vec3 x{0.004 * (k % 10), 0.004 * ((k / 10) % 10),
                 z0 + 0.004 * (k / 100) + 1e-3 * rng.uniform()};
    const std::uint64_t id = add_sphere(sim, x, r);
    mass[id] = sim.particles.mass.back();
  }
  return mass;
}

OutletModule* add_outlet_below(Simulation& sim, double z) {
  OutletSpec o;
  o.name = "product";
  o.half_space = true;
  o.point = {0, 0, z};
  o.normal = {0, 0, -1};  // removes centres below z
  auto m = std::make_unique<OutletModule>(std::vector<OutletSpec>{o});
  OutletModule* raw = m.get();
  sim.modules.push_back(std::move(m));
  return raw;
}

double energy_balance(const Simulation& sim) {
  const Observables o = sim.observe();
  return o.kinetic_translational + o.kinetic_rotational + o.potential_gravity + o.elastic +
         o.ledger.damping + o.ledger.friction + o.ledger.removed - o.ledger.wall_work;
}

}  // namespace

TEST(Outlet, RemovalConservesMassParticleByParticleAndLogsEachOnce) {
  DemSetup d;
  d.gravity = {0, 0, -9.81};
  auto sim = make_simulation(d);
  const auto inserted = add_falling_stream(*sim, 300, 0.0, 3);
  OutletModule* outlet = add_outlet_below(*sim, -0.01);
  sim->dt = 1e-5;
  sim->setup();
  const double e0 = energy_balance(*sim);
  sim->run(6000);  // 0.06 s: a fall of 17.7 mm, so some but not all have left
  const auto& log = outlet->log();
  ASSERT_GT(log.size(), 0u);
  ASSERT_LT(log.size(), inserted.size());
  // every particle is either still in the run or in the log, exactly once, with its exact mass
  std::map<std::uint64_t, double> accounted;
  for (const auto& r : log) {
    EXPECT_TRUE(accounted.emplace(r.id, r.mass).second) << "id " << r.id << " logged twice";
    EXPECT_LE(r.time, sim->time);
    EXPECT_EQ(r.site, 0u);
    EXPECT_DOUBLE_EQ(r.diameter, 2 * std::cbrt(3 * r.mass / (4 * std::numbers::pi * 2500)));
  }
  for (std::size_t i = 0; i < sim->particles.size(); ++i) {
    EXPECT_TRUE(accounted.emplace(sim->particles.id[i], sim->particles.mass[i]).second)
        << "id " << sim->particles.id[i] << " both removed and present";
    EXPECT_GE(sim->particles.x[i].z, -0.01);  // nothing beyond the outlet plane remains
  }
  EXPECT_EQ(accounted, inserted);  // mass removed + mass remaining = mass inserted, exactly
  // the balance holds to the rounding of summing ~1e-5 J terms over 6000 steps
  EXPECT_NEAR(energy_balance(*sim), e0, 1e-12 * 300);
}

TEST(SamplingPlane, CountsTheCrossingsOfABallisticStreamExactly) {
  DemSetup d;
  d.gravity = {0, 0, -9.81};
  auto sim = make_simulation(d);
  // 200 spheres fall through z = 0 once each; 30 more start below it, thrown up through it so
  // that each crosses upwards and falls back down through it (apex z = v²/2g − 5 mm > 0).
  const auto falling = add_falling_stream(*sim, 200, 0.002, 5);
  double mass_up = 0;
  for (int k = 0; k < 30; ++k) {
    add_sphere(*sim, {0.5 + 0.004 * k, 0, -0.005}, 0.4e-3, {0, 0, 0.6});
    mass_up += sim->particles.mass.back();
  }
  double mass_falling = 0;
  for (const auto& [id, m] : falling) mass_falling += m;
  SamplingPlaneSpec s{"grate", {0, 0, 0}, {0, 0, -1}};  // positive: downwards
  auto m = std::make_unique<SamplingPlaneModule>(std::vector<SamplingPlaneSpec>{s});
  SamplingPlaneModule* planes = m.get();
  sim->modules.push_back(std::move(m));
  sim->dt = 1e-5;
  sim->setup();
  sim->run(15000);  // 0.15 s: every falling sphere is 45+ mm below, the thrown ones back below
  for (std::size_t i = 0; i < sim->particles.size(); ++i) ASSERT_LT(sim->particles.x[i].z, 0.0);
  const PlaneCrossings& c = planes->crossings().at(0);
  EXPECT_EQ(c.positive, 200u + 30u);
  EXPECT_EQ(c.negative, 30u);
  // the same masses, summed in another order: equal to rounding
  EXPECT_NEAR(c.mass_positive, mass_falling + mass_up, 1e-12 * (mass_falling + mass_up));
  EXPECT_NEAR(c.mass_negative, mass_up, 1e-12 * mass_up);
}

TEST(Outlet, ProductSizesOfAWindowMatchADirectCountOfTheParticlesThatLeft) {
  DemSetup d;
  d.gravity = {0, 0, -9.81};
  auto sim = make_simulation(d);
  const auto inserted = add_falling_stream(*sim, 300, 0.0, 11);
  std::map<std::uint64_t, double> diameter;
  for (std::size_t i = 0; i < sim->particles.size(); ++i)
    diameter[sim->particles.id[i]] = 2 * sim->particles.radius[i];
  OutletModule* outlet = add_outlet_below(*sim, -0.005);
  sim->dt = 1e-5;
  sim->setup();
  const std::vector<double> sieves{0.8e-3, 1.2e-3, 1.6e-3, 2.0e-3};
  const double t_from = 0.035, t_to = 0.05;
  // direct count: the ids that vanish from the store in steps ending in (t_from, t_to]
  std::vector<double> passing(sieves.size(), 0.0);
  double mass = 0;
  std::uint64_t count = 0;
  std::set<std::uint64_t> before(sim->particles.id.begin(), sim->particles.id.end());
  while (sim->time < 0.06) {
    sim->step();
    std::set<std::uint64_t> now(sim->particles.id.begin(), sim->particles.id.end());
    if (sim->time > t_from && sim->time <= t_to)
      for (auto id : before)
        if (!now.count(id)) {
          ++count;
          mass += inserted.at(id);
          for (std::size_t s = 0; s < sieves.size(); ++s)
            if (diameter.at(id) <= sieves[s]) passing[s] += inserted.at(id);
        }
    before = std::move(now);
  }
  ASSERT_GT(count, 20u);  // the window holds a real part of the stream
  const analysis::ProductSizes p = analysis::product_sizes(outlet->log(), t_from, t_to, sieves);
  EXPECT_EQ(p.count, count);
  // the same particles, summed in the same order (removal order): equal
  EXPECT_DOUBLE_EQ(p.mass, mass);
  for (std::size_t s = 0; s < sieves.size(); ++s) EXPECT_DOUBLE_EQ(p.mass_passing[s], passing[s]);
  EXPECT_GT(p.fraction_passing(1), 0.0);
  EXPECT_LT(p.fraction_passing(1), 1.0);
}

TEST(Outlet, LogAndCrossingCountsSurviveACheckpoint) {
  auto build = [](std::unique_ptr<Simulation>& sim, OutletModule*& outlet,
                  SamplingPlaneModule*& planes) {
    DemSetup d;
    d.gravity = {0, 0, -9.81};
    sim = make_simulation(d);
    add_falling_stream(*sim, 100, 0.0, 7);
    outlet = add_outlet_below(*sim, -0.01);
    SamplingPlaneSpec mid{"mid", {0, 0, -0.004}, {0, 0, -1}};
    mid.log = true;
    auto m = std::make_unique<SamplingPlaneModule>(std::vector<SamplingPlaneSpec>{mid});
    m->register_fields(sim->particles);
    planes = m.get();
    sim->modules.push_back(std::move(m));
    sim->dt = 1e-5;
  };
  std::unique_ptr<Simulation> a, b;
  OutletModule *oa = nullptr, *ob = nullptr;
  SamplingPlaneModule *pa = nullptr, *pb = nullptr;
  build(a, oa, pa);
  a->setup();
  a->run(4500);
  Archive ar;
  a->save(ar);
  EXPECT_GT(pa->log().size(), 0u);  // the checkpoint holds logged crossings
  build(b, ob, pb);
  b->load(ar);
  a->run(2000);
  b->run(2000);
  ASSERT_EQ(oa->log().size(), ob->log().size());
  for (std::size_t k = 0; k < oa->log().size(); ++k) {
    EXPECT_EQ(oa->log()[k].id, ob->log()[k].id);
    EXPECT_EQ(oa->log()[k].time, ob->log()[k].time);
  }
  // both logs (one record type) came back through the checkpoint bit for bit, every field
  auto same = [](const std::vector<ParticleRecord>& x, const std::vector<ParticleRecord>& y) {
    return x.size() == y.size() &&
           (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(ParticleRecord)) == 0);
  };
  EXPECT_TRUE(same(oa->log(), ob->log()));
  EXPECT_TRUE(same(pa->log(), pb->log()));
  EXPECT_EQ(pa->crossings()[0].positive, pb->crossings()[0].positive);
  EXPECT_EQ(pa->crossings()[0].mass_positive, pb->crossings()[0].mass_positive);
  EXPECT_GT(pa->crossings()[0].positive, 0u);
}

TEST(Outlet, LogsTheCompositionOfEachRemovedParticle) {
  DemSetup d;
  d.gravity = {0, 0, -9.81};
  auto sim = make_simulation(d);
  add_falling_stream(*sim, 50, 0.0, 13);
  // two mineral phases as the composition criterion registers them: C_0 + C_1 = 1 per particle
  auto& p = sim->particles;
  const std::size_t c0 = p.add_field("composition.0", 1.0), c1 = p.add_field("composition.1", 0.0);
  std::map<std::uint64_t, double> phase1;
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.field(c1)[i] = 0.01 * static_cast<double>(i);
    p.field(c0)[i] = 1 - p.field(c1)[i];
    phase1[p.id[i]] = p.field(c1)[i];
  }
  OutletModule* outlet = add_outlet_below(*sim, -0.005);
  sim->dt = 1e-5;
  sim->setup();
  sim->run(5000);
  ASSERT_EQ(outlet->composition_fields(), 2u);
  ASSERT_EQ(outlet->log().size(), 50u);
  for (std::size_t n = 0; n < outlet->log().size(); ++n) {
    EXPECT_EQ(outlet->compositions()[2 * n + 1], phase1.at(outlet->log()[n].id));
    EXPECT_EQ(outlet->compositions()[2 * n], 1 - phase1.at(outlet->log()[n].id));
  }
  const std::vector<Table> tables = outlet->series_source()->tables(*sim);
  EXPECT_EQ(tables[0].columns().back().header(), "composition_1 [-]");
}
