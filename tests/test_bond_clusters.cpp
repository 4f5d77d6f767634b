// Bonded grains: packing a shape with sub-spheres (fills it, stays inside, right equivalent
// diameter), bonds only within the gap tolerance and within grains, connected components against
// a brute-force count, the grain-broken threshold in a pulled chain and its restart, the
// breakage-mode rule, refused input.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "case_docs_check.hpp"
#include "comminute/bonds/breakage_mode.hpp"
#include "comminute/bonds/cluster_packing.hpp"
#include "comminute/bonds/fragments.hpp"
#include "comminute/bonds/grain_breakage_module.hpp"
#include "comminute/io/case/bonds_case.hpp"
#include "comminute/io/case/cluster_case.hpp"
#include "comminute/io/case/output_case.hpp"
#include "dem_fixture.hpp"
#include "source_file.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using namespace comminute::testing;
using bonds::GrainTemplate;

namespace {

// Checks what every packing must satisfy: each sub-sphere inside the shape (its centre at least
// r from the surface) and no overlap beyond the relaxation's stopping tolerance.
void expect_valid_packing(const bonds::ClusterShape& shape, const GrainTemplate& g) {
  for (const Vec3& c : g.centres)
    // 1e-9 r: push_inside stops 1e-9 r inside; the distance is exact to ~1e-12 of the shape
    EXPECT_LE(shape.signed_distance(c), -g.radius * (1 - 1e-8));
  for (std::size_t i = 0; i < g.centres.size(); ++i)
    for (std::size_t j = i + 1; j < g.centres.size(); ++j)
      // 1e-4 r: the relaxation stops when the worst overlap is below this (half moved per pass)
      EXPECT_GE(norm(g.centres[j] - g.centres[i]), 2 * g.radius * (1 - 1e-4));
}

IndexedMesh cube_mesh(double side) {
  IndexedMesh m;
  const double h = 0.5 * side;
  for (int k = 0; k < 8; ++k)
    m.vertices.push_back({(k & 1) ? h : -h, (k & 2) ? h : -h, (k & 4) ? h : -h});
  // outward-facing (counter-clockwise seen from outside)
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

}  // namespace

TEST(BondClusters, EllipsoidDistanceIsExactOnTheAxesAndZeroOnTheSurface) {
  const Vec3 e{3e-3, 1.5e-3, 1.1e-3};
  // from the centre the nearest surface point is the end of the smallest semi-axis; 1e-9 m (1e-6
  // of the size): a point on a symmetry plane is moved off it by 1e-9 of the smallest semi-axis,
  // and the root then lies where F(t) is steep, resolved to ~1e-7 of the size
  EXPECT_NEAR(bonds::ellipsoid_signed_distance(e, {}), -1.1e-3, 1e-9);
  // outside on the long axis: the distance to the tip
  EXPECT_NEAR(bonds::ellipsoid_signed_distance(e, {4e-3, 0, 0}), 1e-3, 1e-12);
  // points of the surface: distance zero (bisection to double precision: 1e-12 of the size)
  Rng rng(5, 0);
  for (int k = 0; k < 100; ++k) {
    const double th = std::acos(rng.uniform(-1, 1)), ph = rng.uniform(0, 2 * std::numbers::pi);
    const Vec3 s{e.x * std::sin(th) * std::cos(ph), e.y * std::sin(th) * std::sin(ph),
                 e.z * std::cos(th)};
    EXPECT_NEAR(bonds::ellipsoid_signed_distance(e, s), 0, 1e-12);
    // moved out along the surface normal by h: the distance is h (the normal line's foot)
    Vec3 n{s.x / (e.x * e.x), s.y / (e.y * e.y), s.z / (e.z * e.z)};
    n = n / norm(n);
    EXPECT_NEAR(bonds::ellipsoid_signed_distance(e, s + 1e-4 * n), 1e-4, 1e-12);
  }
}

TEST(BondClusters, SpherePackingFillsTheShape) {
  const auto shape = bonds::make_sphere_shape(4e-3);
  // the equivalent diameter of a sphere is its diameter (round-off only)
  EXPECT_NEAR(shape->equivalent_diameter(), 4e-3, 1e-15);
  Rng rng(11, 0);
  const GrainTemplate g = bonds::pack_cluster(*shape, 40, 0.6, rng);
  expect_valid_packing(*shape, g);
  // at most the target by construction; at least 0.5: random packings of 40 equal spheres in a
  // sphere jam near 0.55-0.6 (wall effect of a container 4 sphere diameters wide), and the
  // relaxation shrinks the radius by 1 % steps only when jammed
  EXPECT_LE(g.solid_fraction(), 0.6 + 1e-12);
  EXPECT_GE(g.solid_fraction(), 0.5);
  RecordProperty("solid_fraction", std::to_string(g.solid_fraction()));
}

TEST(BondClusters, EllipsoidPackingOfARiceGrain) {
  const double l = 6e-3, w = 3e-3, t = 2.2e-3;
  const auto shape = bonds::make_ellipsoid_shape(l, w, t);
  // d_eq = (L W T)^{1/3} for an ellipsoid (volume π L W T / 6)
  EXPECT_NEAR(shape->equivalent_diameter(), std::cbrt(l * w * t), 1e-15);
  Rng rng(12, 0);
  for (int n : {10, 30}) {
    const GrainTemplate g = bonds::pack_cluster(*shape, n, 0.6, rng);
    expect_valid_packing(*shape, g);
    // few spheres in a thin shape jam lower (the 2.2 mm thickness holds two sub-spheres at most)
    EXPECT_GE(g.solid_fraction(), 0.4) << n;
    EXPECT_LE(g.solid_fraction(), 0.6 + 1e-12) << n;
    RecordProperty("solid_fraction_" + std::to_string(n), std::to_string(g.solid_fraction()));
  }
}

TEST(BondClusters, MeshPackingStaysInsideACube) {
  const auto shape = bonds::make_mesh_shape(cube_mesh(4e-3));
  // divergence theorem over 12 triangles: exact to round-off
  EXPECT_NEAR(shape->volume(), 64e-9, 1e-20);
  EXPECT_NEAR(shape->signed_distance({}), -2e-3, 1e-15);
  EXPECT_NEAR(shape->signed_distance({3e-3, 0, 0}), 1e-3, 1e-15);
  EXPECT_NEAR(shape->signed_distance({3e-3, 3e-3, 0}), std::sqrt(2.0) * 1e-3, 1e-15);
  Rng rng(13, 0);
  const GrainTemplate g = bonds::pack_cluster(*shape, 30, 0.55, rng);
  expect_valid_packing(*shape, g);
  // 0.4: 30 spheres in a cube three sphere diameters wide jam lower than in a sphere (corners and
  // flat faces hold loosely ordered wall layers)
  EXPECT_GE(g.solid_fraction(), 0.4);
  RecordProperty("solid_fraction", std::to_string(g.solid_fraction()));
}

TEST(BondClusters, BondsOnlyWithinTheGapTolerance) {
  const auto shape = bonds::make_ellipsoid_shape(6e-3, 3e-3, 2.2e-3);
  Rng rng(14, 0);
  const GrainTemplate g = bonds::pack_cluster(*shape, 30, 0.6, rng);
  const double gap = 0.05 * g.radius;
  const auto pairs = bonds::pairs_within_gap(g.centres, g.radius, gap);
  std::size_t expected = 0;
  for (std::size_t i = 0; i < g.centres.size(); ++i)
    for (std::size_t j = i + 1; j < g.centres.size(); ++j)
      expected += norm(g.centres[j] - g.centres[i]) - 2 * g.radius <= gap ? 1 : 0;
  EXPECT_EQ(pairs.size(), expected);
  for (const auto& p : pairs)
    EXPECT_LE(norm(g.centres[p[1]] - g.centres[p[0]]) - 2 * g.radius, gap);
  // a dense packing joins its spheres into one piece within a few percent of r
  EXPECT_EQ(bonds::count_components(g.centres.size(), pairs), 1u);
}

TEST(BondClusters, ComponentsMatchABruteForceCountAfterRandomFailures) {
  Rng rng(15, 0);
  const std::size_t n = 300;
  std::vector<std::uint32_t> a, b;
  for (std::size_t k = 0; k < 600; ++k) {
    a.push_back(static_cast<std::uint32_t>(rng.below(n)));
    b.push_back(static_cast<std::uint32_t>(rng.below(n)));
  }
  for (int round = 0; round < 6; ++round) {
    // fail a random third of the bonds
    std::vector<std::uint32_t> a2, b2;
    for (std::size_t k = 0; k < a.size(); ++k)
      if (rng.uniform() > 1.0 / 3) {
        a2.push_back(a[k]);
        b2.push_back(b[k]);
      }
    a = a2;
    b = b2;
    std::uint32_t count = 0;
    const auto label = bonds::component_labels(n, a, b, count);
    // brute force: propagate the smallest node index over the edges until nothing changes
    std::vector<std::size_t> lowest(n);
    for (std::size_t i = 0; i < n; ++i) lowest[i] = i;
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t k = 0; k < a.size(); ++k) {
        const std::size_t m = std::min(lowest[a[k]], lowest[b[k]]);
        if (lowest[a[k]] != m || lowest[b[k]] != m) changed = true;
        lowest[a[k]] = lowest[b[k]] = m;
      }
    }
    std::size_t brute = 0;
    for (std::size_t i = 0; i < n; ++i) brute += lowest[i] == i ? 1 : 0;
    EXPECT_EQ(count, brute);
    // the same partition: same label exactly when the same lowest member
    for (std::size_t i = 0; i < n; i += 7)
      for (std::size_t j = 0; j < n; j += 5)
        EXPECT_EQ(label[i] == label[j], lowest[i] == lowest[j]);
  }
}

