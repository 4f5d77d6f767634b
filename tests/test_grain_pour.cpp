// Issue 11, point 2: pouring bonded grain templates during the run ([[insert]] type = "clusters",
// mode = "pour"). Checks: poured grains keep every bond and their template's geometry while they
// fall; the poured mass is the count times the template mass; orientations repeat with the seed,
// change with it and are isotropic; a checkpoint taken mid-pour restarts bit-for-bit; bad keys
// are refused with file, line and key.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <string>

#include "case_docs_check.hpp"
#include "case_sections.hpp"
#include "comminute/bonds/grain_breakage_module.hpp"
#include "comminute/bonds/grain_placement.hpp"
#include "comminute/bonds/grain_pour.hpp"
#include "comminute/io/case/bonds_case.hpp"
#include "comminute/io/case/cluster_case.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "source_file.hpp"

using namespace comminute;

namespace {

namespace ct = comminute::testing;

// Ellipsoidal grains of 6 sub-spheres poured from a box 10 mm above nothing (no walls; gravity the
// default, -9.81 m/s² along z): in free fall nothing loads a grain but its own sub-spheres'
// contacts. `pour.extra` holds more [[insert]] keys.
std::string case_text(int seed, const ct::GrainPourKeys& pour) {
  return ct::dem_sections({static_cast<std::uint64_t>(seed), 0.05, 1.0e-6, 1.0e-4},
                          {"rice", 1450.0, 1.0e8, 0.3, 0.3, 0.4}) +
         ct::grain_pour_insert(pour) +
         ct::parallel_bond_section({8.0e-5, 1.0e11, 4.0e10, 1.0e7, 1.0e7, 0.0, true});
}

ct::GrainPourKeys pour_with(const std::string& extra, int templates = 2) {
  ct::GrainPourKeys k;
  k.extra = extra;
  k.templates = templates;
  return k;
}

std::string case_text(int seed, const std::string& extra) {
  return case_text(seed, pour_with(extra));
}

struct Poured {
  CaseFile file;
  io::DemCase dem;
  bonds::BondsModule* bonds = nullptr;
  bonds::GrainPourModule* pour = nullptr;
  explicit Poured(const std::string& text) : file(CaseFile::parse(text, "pour.toml")) {
    dem = io::build_dem_case(file.root());
    bonds = io::add_bonds(file.root(), dem);
    io::decide_time_step(dem);
    file.reject_unknown();
    for (const auto& m : dem.sim->modules)
      if (auto* p = dynamic_cast<bonds::GrainPourModule*>(m.get())) pour = p;
  }
  Simulation& sim() { return *dem.sim; }
};

// Slot of each particle id.
std::map<std::uint64_t, std::size_t> slots(const ParticleStore& p) {
  std::map<std::uint64_t, std::size_t> out;
  for (std::size_t i = 0; i < p.size(); ++i) out[p.id[i]] = i;
  return out;
}

// For each particle slot: (template, sub-sphere index in it), from the grain records and ids
// (a grain's sub-spheres get consecutive ids in template order).
std::vector<std::pair<std::size_t, std::size_t>> template_spheres(const Poured& c) {
  const ParticleStore& p = c.dem.sim->particles;
  const auto& g = p.field(p.field_index("grain"));
  std::map<std::uint64_t, std::uint64_t> first_id;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto k = static_cast<std::uint64_t>(g[i]);
    if (!first_id.count(k) || p.id[i] < first_id[k]) first_id[k] = p.id[i];
  }
  std::vector<std::pair<std::size_t, std::size_t>> out(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto k = static_cast<std::uint64_t>(g[i]);
    out[i] = {c.pour->grains().at(k).templ, p.id[i] - first_id[k]};
  }
  return out;
}

}  // namespace

