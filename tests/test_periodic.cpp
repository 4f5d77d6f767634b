// Periodic boundaries (issue 14, item 4): ghosts across periodic faces and sector boundaries.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "breakage_engine_fixture.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/geometry/cylinder_wall.hpp"
#include "comminute/geometry/periodic_map.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

double rayleigh_step(double r, double youngs, double poisson, double density) {
  const double G = youngs / (2 * (1 + poisson));
  return 0.2 * std::numbers::pi * r * std::sqrt(density / G) / (0.1631 * poisson + 0.8766);
}

PeriodicMap box_map(bool x, bool y, bool z, double L) {
  return PeriodicMap::axes({x, y, z}, {0, 0, 0}, {L, L, L});
}

// A gas of 3 mm spheres (E = 50 MPa) on a jittered lattice of spacing a filling [0, cells a]^3,
// random speeds up to `speed` per axis.
std::unique_ptr<Simulation> lattice_gas(double restitution, double friction, double a, int cells,
                                        double speed, std::uint64_t seed) {
  DemSetup s;
  s.youngs = 5e7;
  s.restitution = restitution;
  s.friction = friction;
  auto sim = make_simulation(s);
  Rng rng(seed);
  lattice(*sim, 0.003, a, cells * a, speed, rng);
  return sim;
}

// Forces (and torques) by particle id after the last step.
std::map<std::uint64_t, std::pair<Vec3, Vec3>> forces_by_id(const Simulation& sim) {
  std::map<std::uint64_t, std::pair<Vec3, Vec3>> out;
  for (std::size_t i = 0; i < sim.particles.size(); ++i)
    out[sim.particles.id[i]] = {sim.particles.f[i], sim.particles.t[i]};
  return out;
}

}  // namespace

// A particle crossing a periodic face keeps its velocity exactly: wrapping only shifts the
// position by the period (no force, no gravity), so v is bit-identical, and the particle stays
// in [lo, hi) after each rebuild.
TEST(PeriodicAxes, CrossingParticleKeepsItsVelocityExactly) {
  DemSetup s;
  auto sim = make_simulation(s);
  const double L = 0.02, r = 0.001;
  const Vec3 v{3.7, -1.3, 0.9};
  add_sphere(*sim, {0.5 * L, 0.5 * L, 0.5 * L}, r, v, {1, 2, 3});
  sim->set_periodic(box_map(true, true, true, L));
  sim->options.skin = 0.0004;
  sim->dt = 1e-5;
  sim->setup();
  int wraps = 0;
  Vec3 last = sim->particles.x[0];
  for (int k = 0; k < 3000; ++k) {
    sim->step();
    ASSERT_EQ(sim->particles.size(), 1u);  // no ghost outlives the force stage
    EXPECT_EQ(sim->particles.v[0], v);
    EXPECT_EQ(sim->particles.w[0], (Vec3{1, 2, 3}));
    if (norm(sim->particles.x[0] - last) > 0.5 * L) ++wraps;
    last = sim->particles.x[0];
  }
  EXPECT_GE(wraps, 3);  // 0.03 s at 3.7 m/s crosses the 20 mm period more than 5 times in x
  for (int a = 0; a < 3; ++a) {
    // within one rebuild's drift (skin/2) of the box: wrapped at rebuilds only
    EXPECT_GE(sim->particles.x[0][a], -0.5 * sim->options.skin);
    EXPECT_LT(sim->particles.x[0][a], L + 0.5 * sim->options.skin);
  }
}

