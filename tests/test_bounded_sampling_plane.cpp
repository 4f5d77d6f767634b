// Bounded sampling planes (engine/sampling_plane.hpp): a disc or a rectangle on the plane counts
// only the crossings through it, by direction, with their mass; a logged plane keeps one row per
// counted crossing (id, direction, mass, diameter). Bad bounds are refused with key and line.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/engine/sampling_plane.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "dem_fixture.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

struct Expected {
  std::uint64_t positive = 0, negative = 0;
  double mass_positive = 0, mass_negative = 0;
};

}  // namespace

TEST(BoundedSamplingPlane, CountsOnlyTheCrossingsThroughItsDiscOrRectangle) {
  // No gravity, no contacts: spheres on straight paths along x through the plane x = 0, half of
  // them forwards from (-2 mm, y, z) on a 4 mm grid, half backwards from (+2 mm, y + 1 mm,
  // z + 2 mm); none crosses within 2 µm of a bound, so which ones cross within is known exactly.
  DemSetup d;
  auto sim = make_simulation(d);
  const double r = 0.3e-3, v = 0.5;
  std::map<std::uint64_t, int> direction;
  for (int i = -5; i <= 5; ++i)
    for (int j = -5; j <= 5; ++j) {
      direction[add_sphere(*sim, {-0.002, 0.004 * i, 0.004 * j}, r, {v, 0, 0})] = 1;
      direction[add_sphere(*sim, {0.002, 0.004 * i + 0.001, 0.004 * j + 0.002}, r, {-v, 0, 0})] =
          -1;
    }
  // one sphere crosses obliquely (at z = 1 mm, between the grid's rows) 2 µm inside the disc's
  // rim: its centre ends the step of the crossing outside it (4 µm further along y: it crosses
  // 0.6 of the way through step 226), so only the crossing point, not the end-of-step position,
  // counts it; its twin crosses 2 µm outside the rim
  const double vx = 0.05, vy = 1.0, x0 = -0.0001128, t_cross = -x0 / vx, zo = 0.001;
  const double y_in = std::sqrt(0.009998 * 0.009998 - zo * zo);
  const double y_out = std::sqrt(0.010002 * 0.010002 - zo * zo);
  const std::uint64_t inside = add_sphere(*sim, {x0, y_in - vy * t_cross, zo}, 0.1e-3, {vx, vy, 0});
  add_sphere(*sim, {x0, -(y_out - vy * t_cross), zo}, 0.1e-3, {vx, -vy, 0});
  direction[inside] = 1;

  SamplingPlaneSpec disc{"disc", {0, 0, 0}, {1, 0, 0}};
  disc.extent = SamplingPlaneSpec::Extent::disc;
  disc.radius = 0.01;
  disc.log = true;
  SamplingPlaneSpec rect{"rect", {0, 0, 0}, {1, 0, 0}};
  rect.extent = SamplingPlaneSpec::Extent::rectangle;
  rect.u = {0, 1, 0};
  rect.half_u = 0.006;  // |y| <= 6 mm
  rect.half_v = 0.009;  // |z| <= 9 mm (normal x u = +z)
  auto m = std::make_unique<SamplingPlaneModule>(std::vector<SamplingPlaneSpec>{disc, rect});
  SamplingPlaneModule* planes = m.get();
  m->register_fields(sim->particles);
  sim->modules.push_back(std::move(m));
  sim->dt = 1e-5;
  sim->setup();
  sim->run(1000);  // 10 ms: every grid sphere has crossed once (5 mm along x)

  Expected in_disc, in_rect;
  std::map<std::uint64_t, double> mass_of;
  for (std::size_t i = 0; i < sim->particles.size(); ++i) {
    const auto& p = sim->particles;
    mass_of[p.id[i]] = p.mass[i];
    if (p.radius[i] != r) continue;  // the oblique pair: counted by hand below
    const int dir = direction[p.id[i]];
    const double y = p.x[i].y, z = p.x[i].z;  // paths along x: y and z are the crossing point's
    for (auto [e, within] : {std::pair{&in_disc, y * y + z * z < 0.01 * 0.01},
                             std::pair{&in_rect, std::abs(y) < 0.006 && std::abs(z) < 0.009}}) {
      if (!within) continue;
      (dir > 0 ? e->positive : e->negative) += 1;
      (dir > 0 ? e->mass_positive : e->mass_negative) += p.mass[i];
    }
  }
  in_disc.positive += 1;  // the oblique sphere 2 µm inside the rim
  in_disc.mass_positive += mass_of[inside];
  const PlaneCrossings& c_disc = planes->crossings().at(0);
  const PlaneCrossings& c_rect = planes->crossings().at(1);
  EXPECT_EQ(c_disc.positive, in_disc.positive);
  EXPECT_EQ(c_disc.negative, in_disc.negative);
  EXPECT_EQ(c_rect.positive, in_rect.positive);
  EXPECT_EQ(c_rect.negative, in_rect.negative);
  // the grid: 21 forwards (16 (i^2 + j^2) < 100 mm^2) and 18 backwards inside the disc, 3 x 5 and
  // 3 x 4 inside the rectangle, and the oblique sphere makes 22 forwards in the disc (so the test
  // cannot pass with every or no crossing counted)
  EXPECT_EQ(in_disc.positive, 22u);
  EXPECT_EQ(in_disc.negative, 18u);
  EXPECT_EQ(in_rect.positive, 15u);
  EXPECT_EQ(in_rect.negative, 12u);
  // the same masses summed in another order: equal to rounding
  EXPECT_NEAR(c_disc.mass_positive, in_disc.mass_positive, 1e-12 * in_disc.mass_positive);
  EXPECT_NEAR(c_disc.mass_negative, in_disc.mass_negative, 1e-12 * in_disc.mass_negative);
  EXPECT_NEAR(c_rect.mass_positive, in_rect.mass_positive, 1e-12 * in_rect.mass_positive);
  // the log (disc only): one row per counted crossing, with its direction, mass and diameter
  const auto& log = planes->log();
  ASSERT_EQ(log.size(), in_disc.positive + in_disc.negative);
  for (const ParticleRecord& row : log) {
    EXPECT_EQ(row.site, 0u);
    EXPECT_EQ(row.direction, direction[row.id]);
    EXPECT_EQ(row.mass, mass_of[row.id]);
    EXPECT_EQ(row.diameter, row.id == inside ? 2 * 0.1e-3 : 2 * r);
    EXPECT_GT(row.time, 0.0);
  }
}

