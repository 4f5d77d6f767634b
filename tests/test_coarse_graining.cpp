// Coarse graining ([coarse_graining], particles/coarse_graining.hpp; issue 13 point 3): the
// scaled pair parameters give contact forces k² and energies k³ times those of the primary
// particles (Feng & Owen 2014's exact scaling), the case keys are checked, and a settled bed of
// coarse particles (k = 2) has the bulk solid fraction and the vertical stress at depth of the
// same bed of primary particles.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "case_docs_check.hpp"
#include "case_sections.hpp"
#include "comminute/analysis/grid_statistics.hpp"
#include "comminute/contact/jkr_curve.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "comminute/io/case/output_case.hpp"
#include "comminute/io/output/vtk_writer.hpp"
#include "comminute/particles/coarse_graining.hpp"
#include "source_file.hpp"
#include "temp_dir.hpp"

using namespace comminute;

TEST(CoarseGraining, ScaledPairGivesForcesKSquaredAndEnergiesKCubed) {
  PairInput fine;
  fine.restitution = 0.21;
  fine.friction = 0.83;
  fine.dynamic_friction = 0.68;
  fine.rolling_friction = 0.1;
  fine.cohesion_energy_density = 5e4;
  fine.surface_energy = 0.27;  // J/m2, the mixer study's particle Γ
  for (double k : {2.0, 3.7}) {
    const CoarseGraining cg{k, 0.0};
    const PairInput coarse = cg.scaled(fine);
    // Bierwisch et al. 2009: restitution and friction unchanged (compared exactly: copied)
    EXPECT_EQ(coarse.restitution, fine.restitution);
    EXPECT_EQ(coarse.friction, fine.friction);
    EXPECT_EQ(coarse.dynamic_friction, fine.dynamic_friction);
    EXPECT_EQ(coarse.rolling_friction, fine.rolling_friction);
    EXPECT_EQ(coarse.cohesion_energy_density, fine.cohesion_energy_density);
    EXPECT_DOUBLE_EQ(coarse.surface_energy, k * fine.surface_energy);
    // the JKR curve of the coarse pair at the scaled overlap k δ and radius k R* is k² times the
    // primary pair's force (the contact radius k times) and its energy k³ times: the exact
    // scaling. The Newton solve converges to ~1e-12 relative; 1e-9 leaves room for rounding.
    const double E = 5e7 / (2 * (1 - 0.25 * 0.25)), R = 0.5e-3;  // E* of two equal spheres
    for (double delta : {-2e-7, 0.0, 1e-7, 1e-6, 1e-5}) {
      const JkrPoint f = jkr_point(delta, R, E, fine.surface_energy);
      const JkrPoint c = jkr_point(k * delta, k * R, E, coarse.surface_energy);
      EXPECT_NEAR(c.force, k * k * f.force, 1e-9 * std::abs(k * k * f.force) + 1e-18)
          << "k " << k << " delta " << delta;
      EXPECT_NEAR(c.contact_radius, k * f.contact_radius, 1e-9 * k * f.contact_radius);
      if (delta > 0) {
        const double ef = jkr_energy(delta, R, E, fine.surface_energy);
        const double ec = jkr_energy(k * delta, k * R, E, coarse.surface_energy);
        EXPECT_NEAR(ec, k * k * k * ef, 1e-9 * std::abs(k * k * k * ef)) << "delta " << delta;
      }
    }
    // pull-off 1.5 π Γ R* (Johnson, Kendall & Roberts 1971): k² times, like the Hertz force
    // (4/3) E* √R* δ^(3/2) at k δ, k R*
    EXPECT_NEAR(1.5 * std::numbers::pi * coarse.surface_energy * k * R,
                k * k * 1.5 * std::numbers::pi * fine.surface_energy * R, 1e-15);
  }
  EXPECT_DOUBLE_EQ((CoarseGraining{2.0, 0.0}).frequency_factor(), 1.0);
  EXPECT_DOUBLE_EQ((CoarseGraining{2.0, -1.0}).frequency_factor(), 0.5);
  EXPECT_DOUBLE_EQ((CoarseGraining{2.0, 1.0}).primary_diameter(2e-3), 1e-3);
  EXPECT_DOUBLE_EQ((CoarseGraining{2.0, 1.0}).primaries_per_particle(), 8.0);
}