// Total momentum of a fully periodic box of colliding particles (no walls, no gravity) is
// conserved to round-off: every contact force, including those across the faces through ghosts,
// acts on both bodies with opposite signs. Tolerance: 1e-12 of sum |m v| (a sum of ~10^5 forces
// per step over 2000 steps, each rounded at 1e-16 relative).
TEST(PeriodicAxes, MomentumOfACollidingBoxIsConserved) {
  const double a = 0.0032, L = 6 * a;
  auto sim = lattice_gas(0.7, 0.4, a, 6, 2.0, 5);
  sim->set_periodic(box_map(true, true, true, L));
  sim->dt = rayleigh_step(0.0015, 5e7, 0.3, 2500);
  sim->setup();
  const Vec3 p0 = sim->particles.total_momentum();
  double scale = 0;
  for (std::size_t i = 0; i < sim->particles.size(); ++i)
    scale += sim->particles.mass[i] * norm(sim->particles.v[i]);
  std::size_t max_ghosts = 0, cross = 0;
  for (int k = 0; k < 2000; ++k) {
    sim->step();
    max_ghosts = std::max(max_ghosts, sim->ghost_count());
    if (k % 50 == 0)
      for (std::size_t q = 0; q < sim->pairs().size(); ++q)
        cross += sim->pairs().second[q] >= sim->particles.size() && sim->pair_state().active[q];
  }
  EXPECT_GT(max_ghosts, 0u);
  RecordProperty("particles", std::to_string(sim->particles.size()));
  RecordProperty("max_ghosts", std::to_string(max_ghosts));
  EXPECT_GT(cross, 0u);  // contacts across the faces happened
  EXPECT_LE(norm(sim->particles.total_momentum() - p0), 1e-12 * scale);
  EXPECT_GT(sim->observe().ledger.friction, 0.0);  // particles did rub
}

namespace {
// A dense jittered layer of overlapping spheres, periodic along x with period L (or copied
// twice along x in a domain of 2L without periodicity), moving with random velocities.
std::unique_ptr<Simulation> layer(bool periodic, double L, std::uint64_t seed) {
  DemSetup s;
  s.youngs = 5e7;
  s.restitution = 0.6;
  s.friction = 0.5;
  auto sim = make_simulation(s);
  Rng rng(seed);
  const double d = 0.002, a = 0.00195;  // spacing below d: every neighbour overlaps
  struct P {
    Vec3 x, v, w;
  };
  std::vector<P> ps;
  for (double x = 0.5 * a; x < L - 0.25 * a; x += a)
    for (double y = 0.5 * a; y < 4 * a; y += a)
      ps.push_back({{x + 1e-5 * rng.uniform(-1, 1), y, 1e-5 * rng.uniform(-1, 1)},
                    {rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)},
                    {rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)}});
  for (int copy = 0; copy < (periodic ? 1 : 2); ++copy)
    for (const P& p : ps) add_sphere(*sim, p.x + Vec3{copy * L, 0, 0}, 0.5 * d, p.v, p.w);
  if (periodic) sim->set_periodic(PeriodicMap::axes({true, false, false}, {0, 0, 0}, {L, 1, 1}));
  sim->options.skin = 0.0002;
  sim->dt = 0.5 * rayleigh_step(0.5 * d, s.youngs, s.poisson, s.density);
  return sim;
}
}  // namespace

// Contacts across the boundary match a doubled domain: the same layer simulated periodic over
// L, and as two copies side by side in 2L without periodicity. Over 3 steps a disturbance from
// the doubled domain's open ends travels at most 3 contacts, so every particle of the middle
// half [L/2, 3L/2) of the doubled domain (at least 5 diameters from its ends) has the forces of
// the periodic run — including those across x = 0 / L through ghosts and the friction springs
// they build. Tolerance 1e-12 relative: the forces are sums over the same contacts in another
// order (round-off only).
TEST(PeriodicAxes, ContactsAcrossTheBoundaryMatchADoubledDomain) {
  const double L = 20 * 0.00195;
  auto per = layer(true, L, 9), twice = layer(false, L, 9);
  per->setup();
  twice->setup();
  for (int k = 0; k < 3; ++k) {
    per->step();
    twice->step();
  }
  const auto fp = forces_by_id(*per);
  const std::size_t n = per->particles.size();
  ASSERT_EQ(twice->particles.size(), 2 * n);
  double fscale = 0;
  for (const auto& [id, ft] : fp) fscale = std::max(fscale, norm(ft.first));
  ASSERT_GT(fscale, 0.0);
  std::size_t compared = 0, near_face = 0;
  for (std::size_t i = 0; i < twice->particles.size(); ++i) {
    const double x = twice->particles.x[i].x;
    if (x < 0.5 * L || x >= 1.5 * L) continue;
    const std::uint64_t id = (twice->particles.id[i] - 1) % n + 1;  // the copy's original
    const auto& [f, t] = fp.at(id);
    EXPECT_LE(norm(twice->particles.f[i] - f), 1e-12 * fscale) << "id " << id;
    EXPECT_LE(norm(twice->particles.t[i] - t), 1e-12 * fscale * 0.002) << "id " << id;
    ++compared;
    near_face += std::abs(x - L) < 0.004;
  }
  EXPECT_EQ(compared, n);
  EXPECT_GT(near_face, 10u);  // particles within two diameters of the face x = L
}