TEST(GrainPour, PouredGrainsKeepEveryBondAndTheirTemplateGeometryWhileFalling) {
  Poured c(case_text(1, "count = 24"));
  Simulation& sim = c.sim();
  // 6 rounds of 4 grains (t = 1 … 6 ms; at t = 0 none is due yet), then falling to 20 ms
  // (about 2 mm; nothing below)
  sim.run(20000);
  ASSERT_EQ(c.pour->poured(), 24u);
  EXPECT_EQ(sim.particles.size(), 24u * 6);
  std::size_t template_bonds = 0;
  for (const auto& g : c.pour->grains())
    template_bonds += c.pour->grain_template(g.templ).bonds.size();
  EXPECT_TRUE(c.bonds->failures().empty());
  ASSERT_EQ(c.bonds->bonds().size(), template_bonds);  // every bond made at insertion, none lost
  // the batches are the rounds that placed grains, one per millisecond
  for (const auto& g : c.pour->grains())
    EXPECT_EQ(g.batch, static_cast<std::uint64_t>(std::llround(g.time / 1e-3)));
  const auto slot = slots(sim.particles);
  const auto ts = template_spheres(c);
  double worst = 0;
  const bonds::BondList& b = c.bonds->bonds();
  for (std::size_t k = 0; k < b.size(); ++k) {
    const std::size_t i = slot.at(b.id_i[k]), j = slot.at(b.id_j[k]);
    ASSERT_EQ(ts[i].first, ts[j].first);
    const auto& t = c.pour->grain_template(ts[i].first);
    const double d0 = norm(t.centres[ts[j].second] - t.centres[ts[i].second]);
    const double d = norm(sim.particles.x[j] - sim.particles.x[i]);
    worst = std::max(worst, std::abs(d - d0) / d0);
  }
  // 1e-5: a free-falling grain carries no load but the Hertz repulsion of sub-spheres the packing
  // left overlapping, by at most 1e-4 r (cluster_packing.hpp): with E* = 5.5e7 Pa, r ≈ 0.35 mm,
  // δ ≤ 3.5e-8 m that is F = 4/3 E* √(r/2) δ^1.5 ≤ 1.3e-4 N, which a bond of stiffness
  // k_n π r̄² ≈ 3.8e4 N/m answers with ≤ 3.5e-9 m, 5e-6 of the ≈ 0.7 mm distance. A wrongly
  // rotated or wrongly paired sub-sphere changes a distance by a good part of itself.
  EXPECT_LT(worst, 1e-5) << "largest relative change of a bonded distance";
}

TEST(GrainPour, PouredMassIsTheCountTimesTheTemplateMass) {
  // by count: 10 grains of two templates; by mass: as many grains as reach 5 template masses
  Poured by_count(case_text(2, pour_with("count = 10", 1)));
  by_count.sim().run(4000);
  ASSERT_EQ(by_count.pour->poured(), 10u);
  const ParticleStore& p = by_count.sim().particles;
  const double ms = by_count.pour->sphere_mass(0), mg = by_count.pour->grain_mass(0);
  double total = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.mass[i], ms);  // every sub-sphere carries exactly the template's share
    total += p.mass[i];
  }
  // the grain mass is ρ V of the ellipsoid (its sub-spheres carry it; round-off of 6 terms)
  const double v = std::numbers::pi / 6 * 3e-3 * 2e-3 * 1.6e-3;
  EXPECT_NEAR(mg, 1450.0 * v, 1e-14 * 1450.0 * v);
  // the total is the same 60 equal terms summed in another grouping: round-off ≤ 60 ulp
  EXPECT_NEAR(total, 10 * mg, 60 * std::numeric_limits<double>::epsilon() * 10 * mg);
  EXPECT_EQ(by_count.pour->poured_mass(), [&] {
    double s = 0;  // the module sums whole grains in pour order
    for (int k = 0; k < 10; ++k) s += mg;
    return s;
  }());

  // mass target 4.5 grain masses: the pour stops at the grain that reaches it, the 5th
  const std::string target = fmt::format("mass = {:.17g}", 4.5 * mg);
  Poured by_mass(case_text(2, pour_with(target, 1)));
  by_mass.sim().run(10000);
  EXPECT_EQ(by_mass.pour->poured(), 5u);
  EXPECT_EQ(by_mass.sim().particles.size(), 30u);
  EXPECT_GE(by_mass.pour->poured_mass(), 4.5 * mg);
}

TEST(GrainPour, OrientationsRepeatWithTheSeedAndChangeWithIt) {
  auto orientations = [](int seed) {
    Poured c(case_text(seed, "count = 8"));
    c.sim().run(2500);
    EXPECT_EQ(c.pour->poured(), 8u);
    std::vector<std::array<double, 4>> q;
    for (const auto& g : c.pour->grains()) q.push_back(g.rotation);
    return q;
  };
  const auto a = orientations(7), b = orientations(7), c = orientations(8);
  EXPECT_EQ(a, b);
  ASSERT_EQ(a.size(), c.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NE(a[k], c[k]);
}

TEST(GrainPour, SubSpheresSitWhereTheRecordedOrientationPutsThem) {
  // right after the step that inserted them (inserted after that step's drift), the sub-spheres
  // are exactly centre + R c for the recorded quaternion
  Poured c(case_text(3, "count = 4"));
  while (c.pour->poured() == 0 && c.sim().time < 2e-3) c.sim().step();
  ASSERT_EQ(c.pour->poured(), 4u);
  const auto ts = template_spheres(c);
  const ParticleStore& p = c.sim().particles;
  const auto& g = p.field(p.field_index("grain"));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& rec = c.pour->grains().at(static_cast<std::size_t>(g[i]));
    const auto r = bonds::rotation_matrix(rec.rotation);
    const Vec3 body = c.pour->grain_template(ts[i].first).centres[ts[i].second];
    const Vec3 x = rec.centre + Vec3{dot(r[0], body), dot(r[1], body), dot(r[2], body)};
    EXPECT_EQ(p.x[i], x);  // the same arithmetic as the placement: bit for bit
  }
}