namespace {

constexpr double kSide = 0.01;  // m, periodic box side

// A bed settled from a random fill in a box periodic in x and y on a floor: `count` spheres of
// diameter `d` (m), Hertz–Mindlin with friction and JKR adhesion (Γ of the primary particles),
// coarse-grained by `scale`; a grid of 1 mm layers averages over the last 50 ms of 0.25 s.
std::string bed_case(double d, int count, double scale, std::uint64_t seed,
                     double surface_energy = 0.01) {
  return fmt::format(
      R"(
[simulation]
seed = {seed}
end_time = 0.25
[periodic]
x = [0.0, {L}]
y = [0.0, {L}]
[contact]
model = "hertz_mindlin"
cohesion = "jkr"
[materials.powder]
density = 1670.0
youngs_modulus = 1.0e6
poisson_ratio = 0.25
[interaction]
restitution = 0.3
friction = 0.5
surface_energy = {gamma}
[coarse_graining]
scale = {scale}
frequency_exponent = -1.0
{floor}[[insert]]
type = "fill"
material = "powder"
count = {count}
region = {{ shape = "box", lo = [0.0, 0.0, 0.0], hi = [{L}, {L}, 0.05] }}
size = {{ distribution = "fixed", diameter = {d} }}
[grid_statistics]
shape = "box"
lo = [0.0, 0.0, 0.0]
hi = [{L}, {L}, 0.03]
cells = [1, 1, 30]
start = 0.2
every = 10
)",
      fmt::arg("seed", seed), fmt::arg("L", kSide), fmt::arg("scale", scale),
      fmt::arg("count", count), fmt::arg("d", d), fmt::arg("gamma", surface_energy),
      fmt::arg("floor", comminute::testing::plane_wall("floor", 0.0, 1.0, "powder")));
}

struct BedResult {
  double solid_fraction = 0;  // mean over the bulk layers
  double stress_zz = 0;       // Pa, mean vertical stress of the bulk layers
  double weight_above = 0;    // Pa, mean over the bulk layers of the weight above per area
};

constexpr std::size_t kBulkLo = 4, kBulkHi = 16;  // mm: the bulk layers

BedResult settle(double d, int count, double scale, std::uint64_t seed,
                 double surface_energy = 0.01) {
  const CaseFile f = CaseFile::parse(bed_case(d, count, scale, seed, surface_energy));
  io::DemCase c = io::build_dem_case(f.root());
  io::decide_time_step(c);
  f.reject_unknown();
  Simulation& sim = *c.sim;
  sim.setup();
  sim.run(static_cast<std::uint64_t>(std::ceil(c.end_time / sim.dt)));
  analysis::GridStatistics* g = nullptr;
  for (auto& m : sim.modules)
    if (auto* p = dynamic_cast<analysis::GridStatistics*>(m.get())) g = p;
  BedResult r;
  // bulk: 4–16 mm, above the floor's layering (2 coarse diameters) and below the free surface
  // (the bed is about 21 mm deep)
  const double n = static_cast<double>(kBulkHi - kBulkLo);
  for (std::size_t k = kBulkLo; k < kBulkHi; ++k) {
    r.solid_fraction += g->average(k).solid_fraction / n;
    r.stress_zz += g->average(k).stress[2] / n;
  }
  // the weight above height z per area, averaged over the band (0.01 mm steps)
  const int steps = 1200;
  for (int s = 0; s < steps; ++s) {
    const double z = 1e-3 * (kBulkLo + (kBulkHi - kBulkLo) * (s + 0.5) / steps);
    double above = 0;
    for (std::size_t i = 0; i < sim.particles.owned(); ++i)
      if (sim.particles.x[i].z > z) above += sim.particles.mass[i];
    r.weight_above += above * 9.81 / (kSide * kSide) / steps;
  }
  return r;
}

}  // namespace