namespace {
// Two spheres touching across the face x = L (or the same pair at x = L in an open domain),
// closing slowly, drifting along +x so that the pair crosses the face while in contact, and
// sliding slowly in y: a sticking contact whose tangential spring grows step by step.
std::unique_ptr<Simulation> sliding_pair(bool periodic) {
  DemSetup s;
  s.law = "linear_spring_dashpot";
  s.linear_stiffness = 50;  // soft: the contact lasts ~1 ms, time to drift 3 mm across the face
  s.restitution = 0.9;
  s.friction = 0.8;
  auto sim = make_simulation(s);
  const double L = 0.01, r = 0.001, drift = 3.0;
  const double xa = L - 0.9995 * r;  // A just inside the face, B just across it: 1 µm overlap
  add_sphere(*sim, {xa, 0.005, 0.005}, r, {drift + 0.01, 0.002, 0}, {});
  const double xb = (periodic ? 0 : L) + 0.9995 * r;
  add_sphere(*sim, {xb, 0.005, 0.005}, r, {drift - 0.01, -0.002, 0}, {});
  if (periodic) sim->set_periodic(PeriodicMap::axes({true, false, false}, {0, 0, 0}, {L, 1, 1}));
  sim->options.skin = 0.0001;  // a rebuild every 50 µm of drift: many ghost rebuilds in contact
  sim->dt = 1e-6;
  return sim;
}
}  // namespace

// Tangential history survives a wrap: the periodic pair's contact force equals that of the same
// pair in an open domain at every step of the contact (1e-9 of the largest force so far: the
// positions differ by the period L, so their differences round differently, ~1e-16 L / 1 µm
// overlap ~ 1e-12, and near separation the force itself is at that level), while
// both bodies wrap through the face and the ghosts are rebuilt many times. A spring lost at a
// wrap or a ghost rebuild would drop the tangential force to zero.
TEST(PeriodicAxes, TangentialSpringSurvivesWraps) {
  auto per = sliding_pair(true), open = sliding_pair(false);
  per->setup();
  open->setup();
  double ft_max = 0, f_max = 0;
  const std::uint64_t rebuilds0 = per->neighbor_rebuilds();
  int wraps = 0, steps = 0;
  double xa_last = per->particles.x[slot_of(*per, 1)].x;
  for (int k = 0; k < 20000; ++k) {
    per->step();
    open->step();
    const Vec3 f = forces_by_id(*per).at(1).first, g = forces_by_id(*open).at(1).first;
    if (norm(g) == 0) break;  // the pair separated
    ++steps;
    f_max = std::max(f_max, norm(g));
    EXPECT_LE(norm(f - g), 1e-9 * f_max) << "step " << k;
    ft_max = std::max(ft_max, std::abs(g.y));
    const double xa = per->particles.x[slot_of(*per, 1)].x;
    if (xa < xa_last - 0.005) ++wraps;
    xa_last = xa;
  }
  EXPECT_GT(steps, 300);
  RecordProperty("contact_steps", std::to_string(steps));
  EXPECT_GT(per->neighbor_rebuilds() - rebuilds0, 20u);
  EXPECT_EQ(wraps, 1);  // A wrapped while in contact (B wrapped in the first rebuild)
  EXPECT_GT(ft_max, 0.0);
}

