// Per-contact forces and branch vectors for modules (engine/contact_stress.hpp): the Love–Weber
// moment of two pressed spheres and of a sphere on a wall against the analytic tensor, the
// contacts that begin, and the coordination number of a known lattice (bed statistics).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "comminute/analysis/bed_statistics.hpp"
#include "comminute/engine/contact_pipeline.hpp"
#include "comminute/geometry/periodic_map.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using comminute::testing::add_sphere;
using comminute::testing::DemSetup;
using comminute::testing::make_simulation;

namespace {

// Asks for contact stress and arms it at set-up, so that the set-up's force computation fills it.
class ArmAtSetup final : public Module {
 public:
  std::string name() const override { return "arm"; }
  void declare_contact_state(ContactPipeline& p) override { p.require_contact_stress(); }
  void setup(Simulation& sim) override { sim.contacts().stress()->arm(); }
};

double sphere_volume(double r) {
  return 4.0 / 3.0 * std::numbers::pi * r * r * r;
}

// Adds bed statistics measuring every step, sets up and takes one step.
const analysis::BedStatistics& measure_once(Simulation& sim, analysis::BedStatisticsOptions o) {
  o.every = 1;
  auto bed = std::make_unique<analysis::BedStatistics>(o);
  const auto* b = bed.get();
  bed->register_fields(sim.particles);
  sim.modules.push_back(std::move(bed));
  sim.dt = 1e-8;
  sim.setup();
  sim.step();
  return *b;
}

}  // namespace

TEST(ContactStress, TwoPressedSpheresGiveTheAnalyticTensor) {
  auto sim = make_simulation(DemSetup{});
  const double r = 1e-3, delta = 2e-5;
  const Vec3 n = Vec3{1, 2, 2} / 3.0;  // unit, not along an axis: off-diagonal terms are tested
  add_sphere(*sim, n * (r - 0.5 * delta), r);
  add_sphere(*sim, -n * (r - 0.5 * delta), r);
  sim->modules.push_back(std::make_unique<ArmAtSetup>());
  sim->dt = 1e-7;
  sim->setup();
  const ContactStress& cs = *sim->contacts().stress();
  // Hertz: F = (4/3) E* sqrt(R*) δ^1.5 (Hertz 1882), E* = E / (2 (1 − ν²)), R* = r/2
  const double estar = 1e7 / (2 * (1 - 0.3 * 0.3));
  const double f = 4.0 / 3.0 * estar * std::sqrt(0.5 * r) * std::pow(delta, 1.5);
  // σ_i = (1/V) f_i ⊗ l_i with f_0 = F n, l_0 = −(r − δ/2) n: σ = −F (r − δ/2) n ⊗ n / V
  const double lever = r - 0.5 * delta, v = sphere_volume(r);
  const double expect[6] = {n.x * n.x, n.y * n.y, n.z * n.z, n.x * n.y, n.x * n.z, n.y * n.z};
  ASSERT_EQ(cs.moment.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    for (std::size_t k = 0; k < 6; ++k)
      // the positions carry rounding of 1e-16 m on an overlap of 2e-5 m: the force (δ^1.5) is
      // known to ~1e-11 relative; 1e-9 leaves room and still catches any wrong lever or factor
      EXPECT_NEAR(cs.moment[i][k] / v, -f * lever * expect[k] / v, 1e-9 * f * lever / v)
          << "particle " << i << " component " << k;
    EXPECT_EQ(cs.load_bearing[i], 1u);  // threshold 0 N: the one contact bears load
  }
  // the set-up's force computation saw the contact begin
  ASSERT_EQ(cs.starts.size(), 1u);
}

TEST(ContactStress, SphereOnAWallUsesTheContactPointAsLever) {
  auto sim = make_simulation(DemSetup{});
  const double r = 1e-3, delta = 1e-5;
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  add_sphere(*sim, {0, 0, r - delta}, r);
  sim->modules.push_back(std::make_unique<ArmAtSetup>());
  sim->dt = 1e-7;
  sim->setup();
  const ContactStress& cs = *sim->contacts().stress();
  const double fz = sim->particles.f[0].z;  // the wall's push (no gravity, no other contact)
  ASSERT_GT(fz, 0);
  // σ_zz V = f_z l_z with l = contact point − centre = −(r − δ) e_z; other components zero
  EXPECT_NEAR(cs.moment[0][2], -fz * (r - delta), 1e-12 * fz * r);  // rounding only
  for (std::size_t k : {0u, 1u, 3u, 4u, 5u}) EXPECT_EQ(cs.moment[0][k], 0.0);
  EXPECT_EQ(cs.load_bearing[0], 0u);  // wall contacts are not particle contacts
}

