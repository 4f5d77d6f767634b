// Issue 11, test 5: confined compression of a bed of bonded rice grains (a small version of
// examples/rice_compression: fewer grains, fewer sub-spheres). The piston moves down at a
// constant speed to 6 MPa; at 2, 3, 4, 5 and 6 MPa the test reads the breakage per layer and the
// void ratio. Checks: breakage probability rises with stress and is higher in the top layers
// (next to the moving piston; wall friction takes load off the lower layers, Janssen) than in the
// bottom ones; the void ratio falls linearly with log stress past yield (normal compression line).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "comminute/io/case/bonds_case.hpp"
#include "comminute/io/case/cluster_case.hpp"
#include "comminute/io/case/dem_case.hpp"

using namespace comminute;

namespace {

constexpr const char* kCase = R"(
[simulation]
seed = 1
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
  double stress = 0;                // Pa
  std::vector<double> probability;  // per layer 1…5
  double overall = 0, void_ratio = 0;
};

std::vector<Level> compress(int grains, int spheres, double height) {
  std::string text = replace_all(kCase, "GRAINS_TOP", std::to_string(height + 5e-4));
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
    for (int k = 1; k <= 5; ++k) l.probability.push_back(broken[k] / n[k]);
    out.push_back(l);
  }
  return out;
}

}  // namespace

TEST(RiceCompression, BreakageRisesWithStressFromTheTopAndVoidRatioFollowsTheNcl) {
  const std::vector<Level> levels = compress(75, 6, 0.02);
  ASSERT_EQ(levels.size(), 6u) << "the piston did not reach 6 MPa";
  for (const Level& l : levels)
    RecordProperty("at_" + std::to_string(static_cast<int>(l.stress / 1e6)) + "MPa",
                   std::to_string(l.overall) + " e=" + std::to_string(l.void_ratio) + " layers " +
                       std::to_string(l.probability[0]) + " " + std::to_string(l.probability[2]) +
                       " " + std::to_string(l.probability[4]));
  // breakage rises with stress: broken grains stay broken, so the count can only grow; the check
  // is that it does grow between 2 and 6 MPa, from a state where not all are broken
  EXPECT_LT(levels[1].overall, 1.0);
  EXPECT_GT(levels[5].overall, levels[1].overall);
  // from the top layer to the bottom: the two top layers (next to the piston) break more than the
  // two bottom ones at 6 MPa (30 grains per pair: a difference, not a fitted profile)
  const auto& p = levels[5].probability;
  EXPECT_GT(p[3] + p[4], p[0] + p[1]);
  // normal compression line: past yield (2 to 6 MPa) e falls with log σ, linearly: the
  // least-squares line through (ln σ, e) explains at least 90 % of the variance (R² ≥ 0.9; the
  // bed's e decreases in steps where grains break, which scatters it about the line)
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  const double n = 5;
  for (std::size_t k = 1; k < levels.size(); ++k) {
    const double x = std::log(levels[k].stress), y = levels[k].void_ratio;
    EXPECT_LT(levels[k].void_ratio, levels[k - 1].void_ratio);
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