namespace {
// One sphere in a sector of 2π/n about z.
std::unique_ptr<Simulation> sector_sim(int n) {
  DemSetup s;
  auto sim = make_simulation(s);
  sim->set_periodic(PeriodicMap::sector(2, {0, 0, 0}, n));
  sim->options.skin = 0.0004;
  sim->dt = 1e-5;
  return sim;
}
}  // namespace

// Sector periodicity: a particle leaving the sector through θ = 2π/n comes back through θ = 0
// turned by -2π/n; its speed is kept (to 1e-14: a rotation by cos/sin rounds each component) and
// its velocity is the old one turned by the sector angle (1e-14 relative, same reason).
TEST(PeriodicSector, ParticleTurnedBySectorKeepsSpeedAndTurnsVelocity) {
  const int n = 3;
  auto sim = sector_sim(n);
  const Vec3 v{-2.0, 1.0, 0.3};
  add_sphere(*sim, {0.05, 0.06, 0}, 0.001, v, {0, 0, 5});
  sim->setup();
  const PeriodicMap& m = sim->periodic();
  int turns = 0;
  Vec3 v_expected = v;
  for (int k = 0; k < 20000 && turns < 1; ++k) {
    const Vec3 before = sim->particles.v[0];
    sim->step();
    const Vec3 after = sim->particles.v[0];
    if (norm(after - before) > 0) {  // wrapped: turned back by one sector
      ++turns;
      v_expected = m.turn_vector(v_expected, -1);
      EXPECT_LE(norm(after - v_expected), 1e-14 * norm(v));
      EXPECT_NEAR(norm(after), norm(v), 1e-14 * norm(v));
      const double th = m.angle_of(sim->particles.x[0]);
      EXPECT_GE(th, -1e-3);
      EXPECT_LT(th, m.sector_angle());
    }
  }
  EXPECT_EQ(turns, 1);
}

namespace {
// Two spheres in contact (overlapping, sliding and spinning), either astride the sector face
// θ = 0 (periodic: the one below θ = 0 is placed at its image inside the sector) or turned
// into the middle of the sector in an open domain. Positions given as (ρ, θ).
std::unique_ptr<Simulation> sector_pair(bool periodic, double turn) {
  DemSetup s;
  s.youngs = 5e5;  // soft: the contact lasts long enough to drift across the face
  s.friction = 0.5;
  s.restitution = 0.6;
  auto sim = make_simulation(s);
  const int n = 4;
  const double alpha = 2 * std::numbers::pi / n, rho = 0.05, r = 0.002;
  const double half = std::asin(0.999 * r / rho);  // centres 1.998 r apart: touching
  auto polar = [](double rr, double th, double z) {
    return Vec3{rr * std::cos(th), rr * std::sin(th), z};
  };
  auto rot = [](const Vec3& v, double th) {
    return Vec3{std::cos(th) * v.x - std::sin(th) * v.y, std::sin(th) * v.x + std::cos(th) * v.y,
                v.z};
  };
  // both drift at 5 m/s along +y (across θ = 0 at ρ = 50 mm): B leaves through the face θ = α of
  // the periodic run and comes back at θ = 0, taking the contact (and its spring) with it
  const Vec3 va{0.1, 4.99, -0.05}, vb{-0.2, 5.01, 0.1}, wa{0, 20, 10}, wb{5, 0, -30};
  const double tha = half + turn, thb = -half + turn;
  add_sphere(*sim, polar(rho, tha, 0.01), r, rot(va, turn), rot(wa, turn));
  const double thb_placed = periodic ? thb + alpha : thb;
  const double extra = periodic ? alpha : 0;
  add_sphere(*sim, polar(rho, thb_placed, 0.01), r, rot(vb, turn + extra), rot(wb, turn + extra));
  if (periodic) sim->set_periodic(PeriodicMap::sector(2, {0, 0, 0}, n));
  sim->options.skin = 0.0005;
  sim->dt = 0.05 * rayleigh_step(r, s.youngs, s.poisson, s.density);
  return sim;
}
}  // namespace

