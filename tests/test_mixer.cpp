// Mixer generator and walls with periodic images (issue 14, items 4 and 7; test 3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "comminute/core/error.hpp"
#include "comminute/geometry/ball_mill.hpp"
#include "comminute/geometry/mixer.hpp"
#include "mixer_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

constexpr double kPi = std::numbers::pi;

MixerGeometry small_mixer() {
  MixerGeometry g;
  g.vessel_diameter = 0.2;
  g.vessel_height = 0.2;
  g.blades = 3;
  g.blades_built = 3;
  g.blade_length = 0.07;
  g.blade_height = 0.02;
  g.blade_thickness = 0.004;
  g.pitch = 45 * kPi / 180;
  g.bottom_clearance = 0.01;
  g.shaft_diameter = 0.03;
  g.shaft_top = 0.2;
  g.segments = 24;
  return g;
}

// The nearest contact of each wall at x (overlap, normal, point), or none.
bool same_contacts(const Wall& a, const Wall& b, const Vec3& x, double r, double tol) {
  std::vector<WallContact> ca, cb;
  a.contacts(x, r, 0.0, ca);
  b.contacts(x, r, 0.0, cb);
  if (ca.size() != cb.size()) return false;
  auto by = [](const WallContact& p, const WallContact& q) { return p.overlap < q.overlap; };
  std::sort(ca.begin(), ca.end(), by);
  std::sort(cb.begin(), cb.end(), by);
  for (std::size_t k = 0; k < ca.size(); ++k)
    if (std::abs(ca[k].overlap - cb[k].overlap) > tol || norm(ca[k].normal - cb[k].normal) > tol ||
        norm(ca[k].point - cb[k].point) > tol)
      return false;
  return true;
}

}  // namespace

// The shaft mesh is closed, and its enclosed volume is the blades' boxes plus the shaft prism
// (components are summed by the divergence theorem even where they overlap): by hand, to
// round-off (1e-12 relative: sums of ~10^2 triple products). The lowest blade point sits at the
// bottom clearance and the tip at the vessel radius less the wall clearance.
TEST(MixerGeometry, ShaftMeshVolumeAndClearancesByHand) {
  const MixerGeometry g = small_mixer();
  const IndexedMesh m = mixer_shaft_mesh(g);
  const double rs = g.shaft_diameter / 2, r0 = rs / 2, r1 = g.tip_radius();
  const double blade = (r1 - r0) * g.blade_height * g.blade_thickness;
  const double prism = 0.5 * g.segments * rs * rs * std::sin(2 * kPi / g.segments) *
                       (g.shaft_top - g.bottom_clearance);
  EXPECT_NEAR(enclosed_volume(m), 3 * blade + prism, 1e-12 * (3 * blade + prism));
  double zmin = 1e9, rmax = 0;
  for (std::size_t v = 0; v < 24; ++v) {  // the first blade's 8 vertices, the others' likewise
    zmin = std::min(zmin, m.vertices[v].z);
    rmax = std::max(rmax, std::hypot(m.vertices[v].x, m.vertices[v].y));
  }
  EXPECT_NEAR(zmin, g.bottom_clearance, 1e-15);
  // the tip corners lie at r1 radially and ± half the horizontal chord and thickness across
  const double across =
      0.5 * (g.blade_height * std::cos(g.pitch) + g.blade_thickness * std::sin(g.pitch));
  EXPECT_LE(rmax, std::hypot(r1, across) + 1e-15);
  EXPECT_GE(rmax, r1);
  // the vessel: a closed shell and floor but for the open top; volume of a prism of the height
  const IndexedMesh v = mixer_vessel_mesh(0.2, 0.3, 72);
  EXPECT_EQ(v.triangles.size(), 3u * 72u);
}