TEST(BedStatistics, CoordinationOfASimpleCubicLattice) {
  // n³ spheres on a simple cubic lattice, each pair of neighbours overlapping by the same δ:
  // C = 3 n² (n − 1) contacts, Z = 2C/N = 6 (n − 1)/n exactly (counting, no tolerance)
  auto sim = make_simulation(DemSetup{});
  const int n = 4;
  const double r = 1e-3, a = 2 * r - 1e-6;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) add_sphere(*sim, {a * i, a * j, a * k}, r);
  analysis::BedStatisticsOptions o;
  o.region.lo = {-r, -r, -r};
  o.region.hi = {a * n, a * n, a * n};
  const auto* b = &measure_once(*sim, o);
  ASSERT_EQ(b->rows().size(), 1u);
  EXPECT_DOUBLE_EQ(b->rows()[0].contacts, 3.0 * n * n * (n - 1));
  EXPECT_DOUBLE_EQ(b->rows()[0].coordination, 6.0 * (n - 1) / n);
  // no rattlers (every sphere has 3 to 6 contacts): the mechanical number is the same
  EXPECT_DOUBLE_EQ(b->rows()[0].mechanical_coordination, 6.0 * (n - 1) / n);
  EXPECT_EQ(b->chains().size(), static_cast<std::size_t>(3 * n * n * (n - 1)));
  // void ratio: region cross-section (a n + r)², bed height from its bottom (−r) to the top
  // sphere's top, (n − 1) a + 2r; solids n³ (4/3)π r³ (the step moved nothing measurable: 1e-8 s)
  const double side = a * n + r, h = (n - 1) * a + 2 * r;
  const double e = side * side * h / (n * n * n * sphere_volume(r)) - 1;
  EXPECT_NEAR(b->rows()[0].bed_height, h, 1e-12);
  EXPECT_NEAR(b->rows()[0].void_ratio, e, 1e-9 * e);
  // axial stress: each of the n²(n − 1) vertical contacts adds F (2r − δ) to −Σ M_zz (Hertz F
  // with δ = 2r − a = 1e-6 m), over A h; 1e-4: the step's half kick gives the outer spheres
  // ~1e-7 m/s and the contact damping then adds ~1e-5 of F (the lever r for r − δ/2: 2.5e-4)
  const double estar = 1e7 / (2 * (1 - 0.3 * 0.3)), delta = 2 * r - a;
  const double f = 4.0 / 3.0 * estar * std::sqrt(0.5 * r) * std::pow(delta, 1.5);
  const double axial = n * n * (n - 1) * f * a / (side * side * h);
  EXPECT_NEAR(b->rows()[0].axial_stress, axial, 1e-4 * axial);
}

TEST(BedStatistics, ThorntonMechanicalCoordinationLeavesOutRattlers) {
  // counts {0, 1, 3, 3, 3}: Z = 10/5; Zm = (10 − 1)/(5 − 1 − 1) = 3 (Thornton 2000, eq. 4)
  const auto [z, zm] = analysis::BedStatistics::coordination({0, 1, 3, 3, 3});
  EXPECT_DOUBLE_EQ(z, 2.0);
  EXPECT_DOUBLE_EQ(zm, 3.0);
}

TEST(BedStatistics, ThresholdAboveEveryForceLeavesNoLoadBearingContact) {
  auto sim = make_simulation(DemSetup{});
  const double r = 1e-3;
  add_sphere(*sim, {0, 0, 0}, r);
  add_sphere(*sim, {2 * r - 1e-6, 0, 0}, r);
  analysis::BedStatisticsOptions o;
  o.region.lo = {-2 * r, -2 * r, -2 * r};
  o.region.hi = {4 * r, 2 * r, 2 * r};
  o.threshold = 1e3;  // N, far above the contact's ~1e-4 N
  const auto* b = &measure_once(*sim, o);
  EXPECT_EQ(b->rows()[0].contacts, 0.0);
  EXPECT_TRUE(b->chains().empty());
}

TEST(ContactStress, GhostMomentsFoldOntoOwnersTurnedBackInASector) {
  // a quarter sector about z; A at angle α, B at 90° − α, ρ = 5 cm: B's image (turned by −90°)
  // sits at −α, so A and the image touch with overlap δ along +y: on A, M = −F (r − δ/2) ŷŷ; on
  // B (in its own frame, the image's contact turned back by +90°), M = −F (r − δ/2) x̂x̂
  auto sim = make_simulation(DemSetup{});
  sim->set_periodic(PeriodicMap::sector(2, {0, 0, 0}, 4));
  sim->options.skin = 0.0004;
  const double r = 1e-3, delta = 2e-5, rho = 0.05;
  const double a = std::asin((2 * r - delta) / (2 * rho));
  const double b = 0.5 * std::numbers::pi - a;
  add_sphere(*sim, {rho * std::cos(a), rho * std::sin(a), 0}, r);
  add_sphere(*sim, {rho * std::cos(b), rho * std::sin(b), 0}, r);
  sim->modules.push_back(std::make_unique<ArmAtSetup>());
  sim->dt = 1e-7;
  sim->setup();
  const ContactStress& cs = *sim->contacts().stress();
  const double estar = 1e7 / (2 * (1 - 0.3 * 0.3));
  const double f = 4.0 / 3.0 * estar * std::sqrt(0.5 * r) * std::pow(delta, 1.5);  // Hertz
  const double m = -f * (r - 0.5 * delta);
  // positions on a circle of 5 cm carry rounding of ~1e-17 m; the overlap (2e-5 m) is known to
  // ~1e-12 relative and the turn by cos/sin to 1e-16: 1e-9 of the moment is far above both and
  // far below a missing or unturned fold (100 % of a component)
  const double tol = 1e-9 * std::abs(m);
  const SymTensor expect_a{0, m, 0, 0, 0, 0}, expect_b{m, 0, 0, 0, 0, 0};
  const std::size_t ia = sim->particles.x[0].x > sim->particles.x[1].x ? 0 : 1, ib = 1 - ia;
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_NEAR(cs.moment[ia][k], expect_a[k], tol) << "A component " << k;
    EXPECT_NEAR(cs.moment[ib][k], expect_b[k], tol) << "B component " << k;
  }
  EXPECT_EQ(cs.load_bearing[0], 1u);
  EXPECT_EQ(cs.load_bearing[1], 1u);
}