// A contact across the sector boundary gives the same force as the equivalent contact inside:
// the pair astride θ = 0 (through a ghost turned by 2π/n) against the same pair turned by
// α/2 into an open domain; over the sliding contact, while the pair drifts across the face (the
// contact moves from the face θ = α to θ = 0 and its spring is turned with it), the force on A,
// turned back by α/2, matches to 1e-9 of the largest force (the two runs differ by rotations of
// every vector, each rounding at 1e-16; the contact law amplifies it by the stiffness over the
// overlap, ~1e5).
TEST(PeriodicSector, ContactAcrossTheFaceMatchesTheSameContactInside) {
  const double alpha = std::numbers::pi / 2;
  auto per = sector_pair(true, 0.0), inside = sector_pair(false, 0.5 * alpha);
  per->setup();
  inside->setup();
  double worst = 0, fmax = 0;
  int touching = 0;
  for (int k = 0; k < 3000; ++k) {
    per->step();
    inside->step();
    const Vec3 f = forces_by_id(*per).at(1).first;
    Vec3 g = forces_by_id(*inside).at(1).first;
    g = Vec3{std::cos(-0.5 * alpha) * g.x - std::sin(-0.5 * alpha) * g.y,
             std::sin(-0.5 * alpha) * g.x + std::cos(-0.5 * alpha) * g.y, g.z};
    if (norm(g) == 0 && touching > 0) break;  // separated
    if (norm(g) > 0) ++touching;
    fmax = std::max(fmax, norm(g));
    worst = std::max(worst, norm(f - g));
  }
  EXPECT_GT(touching, 100);
  EXPECT_LE(worst, 1e-9 * fmax);
  // B came back through θ = 0 (was at θ ≈ α)
  EXPECT_LT(per->periodic().angle_of(per->particles.x[slot_of(*per, 2)]), 0.25 * alpha);
}

// Sector with a rotating wall: a cylinder shell about the sector axis turning at constant ω is
// the same in every sector, so the case is consistent; particles resting on a floor inside it
// are dragged round and cross the sector faces. Momentum about the axis is not conserved (the
// wall drives it), but every particle must stay inside the shell and the run must stay finite.
TEST(PeriodicSector, RotatingShellAboutTheAxisDrivesParticlesAcrossFaces) {
  DemSetup s;
  s.youngs = 5e7;
  s.friction = 0.6;
  s.gravity = {0, 0, -9.81};
  auto sim = make_simulation(s);
  const double R = 0.03, r = 0.002;
  auto shell = std::make_unique<CylinderWall>(Vec3{0, 0, 0.05}, Vec3{0, 0, 1}, R, 0.1, true, false);
  shell->kinematics.angular_velocity = {0, 0, 20};
  shell->kinematics.center = {0, 0, 0};
  sim->walls.push_back(std::move(shell));
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  for (int k = 0; k < 6; ++k) {
    const double th = 0.1 + 0.2 * k;
    add_sphere(*sim, {(R - 0.99 * r) * std::cos(th), (R - 0.99 * r) * std::sin(th), 0.99 * r}, r);
  }
  sim->set_periodic(PeriodicMap::sector(2, {0, 0, 0}, 3));
  sim->dt = rayleigh_step(r, s.youngs, s.poisson, s.density);
  sim->setup();
  int crossings = 0;
  std::vector<double> th_last(6);
  for (std::size_t i = 0; i < 6; ++i) th_last[i] = sim->periodic().angle_of(sim->particles.x[i]);
  for (int k = 0; k < 40000; ++k) {
    sim->step();
    for (std::size_t i = 0; i < sim->particles.size(); ++i) {
      const double th = sim->periodic().angle_of(sim->particles.x[i]);
      if (th < th_last[sim->particles.id[i] - 1] - 1.0) ++crossings;
      th_last[sim->particles.id[i] - 1] = th;
      ASSERT_LT(sim->periodic().distance_from_axis(sim->particles.x[i]), R);
    }
  }
  EXPECT_GE(crossings, 2);
}

