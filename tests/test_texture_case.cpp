// Texture and liberation from a case file: the example's keys are read and documented, wrong
// input is refused, and a one-phase textured drop-weight run stays exactly one-phase
// (issue 12, test 5 in the running engine).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "comminute/analysis/liberation_observer.hpp"
#include "comminute/breakage/texture/texture_module.hpp"
#include "comminute/breakage/texture/texture_volume.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/breakage_case.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "comminute/io/case/output_case.hpp"
#include "comminute/io/case/texture_case.hpp"
#include "source_file.hpp"
#include "temp_dir.hpp"

using namespace comminute;

namespace {

std::string example_text() {
  std::ifstream in(std::string(COMMINUTE_SOURCE_DIR) +
                   "/examples/texture/drop_weight_texture.toml");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The example with `from` replaced by `to` (the text must contain `from`).
std::string edited(const std::string& from, const std::string& to) {
  std::string t = example_text();
  const auto at = t.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) t.replace(at, from.size(), to);
  return t;
}

struct Built {
  io::DemCase dem;
  breakage::texture::TextureModule* texture = nullptr;
};

Built build(const std::string& text) {
  CaseFile f = CaseFile::parse(text, "texture_case.toml");
  Built b{io::build_dem_case(f.root()), nullptr};
  io::add_breakage(f.root(), b.dem);
  b.texture = io::add_texture(f.root(), b.dem);
  f.reject_unknown();
  return b;
}

}  // namespace

// The texture examples: the drop-weight test and the template of the HPGR texture study (its 8
// generated cases are checked by tests/scripts/test_hpgr_texture_sweep.sh).
TEST(TextureCase, ExampleKeysAreReadAndDocumented) {
  const std::string doc = comminute::testing::read_source_file("docs/breakage.md"),
                    case_doc = comminute::testing::read_source_file("docs/case-file.md");
  for (const char* example :
       {"/examples/texture/drop_weight_texture.toml", "/examples/hpgr_texture/hpgr_texture.toml"}) {
    SCOPED_TRACE(example);
    CaseFile f = CaseFile::load(std::string(COMMINUTE_SOURCE_DIR) + example);
    io::DemCase dem = io::build_dem_case(f.root());
    ASSERT_NE(io::add_breakage(f.root(), dem), nullptr);
    ASSERT_NE(io::add_texture(f.root(), dem), nullptr);
    if (auto o = f.root().optional_table("output")) io::read_output_options(*o);
    f.reject_unknown();
    for (const std::string& path : f.used_keys()) {
      std::string leaf = path.substr(path.find_last_of('.') + 1);
      leaf = leaf.substr(0, leaf.find('['));
      if (path.find('.') == std::string::npos) {
        EXPECT_NE(case_doc.find("[" + leaf), std::string::npos) << path;
        continue;
      }
      if (path.rfind("materials.", 0) == 0 && path.find('.', 10) == std::string::npos) continue;
      if (leaf == "breakage" || leaf == "progeny" || leaf == "generator" || leaf == "phases" ||
          leaf == "grains")
        continue;  // sub-tables
      EXPECT_TRUE(doc.find("`" + leaf + "`") != std::string::npos ||
                  case_doc.find("`" + leaf + "`") != std::string::npos)
          << path << " is not documented";
    }
  }
}

TEST(TextureCase, WrongInputIsRefused) {
  // both an image and a generator
  EXPECT_THROW(build(edited("[texture]\n", "[texture]\nimage = \"ore.raw\"\n")), InputError);
  // liberation without texture
  {
    std::string t = example_text();
    const auto a = t.find("[texture]"), b = t.find("[liberation]");
    t.erase(a, b - a);
    EXPECT_THROW(build(t), InputError);
  }
  // the criterion's relative strengths differ from the phases'
  EXPECT_THROW(build(edited("relative_strength = [1.0, 2.0]", "relative_strength = [1.0, 3.0]")),
               InputError);
  // a grain phase without a phase table, fractions out of range, an unknown key
  EXPECT_THROW(build(edited("phase = 1\n", "phase = 2\n")), InputError);
  EXPECT_THROW(build(edited("volume_fraction = 0.233", "volume_fraction = 1.5")), InputError);
  EXPECT_THROW(build(edited("resolution = 16", "resolution = 16\nresolutoin = 8")), InputError);
  EXPECT_THROW(build(edited("source = \"domain\"", "source = \"outlets\"")), InputError);
  // an image whose labels name a phase that is not defined
  const comminute::testing::TestDir dir;
  const std::string raw = (dir.path() / "ore.raw").string();
  breakage::texture::write_raw_texture(
      raw, breakage::texture::TextureVolume(
               2, 2, 2, 1e-3, {0, 1, 2, 0, 0, 1, 0, 2},
               {{"a", 1000.0, 1.0}, {"b", 2000.0, 2.0}, {"c", 3000.0, 1.0}}));
  std::string text = example_text();
  const auto g = text.find("[texture.generator]"), l = text.find("[liberation]");
  text.replace(g, l - g, "");
  text.replace(text.find("[texture]\n"), 10, "[texture]\nimage = \"" + raw + "\"\n");
  EXPECT_THROW(build(text), InputError);
}

