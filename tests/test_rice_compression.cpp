// Issue 11, test 5: confined compression of a bed of bonded rice grains (a small version of
// examples/rice_compression: fewer grains, fewer sub-spheres). The piston moves down at a
// constant speed to 6 MPa; at 2, 3, 4, 5 and 6 MPa the test reads the breakage per layer and the
// void ratio. Checks: breakage probability rises with stress and is higher in the top layers
// (next to the moving piston; wall friction takes load off the lower layers, Janssen) than in the
// bottom ones; the void ratio falls linearly with log stress past yield (normal compression line).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "comminute/io/case/bonds_case.hpp"
#include "comminute/io/case/cluster_case.hpp"
#include "comminute/io/case/dem_case.hpp"

using namespace comminute;

namespace {

constexpr const char* kCase = R"(
[simulation]
seed = SEED
end_time = 0.5
gravity = [0.0, 0.0, -9.81]
skin = 1.2e-4
[contact]
model = "hertz_mindlin"
[materials.rice]
density = 1450.0
youngs_modulus = 1.0e9
poisson_ratio = 0.3
[materials.plexiglass]
density = 1180.0
youngs_modulus = 3.0e9
poisson_ratio = 0.35
[interaction]
restitution = 0.3
friction = 0.4
[[walls]]
name = "die"
type = "cylinder"
side = "inside"
caps = false
center = [0.0, 0.0, 0.0275]
axis = [0.0, 0.0, 1.0]
radius = 0.01
length = 0.055
material = "plexiglass"
[[walls]]
name = "floor"
type = "plane"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
material = "plexiglass"
[[walls]]
name = "piston"
type = "plane"
point = [0.0, 0.0, GRAINS_TOP]
normal = [0.0, 0.0, -1.0]
material = "plexiglass"
control = { mode = "servo", target_stress = 7.0e6, area = 3.14159e-4, gain = 2.0e-3, max_speed = 0.25 }
[[insert]]
type = "clusters"
material = "rice"
shape = "ellipsoid"
length = 6.0e-3
width = 3.0e-3
thickness = 2.2e-3
spheres_per_grain = SPHERES
templates = 4
count = GRAINS
layers = 5
attempts = 20000
region = { shape = "cylinder", center = [0.0, 0.0, GRAINS_MID], axis = [0.0, 0.0, 1.0], radius = 0.0099, length = GRAINS_HEIGHT }
[bonds]
law = "bilinear_cohesive"
within_grain = true
gap_tolerance = 1.0e-4
penalty_stiffness = 1.0e11
normal_strength = 2.5e6
shear_strength = 2.5e6
mode_I_toughness = 150.0
mode_II_toughness = 300.0
bk_exponent = 2.0
[grain_breakage]
broken_below = 0.9
piston = "piston"
floor = "floor"
area = 3.14159e-4
)";

std::string replace_all(std::string s, const std::string& key, const std::string& value) {
  for (auto k = s.find(key); k != std::string::npos; k = s.find(key, k + value.size()))
    s.replace(k, key.size(), value);
  return s;
}

struct Level {
  double stress = 0;                   // Pa
  std::vector<double> probability;     // per layer 1…5
  std::vector<double> broken, grains;  // per layer 1…5: broken grains, grains
  double overall = 0, void_ratio = 0;
};

std::vector<Level> compress(int grains, int spheres, double height, int seed) {
  std::string text = replace_all(kCase, "GRAINS_TOP", std::to_string(height + 5e-4));
  text = replace_all(text, "SEED", std::to_string(seed));
  text = replace_all(text, "GRAINS_MID", std::to_string(0.5 * height));
  text = replace_all(text, "GRAINS_HEIGHT", std::to_string(height));
  text = replace_all(text, "GRAINS", std::to_string(grains));
  text = replace_all(text, "SPHERES", std::to_string(spheres));
  const CaseFile file = CaseFile::parse(text, "rice_test.toml");
  io::DemCase dem = io::build_dem_case(file.root());
  const bonds::BondsModule* b = io::add_bonds(file.root(), dem);
  bonds::GrainBreakageModule* g = io::add_grain_breakage(file.root(), dem, b);
  io::decide_time_step(dem);
  file.reject_unknown();
  Simulation& sim = *dem.sim;
  std::vector<Level> out;
  const std::vector<double> levels{1e6, 2e6, 3e6, 4e6, 5e6, 6e6};
  while (out.size() < levels.size() && sim.time < 0.3) {
    sim.step();
    if (!g->grains()) continue;
    const bonds::BedSample bed = g->bed(sim);
    if (bed.stress < levels[out.size()]) continue;
    Level l;
    l.stress = bed.stress;
    l.void_ratio = bed.void_ratio;
    std::vector<double> n(6, 0), broken(6, 0);
    for (std::size_t k = 0; k < g->grains(); ++k) {
      n[g->grain_layer(k)] += 1;
      broken[g->grain_layer(k)] += g->broken()[k];
      l.overall += g->broken()[k];
    }
    l.overall /= static_cast<double>(g->grains());
    for (int k = 1; k <= 5; ++k) {
      l.probability.push_back(broken[k] / n[k]);
      l.broken.push_back(broken[k]);
      l.grains.push_back(n[k]);
    }
    out.push_back(l);
  }
  return out;
}

}  // namespace

// The beds of the test: the first eight seeds whose grain templates hold together (seeds 4 and 6
// draw a six-sphere template that falls apart at the gap tolerance, which the builder refuses).
constexpr std::array<int, 8> kSeeds{1, 2, 3, 5, 7, 8, 9, 10};