TEST(CoarseGraining, CaseKeysAreCheckedAndScaleTheInteractions) {
  const CaseFile f = CaseFile::parse(bed_case(2e-3, 10, 2.0, 1));
  io::DemCase c = io::build_dem_case(f.root());
  // Γ of the primary particles (0.01 J/m2) × k in the pair the contact laws read
  EXPECT_DOUBLE_EQ(c.sim->materials.pair(0, 0).surface_energy, 0.02);
  EXPECT_DOUBLE_EQ(c.sim->materials.pair(0, 0).restitution, 0.3);
  for (const auto& [extra, key] :
       std::vector<std::pair<std::string, std::string>>{{"scale = 0.5", "scale"}}) {
    std::string text = bed_case(2e-3, 10, 2.0, 1);
    text.replace(text.find("scale = 2"), std::string("scale = 2").size(), extra);
    const CaseFile g = CaseFile::parse(text);
    EXPECT_THROW(io::build_dem_case(g.root()), InputError) << extra;
  }
  // a coarse particle's breakage is not its primaries': refused
  const CaseFile b = CaseFile::parse(bed_case(2e-3, 10, 2.0, 1) +
                                     "[materials.powder.breakage]\ncriterion = \"peak_force\"\n");
  try {
    io::build_dem_case(b.root());
    ADD_FAILURE() << "coarse graining with breakage was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("materials.powder.breakage"), std::string::npos)
        << e.what();
  }
  // the linear law's stiffness does not scale: refused
  std::string linear = bed_case(2e-3, 10, 2.0, 1);
  const std::string law = "model = \"hertz_mindlin\"\ncohesion = \"jkr\"";
  linear.replace(linear.find(law), law.size(),
                 "model = \"linear_spring_dashpot\"\nnormal_stiffness = 1e3");
  const CaseFile h = CaseFile::parse(linear);
  try {
    io::build_dem_case(h.root());
    ADD_FAILURE() << "coarse graining with the linear law was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "coarse_graining.scale") << e.what();
  }
}

TEST(CoarseGraining, CoarseBedHasTheSolidFractionAndStressOfTheFineBed) {
  // The same solid volume as 2400 primary spheres of 1 mm and as 300 coarse spheres of 2 mm
  // (k = 2), with the mixer study's particle adhesion Γ = 0.27 J/m² (strong: pull-off force 37
  // times a 1 mm sphere's weight, so the bed settles looser than a cohesionless one, φ ≈ 0.55
  // against 0.59 at Γ = 0.01). The coarse bed is the mean of four seeds (8 times fewer
  // particles: a seed-to-seed SD of 0.012 in φ, against 0.004 for the fine bed).
  constexpr double kGamma = 0.27;
  const BedResult fine = settle(1e-3, 2400, 1.0, 11, kGamma);
  BedResult coarse;
  constexpr int kSeeds = 4;
  for (int s = 0; s < kSeeds; ++s) {
    const BedResult c = settle(2e-3, 300, 2.0, 11 + static_cast<std::uint64_t>(s), kGamma);
    // each bed carries its own weight: the Love–Weber stress of the bulk layers against the
    // weight above per area, 3 % (issue 13 test 2); measured 0.98–1.01 for these seeds, up to
    // 1.056 for others (seed 17): a coarse particle straddles 2 of the 12 layers, so which
    // centres fall in the band moves the sum by a few per cent
    EXPECT_NEAR(c.stress_zz / c.weight_above, -1.0, 0.03) << "seed " << 11 + s;
    coarse.solid_fraction += c.solid_fraction / kSeeds;
    coarse.stress_zz += c.stress_zz / kSeeds;
    coarse.weight_above += c.weight_above / kSeeds;
  }
  // the measured values, for the record (docs/models.md quotes them)
  fmt::print("fine bed: phi {:.4f}, stress/weight {:.3f}; coarse beds: phi {:.4f}, {:.3f}\n",
             fine.solid_fraction, fine.stress_zz / fine.weight_above, coarse.solid_fraction,
             coarse.stress_zz / coarse.weight_above);
  EXPECT_NEAR(fine.stress_zz / fine.weight_above, -1.0, 0.03);  // measured −1.005
  // bulk solid fraction, within statistical error: measured over seeds 11–19, one coarse bed
  // has an SD of 0.012 (so the mean of four 0.006) and one fine bed 0.004 (seeds 11–13); the
  // SD of the difference is 0.0073 and 3 SD = 0.022. Measured here: fine 0.5512, coarse mean
  // 0.5594. What the scaling does not keep, the Bond number of one particle (pull-off force /
  // weight, k times smaller for coarse particles), shows as a mean offset of +0.012 (coarse
  // seeds 11–19 0.559, fine seeds 11–13 0.547); without the scaling of Γ (the primaries' Γ for
  // the coarse particles) the offset is +0.028 (seeds 11–19), so at this size one run does not
  // reliably tell the two apart (docs/models.md, "Coarse graining").
  EXPECT_NEAR(coarse.solid_fraction, fine.solid_fraction, 0.022);
  // and the same vertical stress per weight above (each within 3 % of it: 6 % together)
  EXPECT_NEAR(coarse.stress_zz / coarse.weight_above, fine.stress_zz / fine.weight_above, 0.06);
}