// Tip speed and rpm give the shaft's angular velocity: omega = v_tip / r_tip = 2 pi N / 60
// (exact arithmetic but for one division: 1e-12 relative).
TEST(MixerGeometry, TipSpeedAndRpmSetTheShaftSpeed) {
  const std::string keys =
      "vessel_diameter = 0.2\nvessel_height = 0.2\nblades = 3\nshaft_diameter = 0.03\n"
      "blade_length = 0.07\nblade_height = 0.02\nblade_thickness = 0.004\npitch = 45\n"
      "bottom_clearance = 0.01\n";
  const CaseFile a = CaseFile::parse(keys + "tip_speed = 6.25\n");
  auto w = WallRegistry::create("mixer", a.root());
  w->advance(1e-6);
  EXPECT_NEAR(w->kinematics.angular_velocity.z, 6.25 / 0.085, 1e-12 * 6.25 / 0.085);
  const CaseFile b = CaseFile::parse(keys + "rpm = 120\n");
  auto v = WallRegistry::create("mixer", b.root());
  v->advance(1e-6);
  EXPECT_NEAR(v->kinematics.angular_velocity.z, 4 * kPi, 1e-12 * 4 * kPi);
  // a blade reaching the vessel wall is refused, naming the key
  const CaseFile c = CaseFile::parse(
      "vessel_diameter = 0.2\nvessel_height = 0.2\nblades = 3\nshaft_diameter = 0.03\n"
      "blade_length = 0.09\nblade_height = 0.02\nblade_thickness = 0.004\n"
      "bottom_clearance = 0.01\n");
  EXPECT_THROW(WallRegistry::create("mixer", c.root()), InputError);
}

// One blade with its sector images is the three-bladed wall: at 2000 random spheres in the
// vessel (many touching a blade, some astride the sector faces) both walls report the same
// contacts (overlap, normal, point) to 1e-12 m (the images are turned by cos/sin of 2π/3, the
// generated blades likewise: round-off only), and never one twice.
TEST(PeriodicImagesWall, OneBladeWithSectorImagesIsTheThreeBladedWall) {
  const MixerRig rig;
  const CaseFile t3 = CaseFile::parse(mixer_table(rig, 3)),
                 t1 = CaseFile::parse(mixer_table(rig, 1));
  auto whole = WallRegistry::create("mixer", t3.root());
  PeriodicImagesWall imaged(WallRegistry::create("mixer", t1.root()),
                            PeriodicMap::sector(2, {0, 0, 0}, 3));
  Rng rng(7);
  int touching = 0;
  for (int k = 0; k < 2000; ++k) {
    const double rho = rng.uniform(0.0, rig.vessel_radius), th = rng.uniform(-kPi, kPi);
    const Vec3 x{rho * std::cos(th), rho * std::sin(th), rng.uniform(0.0, 0.02)};
    std::vector<WallContact> found;
    if (whole->contacts(x, 0.002, 0.0, found) > 0 && found[0].overlap > 0) ++touching;
    ASSERT_TRUE(same_contacts(*whole, imaged, x, 0.002, 1e-12)) << "at " << x.x << " " << x.y;
  }
  EXPECT_GT(touching, 100);
}

// Along a periodic axis: a post (cylinder, axis z) standing on the face x = L, given once with
// its images, is met by a sphere just inside x = 0 exactly as a post at x = 0 (its image), and
// by a sphere just inside x = L as the post itself; one contact each (1e-15 m: a shift by L).
TEST(PeriodicImagesWall, PostOnAPeriodicFaceIsMetFromBothSides) {
  const double L = 0.05;
  const PeriodicMap map = PeriodicMap::axes({true, false, false}, {0, 0, 0}, {L, 1, 1});
  PeriodicImagesWall post(
      std::make_unique<CylinderWall>(Vec3{L, 0, 0}, Vec3{0, 0, 1}, 0.005, 1.0, false, false), map);
  const CylinderWall at_zero(Vec3{0, 0, 0}, Vec3{0, 0, 1}, 0.005, 1.0, false, false);
  const CylinderWall at_L(Vec3{L, 0, 0}, Vec3{0, 0, 1}, 0.005, 1.0, false, false);
  const Vec3 near0{0.006, 0.001, 0.1}, nearL{L - 0.006, -0.001, 0.1};
  EXPECT_TRUE(same_contacts(post, at_zero, near0, 0.002, 1e-15));
  EXPECT_TRUE(same_contacts(post, at_L, nearL, 0.002, 1e-15));
  std::vector<WallContact> found;
  EXPECT_EQ(post.contacts(near0, 0.002, 0.0, found), 1);
}