// A sector conserves the angular momentum about its axis: a contact across a face acts at x_i on
// one body and, folded back and turned by R^-1, at x_j on the other, and a turn about the axis
// keeps the axial component of x × F; wrapping turns position and velocity together. A gas of
// colliding spheres in a quarter sector (no walls, no gravity, kept off the axis) keeps
// L_z = Σ m (x × v)_z + I ω_z to 1e-12 of Σ m |x| |v| (round-off of the sums over ~10^4 contact
// evaluations per quantity).
TEST(PeriodicSector, AngularMomentumAboutTheAxisIsConserved) {
  DemSetup s;
  s.youngs = 5e7;
  s.restitution = 0.7;
  s.friction = 0.4;
  auto sim = make_simulation(s);
  Rng rng(13);
  const double r = 0.0015;
  for (double rho = 0.03; rho < 0.045; rho += 0.0031)
    for (double th = 0.05; th < 0.5 * std::numbers::pi - 0.05; th += 0.0031 / rho)
      add_sphere(*sim, {rho * std::cos(th), rho * std::sin(th), rng.uniform(-0.001, 0.001)}, r,
                 {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-0.2, 0.2)},
                 {0, 0, rng.uniform(-100, 100)});
  sim->set_periodic(PeriodicMap::sector(2, {0, 0, 0}, 4));
  sim->dt = rayleigh_step(r, s.youngs, s.poisson, s.density);
  auto axial = [&](double& scale) {
    const auto& p = sim->particles;
    double l = 0;
    scale = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      l += p.mass[i] * cross(p.x[i], p.v[i]).z + p.inertia[i] * p.w[i].z;
      scale += p.mass[i] * norm(p.x[i]) * norm(p.v[i]) + p.inertia[i] * norm(p.w[i]);
    }
    return l;
  };
  sim->setup();
  double scale = 0;
  const double l0 = axial(scale);
  int wraps = 0;
  for (int k = 0; k < 1500; ++k) {
    const std::uint64_t before = sim->neighbor_rebuilds();
    sim->step();
    wraps += sim->neighbor_rebuilds() > before;
  }
  double scale1 = 0;
  EXPECT_GT(sim->ghost_count(), 0u);
  EXPECT_GT(sim->observe().ledger.friction, 0.0);
  EXPECT_LE(std::abs(axial(scale1) - l0), 1e-12 * scale);
  RecordProperty("particles", std::to_string(sim->particles.size()));
  RecordProperty("rebuilds", std::to_string(wraps));
}

namespace {
std::unique_ptr<Simulation> periodic_gas(breakage::BreakageModule** mod, BreakageProbe* probe) {
  const double a = 0.0036, L = 7 * a;
  auto sim = lattice_gas(0.8, 0.3, a, 7, 3.0, 31);
  sim->set_periodic(box_map(true, true, false, L));
  // z closed by two planes (parallel to the periodic axes: the same on both sides of each face)
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, L}, Vec3{0, 0, -1}));
  std::vector<std::optional<breakage::MaterialBreakage>> mats;
  mats.emplace_back(weak_material(0.02, 0.3, 0.0008, 0.45, breakage::FinesRule::mass, 0.5));
  breakage::BreakageOptions opt;
  opt.placement.overlap_ratio = 0.01;
  auto m = std::make_unique<breakage::BreakageModule>(std::move(mats), opt);
  m->register_fields(sim->particles);  // before a checkpoint is read (as the front end does)
  *mod = m.get();
  if (probe) {
    probe->module = m.get();
    sim->modules.push_back(std::make_unique<ProbeBefore>(probe));
  }
  sim->modules.push_back(std::move(m));
  if (probe) sim->modules.push_back(std::make_unique<ProbeAfter>(probe, 0.5));
  sim->dt = 0.2 * 3.1416 * 0.00018 * std::sqrt(2500 / (5e7 / 2.6)) / (0.1631 * 0.3 + 0.8766);
  return sim;
}
}  // namespace