namespace {

// Parallel bonds (k̄n = 1e9, k̄s = 4e8 Pa/m, the given strengths) within grains, gap 10 µm.
bonds::BondsModule* add_grain_bonds(Simulation& sim, const std::string& strengths) {
  const CaseFile f = CaseFile::parse("normal_stiffness = 1e9\nshear_stiffness = 4e8\n" + strengths);
  bonds::BondOptions opt;
  opt.gap_tolerance = 1e-5;
  opt.within_grain = true;
  auto b = std::make_unique<bonds::BondsModule>(
      bonds::BondLawRegistry::create("parallel_bond", f.root()), opt);
  bonds::BondsModule* out = b.get();
  sim.modules.push_back(std::move(b));
  return out;
}

// Pulls one particle along +x with a force ramp and damps every particle's motion.
class Pull final : public Module {
 public:
  Pull(std::uint64_t id, double rate, double c) : id_(id), rate_(rate), c_(c) {}
  std::string name() const override { return "pull"; }
  void post_force(Simulation& sim) override {
    auto& p = sim.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.id[i] == id_) p.f[i].x += rate_ * sim.time;
      p.f[i] -= c_ * p.v[i];
    }
  }

 private:
  std::uint64_t id_;
  double rate_, c_;
};

// A grain of four spheres in a row, the first clamped, the last pulled until one bond fails;
// returns the module after 0.05 s more (the pieces apart).
struct PulledChain {
  std::unique_ptr<Simulation> sim;
  bonds::BondsModule* bonds = nullptr;
  bonds::GrainBreakageModule* grains = nullptr;
  explicit PulledChain(double broken_below) {
    sim = make_simulation(DemSetup{});
    const double r = 1e-3;
    const std::size_t gf = sim->particles.add_field("grain", -1);
    const std::size_t lf = sim->particles.add_field("layer", 0);
    std::uint64_t last = 0;
    for (int k = 0; k < 4; ++k) {
      last = add_sphere(*sim, {k * (2 * r + 1e-6), 0, 0}, r);
      sim->particles.field(gf).back() = 0;
      sim->particles.field(lf).back() = 1;
    }
    sim->particles.flags[0] |= pflag::fixed;
    bonds = add_grain_bonds(*sim,
                            "tensile_strength = 1e3\nshear_strength = 1e12\n"
                            "tensile_strength_sd = 2e2\n");
    bonds::GrainBreakageOptions go;
    go.broken_below = broken_below;
    auto g = std::make_unique<bonds::GrainBreakageModule>(*bonds, go);
    grains = g.get();
    sim->modules.push_back(std::move(g));
    // ramp 0.05 N/s: the tensile strength F = σ̄c π r² ≈ 3e-3 N is reached after ~0.06 s
    sim->modules.push_back(std::make_unique<Pull>(last, 0.05, 1e-3));
    sim->dt = 1e-5;
    sim->options.skin = 2e-5;
  }
  PulledChain& pull() {
    for (int k = 0; k < 40000 && bonds->failures().empty(); ++k) sim->step();
    sim->run(5000);
    return *this;
  }
};

}  // namespace