// Test 5 in the engine: a one-phase image gives every particle, fragments of every generation
// included, composition exactly 1 and liberation exactly 1 at every threshold, before and after
// breakage; the sampled particles take the phase's density.
TEST(TextureCase, OnePhaseImageThroughBreakage) {
  const comminute::testing::TestDir dir;
  const std::string raw = (dir.path() / "one.raw").string();
  breakage::texture::write_raw_texture(
      raw, breakage::texture::TextureVolume(8, 8, 8, 1e-3, std::vector<std::uint8_t>(512, 0),
                                            {{"quartz", 2650.0, 1.0}}));
  std::string text = example_text();
  const auto p = text.find("[[texture.phases]]"), l = text.find("[liberation]");
  text.replace(p, l - p,
               "[[texture.phases]]\nname = \"quartz\"\ndensity = 2650.0\n"
               "relative_strength = 1.0\n\n");
  text.replace(text.find("[texture]\n"), 10, "[texture]\nimage = \"" + raw + "\"\n");
  text.replace(text.find("relative_strength = [1.0, 2.0]"), 30, "relative_strength = [1.0]");
  text.replace(text.find("target_phase = 1"), 16, "target_phase = 0");
  text.replace(text.find("count = 200"), 11, "count = 12");
  Built b = build(text);
  ASSERT_NE(b.texture, nullptr);
  Simulation& sim = *b.dem.sim;
  io::decide_time_step(b.dem);
  sim.setup();
  const analysis::LiberationObserver* lib = nullptr;
  for (auto& m : sim.modules)
    if (auto* o = dynamic_cast<const analysis::LiberationObserver*>(m.get())) lib = o;
  ASSERT_NE(lib, nullptr);
  const std::vector<double> rho{2650.0};
  auto check = [&] {
    const auto ps = lib->particles(sim);
    EXPECT_EQ(ps.size(), sim.particles.size());
    for (const auto& q : ps) EXPECT_EQ(q.volume_fraction[0], 1.0);  // exact: one phase
    for (double theta : {1.0, 0.95, 0.9})
      EXPECT_EQ(analysis::liberation_degree(ps, rho, 0, theta), 1.0);
  };
  check();
  EXPECT_NEAR(sim.particles.mass[0],
              2650.0 * 4.0 / 3.0 * M_PI * std::pow(sim.particles.radius[0], 3),
              1e-12 * sim.particles.mass[0]);  // one product of doubles
  while (sim.time < 0.0008) sim.step();
  EXPECT_GT(sim.particles.size(), 12u);  // fragments were born
  check();
  EXPECT_EQ(b.texture->pool().size(), sim.particles.size());  // one texture each, none stale
}