namespace {

DemSetup mixer_material() {
  DemSetup s;
  s.youngs = 5e6;  // soft spheres: a short test; the contact law is the same at any stiffness
  s.poisson = 0.25;
  s.density = 1670;
  s.friction = 0.5;
  s.restitution = 0.5;
  s.gravity = {0, 0, -9.81};
  return s;
}

// Copy k (of 3) of the sector's particles, turned by 2πk/3 about z, into `sim`, swirling about
// the axis at spin (rad/s).
void add_turned(Simulation& sim, const std::vector<Vec3>& sites, int k, double r, double spin) {
  const double a = 2 * kPi * k / 3;
  for (const Vec3& x : sites) {
    const Vec3 y{std::cos(a) * x.x - std::sin(a) * x.y, std::sin(a) * x.x + std::cos(a) * x.y, x.z};
    add_sphere(sim, y, r, cross(Vec3{0, 0, spin}, y));
  }
}

double blades_torque_z(const Simulation& sim) {
  return sim.walls.back()->torque.z;
}

}  // namespace

// A vertical vessel with a rotating three-bladed shaft as a one-third sector (one blade and its
// images, particles wrapped across the faces) against the full vessel filled 3-fold
// symmetrically: the full run stays symmetric, so each sector particle must follow its copy in
// the full vessel and the sector's blade torque × 3 must be the full blades' torque, over 1500
// steps in which 22 particles wrap, three of them while riding on a blade. The two runs differ by
// round-off only (they turn vectors in different places); the contacts amplify it about tenfold
// per 250 steps in this bed (measured: 7e-10 of the largest torque and 4e-12 of the radius after
// 1500 steps), hence the tolerances 1e-7 of the largest torque and 1e-7 of the particle radius. A
// blade contact whose spring is lost at a wrap (not re-keyed to the next image), or a spring not
// turned with its particle, gives differences of 1e-4 (tested by breaking either).
TEST(MixerSector, OneBladeSectorFollowsTheThreefoldSymmetricFullVessel) {
  const MixerRig rig;
  const double r = rig.particle_radius;
  const DemSetup s = mixer_material();
  auto sec = mixer_sim(rig, true, Blades::one_imaged, s);
  auto full = mixer_sim(rig, false, Blades::whole, s);
  Rng rng(3);
  const auto sites = mixer_sites(rig, *full->walls.back(), 1.1 * r, 0, 2 * kPi / 3, 150, rng);
  // riders: spheres resting on blade 0's upper face just behind the sector face θ = 0 (in the
  // sector: just below θ = 2π/3 after the first wrap), carried across the face by the blade
  // while touching it, so their blade contact is re-keyed to the next image and keeps its
  // spring; they move with the blade
  std::vector<Vec3> riders;
  for (double rho : {0.012, 0.018, 0.024})
    riders.push_back(rig.on_upper_face(rho) + (r - 1e-6) * rig.upper_face_normal());
  // ids: the sector's particles are copy 0 of the full vessel's (same ids)
  for (int k = 0; k < 3; ++k) {
    if (k == 0) add_turned(*sec, sites, 0, r, 20.0);
    if (k == 0) add_turned(*sec, riders, 0, r, rig.omega);
    add_turned(*full, sites, k, r, 20.0);
    add_turned(*full, riders, k, r, rig.omega);
  }
  sec->dt = full->dt = 2e-5;
  sec->setup();
  full->setup();
  const PeriodicMap& map = sec->periodic();
  double tmax = 0, worst_torque = 0, worst_x = 0;
  int wraps = 0;
  for (int step = 0; step < 1500; ++step) {
    sec->step();
    full->step();
    const double ts = 3 * blades_torque_z(*sec), tf = blades_torque_z(*full);
    tmax = std::max(tmax, std::abs(tf));
    worst_torque = std::max(worst_torque, std::abs(ts - tf));
  }
  for (std::size_t i = 0; i < sec->particles.size(); ++i) {
    const std::uint64_t id = sec->particles.id[i];
    const Vec3 xf = full->particles.x[slot_of(*full, id)];
    const Vec3 in = map.point(xf, map.wrap_shift(xf));
    if (norm(in - xf) > 0) ++wraps;
    worst_x = std::max(worst_x, norm(in - sec->particles.x[i]));
  }
  std::printf("torque max %g worst %g, x worst %g, wrapped %d of %zu\n", tmax, worst_torque,
              worst_x, wraps, sec->particles.size());
  EXPECT_GT(tmax, 0);
  EXPECT_GE(wraps, 10);
  EXPECT_LE(worst_torque, 1e-7 * tmax);
  EXPECT_LE(worst_x, 1e-7 * r);
}