TEST(BondClusters, GrainBrokenWhenLargestFragmentBelowThreshold) {
  PulledChain loose(0.8), strict(0.45);
  loose.pull();
  strict.pull();
  ASSERT_EQ(loose.bonds->failures().size(), 1u);  // one bond failed: two pieces
  ASSERT_EQ(strict.bonds->failures().size(), 1u);
  // both runs are the same run (same seed, the threshold only observes): the same bond failed
  const auto& f = loose.bonds->failures().front();
  const std::uint64_t cut = std::min(f.id_i, f.id_j);  // bond between particle cut and cut + 1
  // brute force: the pieces are particles 1…cut and cut+1…4 (ids from 1), equal masses
  const double c = static_cast<double>(cut);
  const double largest = std::max(c, 4.0 - c) / 4.0;
  const auto fractions = loose.grains->largest_fractions(*loose.sim);
  ASSERT_EQ(fractions.size(), 1u);
  EXPECT_NEAR(fractions[0], largest, 1e-12);  // sums of four equal masses: round-off
  // the largest piece is 3/4 or 1/2 of the grain: below 0.8, above 0.45
  ASSERT_EQ(loose.grains->rows().size(), 1u);
  EXPECT_NEAR(loose.grains->rows()[0].largest_fraction, largest, 1e-12);
  EXPECT_TRUE(loose.grains->broken()[0]);
  EXPECT_TRUE(strict.grains->rows().empty());
  EXPECT_FALSE(strict.grains->broken()[0]);
}