// The outlet stream as the source: the particles an outlet removed, with their compositions,
// over the whole run or only the last `window` seconds.
TEST(TextureCase, LiberationOfTheOutletStreamOverAWindow) {
  auto run = [](const std::string& window) {
    std::string text = edited("source = \"domain\"", "source = \"outlets\"\nwindow = " + window);
    text.replace(text.find("count = 200"), 11, "count = 30");
    text +=
        "\n[[outlets]]\nname = \"side\"\n"
        "region = { shape = \"box\", lo = [-1.0, -1.0, -1.0], hi = [0.1, 1.0, 1.0] }\n";
    Built b = build(text);
    Simulation& sim = *b.dem.sim;
    io::decide_time_step(b.dem);
    sim.setup();
    const std::size_t before = sim.particles.size();
    for (int s = 0; s < 20; ++s) sim.step();
    const analysis::LiberationObserver* lib = nullptr;
    for (auto& m : sim.modules)
      if (auto* o = dynamic_cast<const analysis::LiberationObserver*>(m.get())) lib = o;
    EXPECT_NE(lib, nullptr);
    const auto ps = lib->particles(sim);
    return std::make_pair(ps, before - sim.particles.size());
  };
  const auto [all, removed] = run("0.0");
  EXPECT_GT(removed, 0u);  // the fill region reaches into the outlet's box
  ASSERT_EQ(all.size(), removed);
  for (const auto& q : all) {
    EXPECT_NEAR(q.volume_fraction[0] + q.volume_fraction[1], 1.0, 1e-15);  // voxel fractions
    EXPECT_GT(q.mass, 0.0);
  }
  // removed in the first step, 19 steps (more than 1e-6 s) ago: outside a window of 1e-6 s
  const auto [recent, removed_again] = run("1e-6");
  EXPECT_EQ(removed_again, removed);
  EXPECT_TRUE(recent.empty());
}

namespace {

// The example with an 8^3 image that is all phase 1 ("strong", f_rel = 1000 against "weak", 1)
// and 12 particles; the text from `from` to the end of `through` replaced by `criterion`.
std::string all_strong_case(const std::filesystem::path& dir, const std::string& from,
                            const std::string& through, const std::string& criterion) {
  const std::string raw = (dir / "strong.raw").string();
  breakage::texture::write_raw_texture(
      raw, breakage::texture::TextureVolume(8, 8, 8, 1e-3, std::vector<std::uint8_t>(512, 1),
                                            {{"weak", 2650.0, 1.0}, {"strong", 2650.0, 1000.0}}));
  std::string text = example_text();
  const auto g = text.find("[texture.generator]"), l = text.find("[liberation]");
  text.replace(g, l - g, "");
  text.replace(text.find("[texture]\n"), 10, "[texture]\nimage = \"" + raw + "\"\n");
  const auto c = text.find(from), e = text.find(through, c) + through.size();
  text.replace(c, e - c, criterion);
  text.replace(text.find("relative_strength = 2.0"), 23, "relative_strength = 1000.0");
  text.replace(text.find("count = 200"), 11, "count = 12");
  return text;
}

// The case without [texture] and [liberation] (composition.0 = 1 by default).
std::string without_texture(std::string text) {
  text.erase(text.find("[texture]"), text.find("[[walls]]") - text.find("[texture]"));
  return text;
}

// True when some of the 12 particles broke in the first 0.8 ms (the impact on the anvil).
bool broken(const std::string& text) {
  Built b = build(text);
  Simulation& sim = *b.dem.sim;
  io::decide_time_step(b.dem);
  sim.setup();
  while (sim.time < 0.0008) sim.step();
  return sim.particles.size() > 12;
}

}  // namespace

// The texture feeds the composition criterion: an ore that is all phase 1, a thousand times
// stronger than phase 0, does not break at an impact that breaks the same particles when they
// carry no texture (composition.0 = 1 by default).
TEST(TextureCase, TextureFeedsTheCompositionCriterion) {
  const comminute::testing::TestDir dir;
  const std::string list = "relative_strength = [1.0, 2.0]";
  const std::string text =
      all_strong_case(dir.path(), list, list, "relative_strength = [1.0, 1000.0]");
  EXPECT_TRUE(broken(without_texture(text)));  // F_crit = F_CS: the 20 m/s impact (~2 kN)
  EXPECT_FALSE(broken(text));                  // F_crit = 1000 F_CS
}

// The phase-weighted option of tavares (docs/models.md eq. C2b) fed by the texture: an all-strong
// image with f_rel = 1000 keeps the particles whole at an impact (~200 J/kg) that breaks them
// without the texture (E50 ~ 60 J/kg); a list that differs from the phases' is refused.
TEST(TextureCase, TextureFeedsThePhaseWeightedTavares) {
  const comminute::testing::TestDir dir;
  const std::string text = all_strong_case(
      dir.path(), "criterion = \"composition_peak_force\"", "factor_sigma = 0.3",
      "criterion = \"tavares\"\ne_inf = 60.0\nsigma = 0.3\nrelative_strength = [1.0, 1000.0]");
  EXPECT_TRUE(broken(without_texture(text)));  // composition (1, 0): E ~ E50, below the impact
  EXPECT_FALSE(broken(text));                  // composition (0, 1): E times 1000
  std::string wrong = text;
  wrong.replace(wrong.find("relative_strength = [1.0, 1000.0]"), 33,
                "relative_strength = [1.0, 999.0]");
  EXPECT_THROW(build(wrong), InputError);
}