TEST(GrainPour, OrientationsAreIsotropic) {
  // 3000 grains in one round into a box 20 grain lengths wide (few rejections to bias the
  // orientations); for a uniformly random rotation R every entry has mean 0 and mean square 1/3
  // (E[R] = 0 and E[R_ij²] = 1/3 for the Haar measure on SO(3))
  ct::GrainPourKeys big = pour_with("count = 3000");
  big.rate = 1.0e9;
  big.spheres_per_grain = 2;
  big.lo = {-0.03, -0.03, 0.0};
  big.hi = {0.03, 0.03, 0.06};
  const std::string text = case_text(4, big);
  Poured c(text);
  while (c.pour->poured() < 3000 && c.sim().time < 3e-3) c.sim().step();
  ASSERT_EQ(c.pour->poured(), 3000u);
  // these came in at the first step, before that step's bond sweep (create_at = 0): the sweep
  // finds the same pairs and bonds none of them twice
  std::size_t template_bonds = 0;
  for (const auto& g : c.pour->grains())
    template_bonds += c.pour->grain_template(g.templ).bonds.size();
  EXPECT_EQ(c.pour->grains().front().time, c.sim().dt);
  EXPECT_EQ(c.bonds->bonds().size(), template_bonds);
  const double n = 3000;
  double mean[3][3] = {}, square[3][3] = {};
  for (const auto& g : c.pour->grains()) {
    const auto r = bonds::rotation_matrix(g.rotation);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        mean[i][j] += r[i][j] / n;
        square[i][j] += r[i][j] * r[i][j] / n;
      }
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      // 4.5 standard errors (a false alarm about once in 10^5 per entry, 18 entries): Var R_ij =
      // 1/3, Var R_ij² = E[R_ij⁴] − 1/9 = 1/5 − 1/9 = 4/45 (a unit vector's component)
      EXPECT_NEAR(mean[i][j], 0, 4.5 * std::sqrt(1.0 / 3 / n)) << i << j;
      EXPECT_NEAR(square[i][j], 1.0 / 3, 4.5 * std::sqrt(4.0 / 45 / n)) << i << j;
    }
}

TEST(GrainPour, CheckpointMidPourRestartsBitForBit) {
  const std::string text = case_text(
      5,
      "count = 16\nlayers = 2\nend = 0.004\nvelocity = [0.0, 0.0, -0.2]\nvelocity_spread = 0.05");
  Poured straight(text), resumed(text);
  straight.sim().run(2500);  // rounds at 1 and 2 ms in, 3 and 4 ms to come
  ASSERT_GT(straight.pour->poured(), 0u);
  ASSERT_LT(straight.pour->poured(), 16u);
  Archive a;
  straight.sim().save(a);
  straight.sim().run(6000);
  resumed.sim().load(a);
  resumed.sim().run(6000);
  ASSERT_EQ(straight.pour->poured(), 16u);
  const ParticleStore &p = straight.sim().particles, &q = resumed.sim().particles;
  EXPECT_EQ(p.id, q.id);
  EXPECT_EQ(p.x, q.x);
  EXPECT_EQ(p.v, q.v);
  EXPECT_EQ(p.w, q.w);
  EXPECT_EQ(p.mass, q.mass);
  for (const char* f : {"grain", "layer", "batch"})
    EXPECT_EQ(p.field(p.field_index(f)), q.field(q.field_index(f))) << f;
  ASSERT_EQ(straight.pour->grains().size(), resumed.pour->grains().size());
  for (std::size_t k = 0; k < straight.pour->grains().size(); ++k) {
    const auto &g = straight.pour->grains()[k], &h = resumed.pour->grains()[k];
    EXPECT_EQ(g.rotation, h.rotation);
    EXPECT_EQ(g.centre, h.centre);
    EXPECT_EQ(g.batch, h.batch);
    EXPECT_EQ(g.layer, h.layer);
  }
  EXPECT_EQ(straight.bonds->bonds().id_i, resumed.bonds->bonds().id_i);
  EXPECT_EQ(straight.bonds->bonds().id_j, resumed.bonds->bonds().id_j);
  // layers are the two time windows of [0, 4 ms]: the round at 1 ms → 1; 2, 3, 4 ms → 2
  for (const auto& g : straight.pour->grains())
    EXPECT_EQ(g.layer, g.time < 2e-3 - 1e-9 ? 1u : 2u) << g.time;
}