TEST(BondClusters, EveryKeyOfTheRiceExampleIsDocumented) {
  const std::string doc = comminute::testing::read_source_file("docs/case-file.md");
  ASSERT_FALSE(doc.empty());
  CaseFile f = CaseFile::load(std::string(COMMINUTE_SOURCE_DIR) +
                              "/examples/rice_compression/rice_compression.toml");
  io::DemCase dem = io::build_dem_case(f.root());
  const bonds::BondsModule* b = io::add_bonds(f.root(), dem);
  ASSERT_NE(io::add_grain_breakage(f.root(), dem, b), nullptr);
  if (auto o = f.root().optional_table("output")) io::read_output_options(*o);
  f.reject_unknown();
  expect_used_keys_documented(f, doc);
  // 200 grains of 10 sub-spheres, each grain's sub-spheres carrying its mass ρ π L W T / 6
  const ParticleStore& p = dem.sim->particles;
  ASSERT_EQ(p.size(), 2000u);
  const double grain_mass = 1450.0 * std::numbers::pi * 6e-3 * 3e-3 * 2.2e-3 / 6;
  EXPECT_NEAR(p.total_mass(), 200 * grain_mass, 1e-9 * 200 * grain_mass);  // round-off of sums
}

TEST(BondClusters, WithinGrainBondsNeverJoinTwoGrains) {
  // two grains of two spheres each, all four in a touching row: only 0-1 and 2-3 are bonded
  auto sim = make_simulation(DemSetup{});
  const std::size_t gf = sim->particles.add_field("grain", -1);
  for (int k = 0; k < 4; ++k) {
    add_sphere(*sim, {k * 2.000001e-3, 0, 0}, 1e-3);
    sim->particles.field(gf).back() = k / 2;
  }
  bonds::BondsModule* module =
      add_grain_bonds(*sim, "tensile_strength = 1e6\nshear_strength = 1e6\n");
  sim->dt = 1e-6;
  sim->options.skin = 2e-5;
  sim->step();
  ASSERT_EQ(module->bonds().size(), 2u);
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_EQ((module->bonds().id_i[k] - 1) / 2, (module->bonds().id_j[k] - 1) / 2);
}

TEST(BondClusters, GrainBreakageRestartsBitForBit) {
  // saved before the bond fails (at 0.03 s; it fails near 0.06 s), continued to 0.1 s
  PulledChain straight(0.8), resumed(0.8);
  straight.sim->run(3000);
  Archive a;
  straight.sim->save(a);
  straight.sim->run(7000);
  resumed.sim->load(a);
  resumed.sim->run(7000);
  ASSERT_EQ(straight.grains->rows().size(), 1u);
  ASSERT_EQ(resumed.grains->rows().size(), 1u);
  const auto &r = straight.grains->rows()[0], &q = resumed.grains->rows()[0];
  EXPECT_GT(r.time, 0.03);  // the grain broke after the restart point
  EXPECT_EQ(r.time, q.time);
  EXPECT_EQ(r.largest_fraction, q.largest_fraction);
  EXPECT_EQ(r.mode, q.mode);
  EXPECT_EQ(straight.grains->broken(), resumed.grains->broken());
  EXPECT_EQ(straight.sim->particles.x, resumed.sim->particles.x);
}