namespace {

// Time series of the bed statistics of a mixer run, one entry per sample.
struct BedSamples {
  std::vector<std::array<double, 3>> fraction;  // solid fraction in 3 height bins
  std::vector<std::array<double, 3>> momentum;  // tangential momentum in 3 radial bins of equal
                                                // area, kg m/s
  std::vector<std::array<double, 3>> mass;      // mass in those bins, kg
  std::vector<double> torque;                   // blades + shaft torque about z, whole vessel, N m
};

// Samples every `every` steps over `samples` samples; `copies` = 3 for the sector (its
// particles stand for a third of the vessel), 1 for the full vessel.
BedSamples sample_bed(Simulation& sim, const MixerRig& rig, int copies, int samples, int every) {
  BedSamples out;
  const double r_in = rig.shaft_radius, r_out = rig.vessel_radius, dz = 0.006;
  const double ring = kPi * (r_out * r_out - r_in * r_in) / copies;  // m2 of the run's annulus
  // radial bins of equal area (edges 6, 18.0, 24.7, 30 mm): the bed is flung outwards, and
  // bins of equal width would leave the inner one nearly empty
  const double a_in = r_in * r_in, a_out = r_out * r_out;
  for (int k = 0; k < samples; ++k) {
    sim.run(static_cast<std::uint64_t>(every));
    std::array<double, 3> vol{}, mom{}, mass{};
    const auto& p = sim.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double rho = std::hypot(p.x[i].x, p.x[i].y);
      const auto bz = static_cast<std::size_t>(p.x[i].z / dz);
      if (bz < 3) vol[bz] += 4.0 / 3 * kPi * std::pow(p.radius[i], 3);
      const auto br =
          static_cast<std::size_t>(std::clamp(3 * (rho * rho - a_in) / (a_out - a_in), 0.0, 2.999));
      const double ut = (p.x[i].x * p.v[i].y - p.x[i].y * p.v[i].x) / rho;
      mom[br] += p.mass[i] * ut;
      mass[br] += p.mass[i];
    }
    std::array<double, 3> f{};
    for (std::size_t b = 0; b < 3; ++b) f[b] = vol[b] / (ring * dz);
    out.fraction.push_back(f);
    out.momentum.push_back(mom);
    out.mass.push_back(mass);
    const std::size_t nw = sim.walls.size();
    out.torque.push_back(copies * (sim.walls[nw - 1]->torque.z + sim.walls[nw - 2]->torque.z));
  }
  return out;
}

// Mean and standard error of the ratio sum(x) / sum(w) of two series (w = 1: the mean of x) from
// `blocks` block ratios (the blocks are long against the correlation time of the bed, so they
// are nearly independent); a ratio of sums weighs each sample by its w (its mass in a bin).
std::pair<double, double> block_mean(const std::vector<double>& x, const std::vector<double>& w,
                                     int blocks) {
  const std::size_t per = x.size() / static_cast<std::size_t>(blocks);
  std::vector<double> m(static_cast<std::size_t>(blocks), 0.0);
  for (int b = 0; b < blocks; ++b) {
    double sx = 0, sw = 0;
    for (std::size_t k = 0; k < per; ++k) {
      sx += x[b * per + k];
      sw += w.empty() ? 1.0 : w[b * per + k];
    }
    m[b] = sx / sw;
  }
  double mean = 0, var = 0;
  for (double v : m) mean += v / blocks;
  for (double v : m) var += (v - mean) * (v - mean) / (blocks - 1);
  return {mean, std::sqrt(var / blocks)};
}

}  // namespace

