// Bond forces in the Love–Weber stress (issue 11): a column of four spheres held apart by gaps
// and joined by parallel bonds, pressed between a floor and a servo piston. No two spheres touch,
// so only the bonds carry the load through the column: the bed's axial stress, each layer's and
// the inner spheres' own stress must come out of the bond forces.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "case_sections.hpp"
#include "comminute/analysis/bed_statistics.hpp"
#include "temp_dir.hpp"

using namespace comminute;

namespace {

constexpr double kR = 1e-3;    // m, sphere radius
constexpr double kGap = 2e-5;  // m, between neighbouring spheres (bonded across it)
constexpr int kSpheres = 4;
constexpr double kForce = 10.0;                       // N, the piston's target
constexpr double kArea = std::numbers::pi * kR * kR;  // m², the bed region's cross-section
constexpr double kPitch = 2 * kR + kGap;              // m, centre distance
constexpr double kHeight = kSpheres * kPitch - kGap;  // m, column height unloaded

std::string case_text() {
  using namespace comminute::testing;
  return dem_sections({1, 1.0, 2e-7, 1e-4}, {"rock", 2500.0, 1.0e10, 0.25, 0.3, 0.0}) +
         plane_wall("floor", 0.0, 1.0, "rock") +
         plane_wall("piston", kHeight, -1.0, "rock",
                    fmt::format("control = {{ mode = \"servo\", target_force = {}, area = {}, "
                                "gain = 0.17, max_speed = 0.05 }}",
                                kForce, kArea)) +
         data_file_insert("rock", "column.data") +
         parallel_bond_section({3e-5, 1e12, 4e11, 1e9, 1e9}) +
         fmt::format(R"(
[bed_statistics]
shape = "cylinder"
origin = [0.0, 0.0, 0.0]
axis = [0.0, 0.0, 1.0]
radius = {r}
z_min = 0.0
z_max = 0.02
layers = {n}
every = 10
load_wall = "piston"
force_chains = false
)",
                     fmt::arg("r", kR), fmt::arg("n", kSpheres));
}

}  // namespace

TEST(BondStress, BondedColumnLoveWeberStressIsTheAppliedForcePerArea) {
  comminute::testing::TestDir dir;
  {
    std::ofstream data(dir.path() / "column.data");
    data << "# a column of spheres 20 um apart\n\n"
         << kSpheres << " atoms\n1 atom types\n\nAtoms # sphere\n\n";
    for (int k = 0; k < kSpheres; ++k)
      data << k + 1 << " 1 " << 2 * kR << " 2500 0 0 " << fmt::format("{:.12g}", kR + k * kPitch)
           << "\n";
  }
  const std::filesystem::path path = dir.path() / "column.toml";
  std::ofstream(path) << case_text();
  comminute::testing::LoadedCase loaded = comminute::testing::load_case(path);
  const bonds::BondsModule* bonded = loaded.bonds;
  Simulation& sim = *loaded.dem.sim;
  const analysis::BedStatistics* bed = nullptr;
  for (const auto& m : sim.modules)
    if (auto* b = dynamic_cast<const analysis::BedStatistics*>(m.get())) bed = b;
  ASSERT_NE(bed, nullptr);
  sim.setup();
  // 2 ms: the piston closes the ~20 um of wall overlap and bond shortening at 0.05 m/s within
  // 0.5 ms; the servo (gain ≈ 1/√(k m), a matched damper at the column's end) then absorbs the
  // column's axial vibration
  sim.run(10000);
  ASSERT_EQ(bonded->bonds().size(), static_cast<std::size_t>(kSpheres - 1));
  ASSERT_TRUE(bonded->failures().empty());

  // averages over the last 2000 steps (200 measurements): what is left of the vibration averages
  // out; its inertial terms are not part of the static stress
  const auto& rows = bed->rows();
  const auto& layers = bed->layer_rows();
  ASSERT_GE(rows.size(), 1000u);
  const std::size_t last = 200;
  double axial = 0, wall = 0, contacts = 0;
  std::vector<double> layer(kSpheres, 0.0);
  for (std::size_t k = rows.size() - last; k < rows.size(); ++k) {
    axial += rows[k].axial_stress / last;
    wall += rows[k].wall_axial_stress / last;
    contacts += rows[k].contacts;
  }
  for (std::size_t k = layers.size() - last * kSpheres; k < layers.size(); ++k)
    layer[static_cast<std::size_t>(layers[k].layer)] -= layers[k].stress[2] / last;
  const double applied = kForce / kArea;
  RecordProperty("axial_over_applied", std::to_string(axial / applied));
  RecordProperty("wall_over_applied", std::to_string(wall / applied));
  for (int k = 0; k < kSpheres; ++k)
    RecordProperty("layer" + std::to_string(k) + "_over_applied",
                   std::to_string(layer[k] / applied));
  // the servo holds the piston force at its target: the stress it applies is F / A
  EXPECT_NEAR(wall, applied, 0.005 * applied);
  // no two spheres touch: only the bonds carry the load from sphere to sphere (without their
  // part the contacts alone give 2R / h ≈ 0.25 of it: the two wall contacts' levers)
  EXPECT_EQ(contacts, 0.0);
  // Love–Weber over the column: Σ f ⊗ l / (A h) with the levers adding up to the distance
  // between the two wall contact points, i.e. h less half of each wall overlap (≈ 8 um each)
  // while h is measured to the top sphere's top: within 1 % (each lost um is 0.012 % of h;
  // measured 0.2 % low)
  EXPECT_NEAR(axial, applied, 0.01 * applied);
  // each layer holds one sphere: its stress is that sphere's moment over a quarter of A h; the
  // levers of an inner sphere's two bonds are half the pitch each, so (2R + gap)/(h/4) = 1.003;
  // an end sphere's wall lever is R less half its overlap: 1 % (measured +0.4 % and −0.7 %)
  for (int k = 0; k < kSpheres; ++k) EXPECT_NEAR(layer[k], applied, 0.01 * applied) << k;
  // an inner sphere's own stress: σ_zz = −F × pitch / V (its two bonds, lever pitch/2 each)
  const ParticleStore& p = sim.particles;
  const auto& szz = p.field(p.field_index("bed.stress_zz"));
  const double v = 4.0 / 3.0 * std::numbers::pi * kR * kR * kR;
  for (std::size_t i = 0; i < p.owned(); ++i) {
    if (p.x[i].z < 1.5 * kR || p.x[i].z > kHeight - 1.5 * kR) continue;  // the end spheres
    // 2 %: one step's value, not an average (the remaining vibration's force swing)
    EXPECT_NEAR(szz[i], -kForce * kPitch / v, 0.02 * kForce * kPitch / v) << "particle " << i;
  }
}