TEST(GrainPour, BadKeysAreRefusedWithFileLineAndKey) {
  struct Bad {
    std::string extra, key;  // extra [[insert]] lines; the dotted key the message must name
  };
  const std::vector<Bad> bad = {
      {"count = 4\nmass = 0.1", "insert[0]"},         // two targets
      {"", "insert[0]"},                              // no target
      {"count = 0", "insert[0].count"},               // not a grain
      {"mass = -1.0", "insert[0].mass"},              // negative mass
      {"count = 4\nlayers = 3", "insert[0].layers"},  // time windows need an end
      {"count = 4\nstart = 0.2\nend = 0.1", "insert[0].end"},
      {"count = 4\nstart = 0.0\nend = 0.01\nvelocity = [0.0, 0.0]", "insert[0].velocity"},
      {"count = 4\nattempts = 0", "insert[0].attempts"},
      {"count = 4\nvelocity_spread = -1.0", "insert[0].velocity_spread"},
      {"count = 4\nsolid_fraction = 0.9", "insert[0].solid_fraction"},
      {"count = 4\nrat = 5.0", "insert[0].rat"},  // unknown (a typo of rate)
  };
  for (const Bad& b : bad) {
    try {
      Poured c(case_text(1, b.extra));
      ADD_FAILURE() << "accepted: " << b.extra;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "pour.toml") << b.extra;
      EXPECT_EQ(e.key(), b.key) << b.extra << ": " << e.what();
      EXPECT_GT(e.line(), 0) << b.extra << ": " << e.what();
    }
  }
  // keys of the case text itself: a zero interval, an unknown mode, a missing rate (the table is
  // named, the message names the key)
  struct Changed {
    std::function<void(ct::GrainPourKeys&)> change;
    std::string key;
    bool names_rate = false;  // the message must name the missing key 'rate'
  };
  const std::vector<Changed> changed = {
      {[](ct::GrainPourKeys& k) { k.interval = 0.0; }, "insert[0].interval"},
      {[](ct::GrainPourKeys& k) { k.mode = "drip"; }, "insert[0].mode"},
      {[](ct::GrainPourKeys& k) { k.rate = 0.0; }, "insert[0]", true}};  // rate 0: left out
  for (const auto& [change, key, names_rate] : changed) {
    ct::GrainPourKeys k = pour_with("count = 4");
    change(k);
    try {
      Poured c(case_text(1, k));
      ADD_FAILURE() << "accepted a change of " << key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key) << e.what();
      EXPECT_GT(e.line(), 0) << e.what();
      if (names_rate) {
        EXPECT_NE(std::string(e.what()).find("'rate'"), std::string::npos) << e.what();
      }
    }
  }
}

TEST(GrainPour, GrainBreakageCountsPouredGrains) {
  // [grain_breakage] sees no grain at the start and each poured grain once it is in, with its
  // layer and the template's mass; none is broken (no bond fails in free fall)
  const std::string text =
      case_text(6, "count = 8\nlayers = 2\nend = 0.002") + "[grain_breakage]\nbroken_below = 0.9\n";
  const CaseFile f = CaseFile::parse(text, "pour.toml");
  io::DemCase dem = io::build_dem_case(f.root());
  const bonds::BondsModule* b = io::add_bonds(f.root(), dem);
  bonds::GrainBreakageModule* g = io::add_grain_breakage(f.root(), dem, b);
  ASSERT_NE(g, nullptr);
  io::decide_time_step(dem);
  f.reject_unknown();
  bonds::GrainPourModule* pour = nullptr;
  for (const auto& m : dem.sim->modules)
    if (auto* p = dynamic_cast<bonds::GrainPourModule*>(m.get())) pour = p;
  dem.sim->step();
  EXPECT_EQ(g->grains(), 0u);
  dem.sim->run(3000);
  ASSERT_EQ(pour->poured(), 8u);
  ASSERT_EQ(g->grains(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_EQ(g->grain_layer(k), pour->grains()[k].layer);
    EXPECT_FALSE(g->broken()[k]);
  }
  for (double largest : g->largest_fractions(*dem.sim))
    EXPECT_NEAR(largest, 1.0, 1e-12);  // whole grains: one fragment (round-off of the sums)
}

TEST(GrainPour, EveryKeyOfAPourIsDocumented) {
  const std::string doc = comminute::testing::read_source_file("docs/case-file.md");
  ASSERT_FALSE(doc.empty());
  Poured c(case_text(1,
                     "mass = 1e-3\nstart = 0.001\nend = 0.01\nlayers = 2\nattempts = 20\n"
                     "velocity = [0.0, 0.0, -0.1]\nvelocity_spread = 0.01"));
  comminute::testing::expect_used_keys_documented(c.file, doc);
}