// Issue 14, test 3: a vertical vessel with a rotating three-bladed shaft run as a one-third
// sector (one blade and its images, 200 particles) gives the same bed statistics as the full
// vessel (three blades, 600 particles, filled independently): the solid fraction in three height
// bins (6 mm each), the mean tangential velocity (mass-weighted) in three radial bins of equal
// area, and the shaft torque (blades + shaft, × 3 for the sector: the wall-force measure),
// averaged over 0.6 s of stirring (about 4 turns) after 0.2 s of start-up.
// Statistical error: 15 block means (0.04 s each, a quarter turn of the blades) per run give each
// mean's standard error s; the two runs are independent, so their difference has the error
// sqrt(s_sector² + s_full²), and the assertion allows 4 of them (a false alarm once in ~10^4 per
// quantity for Gaussian block means). Measured: every difference within 2 of them (the errors are
// 1–2 % of the solid fractions, 1–4 % of the velocities, 5 % of the torque). The run is
// deterministic (fixed seeds), so it passes or fails the same way each time on one thread count.
TEST(MixerSector, BedStatisticsOfTheSectorMatchTheFullVessel) {
  MixerRig rig;
  rig.omega = 40;  // rad/s: tip speed 1.08 m/s
  const double r = rig.particle_radius;
  const DemSetup s = mixer_material();
  auto sec = mixer_sim(rig, true, Blades::one_imaged, s);
  auto full = mixer_sim(rig, false, Blades::whole, s);
  Rng ra(11), rb(12);
  const Wall& whole_blades = *full->walls.back();
  for (const Vec3& x : mixer_sites(rig, whole_blades, 1.1 * r, 0, 2 * kPi / 3, 200, ra))
    add_sphere(*sec, x, r);
  for (const Vec3& x : mixer_sites(rig, whole_blades, 1.1 * r, 0, 2 * kPi, 600, rb))
    add_sphere(*full, x, r);
  ASSERT_EQ(sec->particles.size(), 200u);
  ASSERT_EQ(full->particles.size(), 600u);
  sec->dt = full->dt = 2e-5;
  sec->run(10000);  // 0.2 s: the bed falls and the stirring sets in
  full->run(10000);
  const BedSamples a = sample_bed(*sec, rig, 3, 300, 100), b = sample_bed(*full, rig, 1, 300, 100);
  auto check = [](const std::vector<double>& xs, const std::vector<double>& ws,
                  const std::vector<double>& xf, const std::vector<double>& wf, const char* what) {
    const auto [ms, es] = block_mean(xs, ws, 15);
    const auto [mf, ef] = block_mean(xf, wf, 15);
    const double sigma = std::hypot(es, ef);
    std::printf("%s: sector %.5g ± %.2g, full %.5g ± %.2g (diff %.2g sigma)\n", what, ms, es, mf,
                ef, std::abs(ms - mf) / sigma);
    EXPECT_LE(std::abs(ms - mf), 4 * sigma) << what;
  };
  for (std::size_t k = 0; k < 3; ++k) {
    auto column = [k](const std::vector<std::array<double, 3>>& rows) {
      std::vector<double> c;
      for (const auto& v : rows) c.push_back(v[k]);
      return c;
    };
    check(column(a.fraction), {}, column(b.fraction), {},
          ("solid fraction, height bin " + std::to_string(k)).c_str());
    check(column(a.momentum), column(a.mass), column(b.momentum), column(b.mass),
          ("u_theta, radial bin " + std::to_string(k)).c_str());
  }
  check(a.torque, {}, b.torque, {}, "shaft torque");
}