TEST(BondClusters, BreakageModesFollowTheDocumentedRule) {
  // a rod of 9 centres along x (half-length a = 4 + 0.5 = 4.5 with radius 0.5)
  std::vector<Vec3> c;
  for (int k = -4; k <= 4; ++k) c.push_back({static_cast<double>(k), 0.1 * (k % 2), 0});
  const Vec3 x{1, 0, 0}, y{0, 1, 0};
  using bonds::BreakageMode;
  // bonds along the axis cut at mid-length: a transverse crack in the middle (s = 0.5 / 4.5)
  EXPECT_EQ(bonds::classify_breakage(c, 0.5, {{{0.5, 0, 0}, x}}), BreakageMode::central);
  // the same near a tip (s = 3.5 / 4.5 > 0.5): a chipped end
  EXPECT_EQ(bonds::classify_breakage(c, 0.5, {{{3.5, 0, 0}, x}}), BreakageMode::end_chipping);
  // bonds across the axis (α = 0 < 0.55): split lengthwise, wherever they are
  EXPECT_EQ(bonds::classify_breakage(c, 0.5, {{{-2, 0, 0}, y}, {{2, 0, 0}, y}}),
            BreakageMode::split);
  // α at the threshold side: directions at 60° from the axis give |n·e| = 0.5 < 0.55
  const Vec3 tilted{0.5, std::sqrt(3.0) / 2, 0};
  EXPECT_EQ(bonds::classify_breakage(c, 0.5, {{{0, 0, 0}, tilted}}), BreakageMode::split);
}

TEST(BondClusters, ClustersWithoutWithinGrainBondsAreRefused) {
  const CaseFile f = CaseFile::parse(R"(
[simulation]
end_time = 0.1
[contact]
model = "hertz_mindlin"
[materials.rice]
density = 1450.0
youngs_modulus = 1.0e8
poisson_ratio = 0.3
[[insert]]
type = "clusters"
material = "rice"
shape = "sphere"
diameter = 3e-3
spheres_per_grain = 8
count = 2
region = { shape = "box", lo = [0.0, 0.0, 0.0], hi = [0.02, 0.02, 0.02] }
[bonds]
law = "parallel_bond"
normal_stiffness = 1e9
shear_strength = 1e6
shear_stiffness = 1e9
tensile_strength = 1e6
)");
  try {
    io::build_dem_case(f.root());
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("within_grain"), std::string::npos) << e.what();
  }
}

TEST(BondClusters, StlGrainsFromACaseFile) {
  // a 3 mm cube as an ASCII STL in millimetres (scale = 0.001), 6 grains of 12 sub-spheres
  const comminute::testing::TestDir dir;
  const IndexedMesh cube = cube_mesh(3.0);
  {
    std::ofstream stl(dir / "cube.stl");
    stl << "solid cube\n";
    for (const auto& t : cube.triangles) {
      stl << " facet normal 0 0 0\n  outer loop\n";
      for (std::uint32_t v : t)
        stl << "   vertex " << cube.vertices[v].x << " " << cube.vertices[v].y << " "
            << cube.vertices[v].z << "\n";
      stl << "  endloop\n endfacet\n";
    }
    stl << "endsolid cube\n";
  }
  {
    std::ofstream toml(dir / "case.toml");
    toml << R"([simulation]
end_time = 0.1
skin = 3e-4
[contact]
model = "hertz_mindlin"
[materials.rock]
density = 2500.0
youngs_modulus = 1.0e8
poisson_ratio = 0.3
[[insert]]
type = "clusters"
material = "rock"
shape = "stl"
file = "cube.stl"
scale = 0.001
spheres_per_grain = 12
count = 6
layers = 2
region = { shape = "box", lo = [0.0, 0.0, 0.0], hi = [0.02, 0.02, 0.02] }
[bonds]
law = "parallel_bond"
within_grain = true
gap_tolerance = 3e-4
normal_stiffness = 1e9
shear_stiffness = 1e9
tensile_strength = 1e6
shear_strength = 1e6
)";
  }
  CaseFile f = CaseFile::load(dir / "case.toml");
  io::DemCase dem = io::build_dem_case(f.root());
  const ParticleStore& p = dem.sim->particles;
  ASSERT_EQ(p.size(), 72u);
  // each grain carries the cube's mass ρ (3 mm)³ (round-off of twelve terms)
  const auto& grain = p.field(p.field_index("grain"));
  const auto& layer = p.field(p.field_index("layer"));
  std::vector<double> mass(6, 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    mass[static_cast<std::size_t>(grain[i])] += p.mass[i];
    // layers: grains 0-2 in the lower half (layer 1), 3-5 in the upper one
    EXPECT_EQ(layer[i], grain[i] < 3 ? 1.0 : 2.0);
  }
  for (double m : mass) EXPECT_NEAR(m, 2500.0 * 27e-9, 1e-12 * 2500.0 * 27e-9);
}