TEST(CoarseGraining, SnapshotsGiveThePrimaryDiameter) {
  ParticleStore p;
  ParticleInit a;
  a.radius = 1.25e-3;
  a.density = 1670;
  p.add(a);
  const auto has = [](const io::VtkPolyData& pd, const std::string& name) {
    for (const auto& arr : pd.point_data)
      if (arr.name == name) return true;
    return false;
  };
  EXPECT_FALSE(has(io::particle_polydata(p, 0.0, std::vector<std::string>{}), "primary_diameter"));
  const io::VtkPolyData pd = io::particle_polydata(p, 0.0, std::vector<std::string>{}, 2.5);
  for (const auto& arr : pd.point_data) {
    if (arr.name != "primary_diameter") continue;
    ASSERT_EQ(arr.bytes.size(), sizeof(double));
    double d = 0;
    std::memcpy(&d, arr.bytes.data(), sizeof d);
    EXPECT_DOUBLE_EQ(d, 2.5e-3 / 2.5);  // D / k
    return;
  }
  ADD_FAILURE() << "no primary_diameter array under coarse graining";
}

TEST(CoarseGraining, MixerExampleIsCoarseGrainedAndDocumented) {
  // examples/mixer_pbm/mixer_sector_6p25.toml builds (in a scratch copy: it writes its STL files),
  // uses only documented keys, and its pairs carry the study's Γ × k (k = 2.5)
  const comminute::testing::TestDir dir;
  std::filesystem::copy_file(
      std::string(COMMINUTE_SOURCE_DIR) + "/examples/mixer_pbm/mixer_sector_6p25.toml",
      dir / "mixer_sector_6p25.toml");
  const CaseFile f = CaseFile::load(dir / "mixer_sector_6p25.toml");
  io::DemCase c = io::build_dem_case(f.root());
  io::read_output_options(*f.root().optional_table("output"));
  f.reject_unknown();
  comminute::testing::expect_used_keys_documented(
      f, comminute::testing::read_source_file("docs/case-file.md"));
  const auto& m = c.sim->materials;
  const auto particle = static_cast<std::uint16_t>(m.find("particle"));
  const auto steel = static_cast<std::uint16_t>(m.find("steel"));
  EXPECT_DOUBLE_EQ(m.pair(particle, particle).surface_energy, 2.5 * 0.27);
  EXPECT_DOUBLE_EQ(m.pair(particle, steel).surface_energy, 2.5 * 0.78);
  EXPECT_DOUBLE_EQ(m.pair(particle, particle).restitution, 0.21);
}