// A TIFF stack as the image: needs voxel_size (TIFF has no physical size), which a raw image
// must not have.
TEST(TextureCase, TiffStackImage) {
  const std::string tif = std::string(COMMINUTE_TEST_DATA) + "/texture/stack.tif";
  std::string text = example_text();
  const auto g = text.find("[texture.generator]"), l = text.find("[liberation]");
  text.replace(
      g, l - g,
      "[[texture.phases]]\nname = \"third\"\ndensity = 3000.0\nrelative_strength = 1.0\n\n");
  text.replace(text.find("relative_strength = [1.0, 2.0]"), 30,
               "relative_strength = [1.0, 2.0, 1.0]");
  std::string no_size = text;
  no_size.replace(no_size.find("[texture]\n"), 10, "[texture]\nimage = \"" + tif + "\"\n");
  EXPECT_THROW(build(no_size), InputError);
  text.replace(text.find("[texture]\n"), 10,
               "[texture]\nimage = \"" + tif + "\"\nvoxel_size = 1e-3\n");
  const Built b = build(text);
  ASSERT_NE(b.texture, nullptr);
  EXPECT_EQ(b.texture->volume().nz(), 3u);
  EXPECT_EQ(b.texture->volume().phases().size(), 3u);
}

// Masses follow the phases through breakage: the sampled particles have m = rho(C) V exactly; the
// fragments of one parent share its mass in proportion to rho(C_j) V_j (so m_j / (rho_j V_j) is one
// number per parent), and the particles plus the fines booked as mass keep the initial mass.
TEST(TextureCase, FragmentMassesFollowTheirPhases) {
  std::string text = edited("count = 200", "count = 12");
  Built b = build(text);
  Simulation& sim = *b.dem.sim;
  io::decide_time_step(b.dem);
  sim.setup();
  breakage::BreakageModule* brk = nullptr;
  for (auto& m : sim.modules)
    if (auto* x = dynamic_cast<breakage::BreakageModule*>(m.get())) brk = x;
  ASSERT_NE(brk, nullptr);
  const auto& p = sim.particles;
  const double rho[2] = {2650.0, 5180.0};
  auto density = [&](std::size_t i) {
    return p.field(p.field_index("composition.0"))[i] * rho[0] +
           p.field(p.field_index("composition.1"))[i] * rho[1];
  };
  auto final_volume = [&](std::size_t i) {
    const double r = std::max(p.radius[i], p.field(p.field_index("breakage.target_radius"))[i]);
    return 4.0 / 3.0 * M_PI * r * r * r;
  };
  const double m0 = p.total_mass();
  for (std::size_t i = 0; i < p.size(); ++i)  // a product and a sum of two: a few ulp
    EXPECT_NEAR(p.mass[i], density(i) * final_volume(i), 1e-14 * p.mass[i]);
  while (sim.time < 0.0008) sim.step();
  ASSERT_GT(p.size(), 12u);
  double fines = 0;
  for (double f : brk->fines_mass()) fines += f;
  // mass: the rule keeps each parent's sum up to rounding, over a few hundred breakages
  EXPECT_NEAR(p.total_mass() + fines, m0, 1e-12 * m0);
  std::map<double, double> factor;  // by parent id
  std::size_t siblings = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double parent = p.field(p.field_index("breakage.parent_id"))[i];
    if (parent == 0) continue;
    const double f = p.mass[i] / (density(i) * final_volume(i));
    const auto [it, fresh] = factor.emplace(parent, f);
    if (!fresh) {
      ++siblings;
      // voxel fractions are ratios of integers: the same density as in the rule, to rounding
      EXPECT_NEAR(f, it->second, 1e-12);
    }
  }
  EXPECT_GT(siblings, 100u);
  // The scale M / sum(rho_j V_j) is 1 but for voxel rounding: the blocks cover the parent's 16^3
  // voxels in proportion to V_j, each block count rounded by under one voxel; with ~50 fragments
  // that is < 50 of 4096 voxels, times a density contrast below 2: under 2.5 %.
  EXPECT_GE(factor.size(), 5u);
  for (const auto& [parent, f] : factor) EXPECT_NEAR(f, 1.0, 0.025) << parent;
}