TEST(BoundedSamplingPlane, BadBoundsAreRefusedWithKeyAndLine) {
  const TestDir dir;
  const std::string head =
      "[simulation]\nend_time = 0.1\n[contact]\nmodel = \"hertz_mindlin\"\n"
      "[materials.ore]\ndensity = 2700.0\nyoungs_modulus = 5.0e7\npoisson_ratio = 0.25\n"
      "[interaction]\nrestitution = 0.3\nfriction = 0.5\n"
      "[[insert]]\ntype = \"fill\"\nmaterial = \"ore\"\ncount = 1\n"
      "region = { shape = \"box\", lo = [0.0, 0.0, 0.0], hi = [0.1, 0.1, 0.1] }\n"
      "size = { distribution = \"fixed\", diameter = 0.01 }\n"
      "[[sampling_planes]]\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n";
  struct Case {
    std::string keys, key, says;
  };
  for (const Case& c :
       {Case{"radius = -1.0\n", "radius", "> 0"},
        Case{"radius = 1.0\nsize = [1.0, 1.0]\nu = [1.0, 0.0, 0.0]\n", "size", "one of"},
        Case{"size = [1.0]\nu = [1.0, 0.0, 0.0]\n", "size", "two side lengths"},
        Case{"size = [1.0, 2.0]\nu = [0.0, 0.0, 3.0]\n", "u", "normal"},
        Case{"u = [1.0, 0.0, 0.0]\n", "u", "give 'size'"},
        Case{"size = [1.0, 2.0]\n", "size", "needs 'u'"}}) {
    const CaseFile f = CaseFile::parse(head + c.keys, (dir / "planes.toml").string());
    try {
      io::build_dem_case(f.root());
      ADD_FAILURE() << "accepted: " << c.keys;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "sampling_planes[0]." + c.key) << e.what();
      EXPECT_GT(e.line(), 0) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
}
