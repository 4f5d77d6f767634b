// Insertion: a fill places the requested count (or volume fraction) without overlaps, inside its
// region and clear of walls; a pour inserts at its rate; size distributions have the moments and
// medians their parameters say.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "comminute/core/case_table.hpp"
#include "comminute/engine/insertion.hpp"
#include "comminute/geometry/box_wall.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

// A distribution from the text of its [insert.size] table, as the case builder makes it.
std::shared_ptr<const SizeDistribution> make_size(const std::string& toml) {
  const CaseTable t = CaseFile::parse(toml).root();
  return SizeDistributionRegistry::create(t.string("distribution"), t);
}

InsertionSpec fill_spec(std::shared_ptr<const SizeDistribution> size) {
  InsertionSpec s;
  s.label = "insert[0]";
  s.region.lo = {0, 0, 0};
  s.region.hi = {0.03, 0.03, 0.03};
  s.density = 2500;
  s.size = std::move(size);
  return s;
}

double min_gap(const ParticleStore& p) {
  double gap = 1e9;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      gap = std::min(gap, norm(p.x[i] - p.x[j]) - p.radius[i] - p.radius[j]);
  return gap;
}

}  // namespace

TEST(Insertion, FillPlacesCountWithoutOverlapInsideRegionAndWalls) {
  auto sim = make_simulation({});
  // a wall plane through the region: particles must stay clear of it
  sim->walls.push_back(
      std::make_unique<BoxWall>(Vec3{0, 0, 0}, Vec3{0.03, 0.03, 0.025}, std::array<bool, 6>{}));
  InsertionSpec s = fill_spec(make_size("distribution = 'uniform'\nmin = 0.001\nmax = 0.003"));
  s.count = 800;
  sim->modules.push_back(std::make_unique<InsertionModule>(s, 7));
  sim->dt = 1e-6;
  sim->setup();
  const auto& p = sim->particles;
  ASSERT_EQ(p.size(), 800u);
  EXPECT_GE(min_gap(p), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_TRUE(s.region.contains(p.x[i], p.radius[i]));
    EXPECT_LE(p.x[i].z + p.radius[i], 0.025);
  }
}

TEST(Insertion, FillByVolumeFractionReachesIt) {
  auto sim = make_simulation({});
  InsertionSpec s = fill_spec(make_size("distribution = 'fixed'\ndiameter = 0.002"));
  s.volume_fraction = 0.2;
  sim->modules.push_back(std::make_unique<InsertionModule>(s, 7));
  sim->dt = 1e-6;
  sim->setup();
  double v = 0;
  for (double r : sim->particles.radius) v += 4.0 / 3.0 * M_PI * r * r * r;
  // the count is rounded to an integer: one particle of 4.2e-9 m3 in 2.7e-5 m3 is 1.6e-4
  EXPECT_NEAR(v / s.region.volume(), 0.2, 2e-4);
}

TEST(Insertion, ImpossibleFillSaysHowManyFitted) {
  auto sim = make_simulation({});
  InsertionSpec s = fill_spec(make_size("distribution = 'fixed'\ndiameter = 0.01"));
  s.count = 100;  // 100 spheres of 1 cm in a 3 cm cube cannot fit
  sim->modules.push_back(std::make_unique<InsertionModule>(s, 7));
  sim->dt = 1e-6;
  try {
    sim->setup();
    FAIL();
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("placed only"), std::string::npos);
  }
}

TEST(Insertion, PourFollowsItsRate) {
  auto sim = make_simulation({});
  InsertionSpec s = fill_spec(make_size("distribution = 'fixed'\ndiameter = 0.001"));
  s.pour = true;
  s.rate = 20000;  // 1/s
  s.start = 0.001;
  s.end = 0.006;
  s.interval = 5e-4;
  sim->modules.push_back(std::make_unique<InsertionModule>(s, 7));
  sim->dt = 1e-5;
  sim->setup();
  sim->run(300);  // t = 3 ms: 2 ms of pouring
  EXPECT_NEAR(static_cast<double>(sim->particles.size()), 20000 * 0.002, 20000 * s.interval + 1);
  sim->run(700);  // t = 10 ms, pouring ended at 6 ms
  EXPECT_EQ(sim->particles.size(), 100u);
  EXPECT_GE(min_gap(sim->particles), -1e-5);  // poured into free space, then moving under gravity=0
}

TEST(SizeDistribution, LognormalMedianAndNormalMean) {
  // 20000 draws: the sample median of a lognormal is within ~1 % of its median (SE of the median
  // of ln d is 1.25 sigma / sqrt(n) = 0.0035 here); the truncated-normal mean within 3 SE.
  Rng rng(1);
  auto ln = make_size(R"(distribution = "lognormal"
                         median = 0.002
                         sigma = 0.4
                         min = 1e-6
                         max = 1.0)");
  std::vector<double> d(20000);
  for (auto& x : d) x = ln->sample(rng);
  std::nth_element(d.begin(), d.begin() + 10000, d.end());
  EXPECT_NEAR(d[10000] / 0.002, 1.0, 0.011);
  auto nd = make_size(R"(distribution = "normal"
                         mean = 0.003
                         sd = 0.0003
                         min = 0.0015
                         max = 0.0045)");  // +-5 sd: truncation negligible
  double s = 0;
  for (int k = 0; k < 20000; ++k) s += nd->sample(rng);
  EXPECT_NEAR(s / 20000, 0.003, 3 * 0.0003 / std::sqrt(20000.0));
}

TEST(SizeDistribution, MassBasedTableGivesMassFractions) {
  // Two sizes with equal mass fractions: the smaller one (half the diameter) must be drawn 8x as
  // often. 40000 draws: binomial SE of the number fraction 8/9 is 0.0016; 4 SE below.
  Rng rng(2);
  auto t = make_size(R"(distribution = "table"
                        diameters = [0.001, 0.002]
                        fractions = [0.5, 0.5])");
  int small = 0;
  for (int k = 0; k < 40000; ++k) small += t->sample(rng) < 0.0015;
  EXPECT_NEAR(small / 40000.0, 8.0 / 9.0, 0.0064);
}