// Breakage with periodic axes: fragments are owned particles, ghosts are made anew from them;
// the mass (particles + fines booked as mass) is kept to 1e-12 relative over many events, as in
// the closed box (fragment masses close the parent's by construction; rounding of sums only).
TEST(PeriodicAxes, BreakageKeepsMassExactly) {
  breakage::BreakageModule* mod = nullptr;
  BreakageProbe probe;
  auto sim = periodic_gas(&mod, &probe);
  sim->setup();
  const double m0 = sim->particles.total_mass();
  for (int k = 0; k < 3000 && mod->breakages() < 300; ++k) sim->step();
  EXPECT_GE(mod->breakages(), 100u);
  const double m1 = sim->particles.total_mass() + fines_total(*mod);
  EXPECT_LE(std::abs(m1 - m0) / m0, 1e-12);
  EXPECT_LE(probe.worst_mass_error, 1e-12);
}

// Restart bit for bit with ghosts present: a periodic breakage run saved mid-way and continued
// in a fresh simulation reproduces the uninterrupted run exactly (same thread count).
TEST(PeriodicAxes, CheckpointContinuesExactlyWithGhosts) {
  breakage::BreakageModule *ma = nullptr, *mb = nullptr;
  auto a = periodic_gas(&ma, nullptr);
  a->setup();
  a->run(400);
  Archive ar;
  a->save(ar);
  ASSERT_GT(a->ghost_count(), 0u);
  a->run(400);
  auto b = periodic_gas(&mb, nullptr);
  b->load(ar);
  b->run(400);
  ASSERT_GT(ma->breakages(), 0u);
  EXPECT_EQ(ma->breakages(), mb->breakages());
  ASSERT_EQ(a->particles.size(), b->particles.size());
  for (std::size_t i = 0; i < a->particles.size(); ++i) {
    ASSERT_EQ(a->particles.id[i], b->particles.id[i]);
    EXPECT_EQ(a->particles.x[i], b->particles.x[i]);
    EXPECT_EQ(a->particles.v[i], b->particles.v[i]);
    EXPECT_EQ(a->particles.f[i], b->particles.f[i]);
  }
}

// The ghost rule: each pair across a face is seen once. Brute force over all minimum-image pairs
// of a random periodic box in x and y: every overlapping pair is in the list exactly once.
TEST(PeriodicAxes, EveryPairAcrossFacesIsListedOnce) {
  DemSetup s;
  auto sim = make_simulation(s);
  Rng rng(3);
  const double L = 0.02;
  for (int k = 0; k < 150; ++k)
    add_sphere(*sim, {rng.uniform(0, L), rng.uniform(0, L), rng.uniform(0, 0.004)},
               rng.uniform(0.0005, 0.0015));
  sim->set_periodic(box_map(true, true, false, L));
  sim->options.skin = 0.0003;
  sim->dt = 1e-7;
  sim->setup();
  sim->step();
  const auto& p = sim->particles;
  const std::size_t n = p.size();
  std::map<std::pair<std::uint64_t, std::uint64_t>, int> listed;
  // the list holds ghost slots >= n; the pair's bodies are the owners
  for (std::size_t q = 0; q < sim->pairs().size(); ++q) {
    const std::size_t i = sim->slot_owner(sim->pairs().first[q]),
                      j = sim->slot_owner(sim->pairs().second[q]);
    const Vec3 d =
        sim->slot_position(sim->pairs().first[q]) - sim->slot_position(sim->pairs().second[q]);
    if (norm(d) < p.radius[i] + p.radius[j])
      ++listed[{std::min(p.id[i], p.id[j]), std::max(p.id[i], p.id[j])}];
  }
  int expected = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      Vec3 d = p.x[i] - p.x[j];
      for (int a = 0; a < 2; ++a) d[a] -= L * std::round(d[a] / L);  // minimum image
      if (norm(d) < p.radius[i] + p.radius[j]) {
        ++expected;
        EXPECT_EQ((listed[{std::min(p.id[i], p.id[j]), std::max(p.id[i], p.id[j])}]), 1)
            << p.id[i] << " " << p.id[j];
      }
    }
  EXPECT_GT(expected, 10);
  EXPECT_EQ(listed.size(), static_cast<std::size_t>(expected));
}