TEST(RiceCompression, BreakageRisesWithStressFromTheTopAndVoidRatioFollowsTheNcl) {
  // Eight beds of 75 grains (15 per layer), one per seed, each compressed to 6 MPa: the layer
  // order is judged on 120 grains per layer instead of 15 (one bed sits within its own scatter:
  // 30 grains per pair of layers gave 0.60 against 0.67).
  std::array<double, 5> broken{}, grains{};  // at 6 MPa, pooled over the beds, layers 1 (bottom)…5
  std::vector<double> mean_e(6, 0.0), log_stress(6, 0.0);
  for (const int seed : kSeeds) {
    const std::vector<Level> levels = compress(75, 6, 0.02, seed);
    ASSERT_EQ(levels.size(), 6u) << "seed " << seed << ": the piston did not reach 6 MPa";
    // breakage rises with stress: broken grains stay broken, so the count can only grow; the
    // check is that it does grow between 2 and 6 MPa, from a state where not all are broken
    EXPECT_LT(levels[1].overall, 1.0) << "seed " << seed;
    EXPECT_GT(levels[5].overall, levels[1].overall) << "seed " << seed;
    for (std::size_t k = 0; k < levels.size(); ++k) {
      if (k > 0) {
        EXPECT_LT(levels[k].void_ratio, levels[k - 1].void_ratio) << "seed " << seed;
      }
      mean_e[k] += levels[k].void_ratio / static_cast<double>(kSeeds.size());
      log_stress[k] += std::log(levels[k].stress) / static_cast<double>(kSeeds.size());
    }
    for (std::size_t layer = 0; layer < 5; ++layer) {
      broken[layer] += levels[5].broken[layer];
      grains[layer] += levels[5].grains[layer];
    }
    RecordProperty("seed_" + std::to_string(seed),
                   std::to_string(levels[5].overall) + " layers " +
                       std::to_string(levels[5].probability[0]) + " " +
                       std::to_string(levels[5].probability[1]) + " " +
                       std::to_string(levels[5].probability[2]) + " " +
                       std::to_string(levels[5].probability[3]) + " " +
                       std::to_string(levels[5].probability[4]));
  }
  // From the top layer to the bottom (next to the piston the bed breaks more; wall friction takes
  // load off the lower layers, Janssen), pooled over the beds at 6 MPa: the two top layers break
  // more than the two bottom ones, and the broken fraction rises with the layer's height in the
  // least-squares sense (Cochran–Armitage trend over the five layers, weights −2…2). Each grain is
  // a Bernoulli trial: the standard error of the pair difference, √(p̄(1−p̄)(1/n_top + 1/n_bottom)),
  // is 0.045 at 240 grains per pair. Measured: top pair 0.504, bottom pair 0.375, a difference of
  // 2.85 standard errors (the spread of the eight beds' own differences gives 3.0); trend z = 2.83.
  // A rounding change redraws the beds' breakage: it flips either check with a chance of about
  // Φ(−2.8) ≈ 0.3 % (one bed alone: 0.60 against 0.67, inside its scatter of ±0.13), while beds
  // without the gradient would fail each check half the time. (The profile is not monotone: the
  // middle layer breaks most, 0.64, bottom layer 0.35, top layer 0.50.)
  const double top = (broken[3] + broken[4]) / (grains[3] + grains[4]);
  const double bottom = (broken[0] + broken[1]) / (grains[0] + grains[1]);
  const double pooled = (broken[0] + broken[1] + broken[3] + broken[4]) /
                        (grains[0] + grains[1] + grains[3] + grains[4]);
  const double se = std::sqrt(pooled * (1 - pooled) *
                              (1 / (grains[3] + grains[4]) + 1 / (grains[0] + grains[1])));
  double all = 0, n_all = 0, t = 0, var_w = 0, sum_w = 0;
  for (std::size_t layer = 0; layer < 5; ++layer) {
    all += broken[layer];
    n_all += grains[layer];
  }
  const double p_all = all / n_all;
  for (std::size_t layer = 0; layer < 5; ++layer) {
    const double w = static_cast<double>(layer) - 2;
    t += w * (broken[layer] - grains[layer] * p_all);
    var_w += grains[layer] * w * w;
    sum_w += grains[layer] * w;
  }
  const double trend_z = t / std::sqrt(p_all * (1 - p_all) * (var_w - sum_w * sum_w / n_all));
  RecordProperty("top_pair", std::to_string(top));
  RecordProperty("bottom_pair", std::to_string(bottom));
  RecordProperty("pair_difference_in_standard_errors", std::to_string((top - bottom) / se));
  RecordProperty("trend_z", std::to_string(trend_z));
  EXPECT_GT(top, bottom);
  EXPECT_GT(trend_z, 0);
  // normal compression line: past yield (2 to 6 MPa) e falls with log σ, linearly: the
  // least-squares line through (ln σ, mean e over the beds) explains at least 90 % of the
  // variance (R² ≥ 0.9; a bed's e decreases in steps where grains break, which scatters it about
  // the line; one bed alone gave R² from 0.90 to 0.99 over the seeds)
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  const double n = 5;
  for (std::size_t k = 1; k < mean_e.size(); ++k) {
    const double x = log_stress[k], y = mean_e[k];
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    syy += y * y;
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double r2 = std::pow(n * sxy - sx * sy, 2) / ((n * sxx - sx * sx) * (n * syy - sy * sy));
  RecordProperty("compression_index_ln", std::to_string(-slope));
  RecordProperty("r2", std::to_string(r2));
  EXPECT_LT(slope, 0);
  EXPECT_GE(r2, 0.9);
}
