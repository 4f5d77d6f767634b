// Motion models for analytic walls (geometry/prescribed_motion_wall.hpp): a plane lifted by the
// `translation` model (with a ramp) carries a sphere resting on it at the plane's speed with the
// static Hertz overlap; a moving plane restarts from a checkpoint bit for bit; bad motion keys are
// refused with key and line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "comminute/core/archive.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "comminute/geometry/prescribed_motion_wall.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "dem_fixture.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

const std::string kHead =
    "[simulation]\nend_time = 0.1\ngravity = [0.0, 0.0, -9.81]\n[contact]\n"
    "model = \"hertz_mindlin\"\n"
    "[materials.ore]\ndensity = 2700.0\nyoungs_modulus = 5.0e7\npoisson_ratio = 0.25\n"
    "[interaction]\nrestitution = 0.3\nfriction = 0.5\n"
    "[[insert]]\ntype = \"fill\"\nmaterial = \"ore\"\ncount = 1\n"
    "region = { shape = \"box\", lo = [0.5, -0.01, 0.0], hi = [0.6, 0.01, 0.03] }\n"
    "size = { distribution = \"fixed\", diameter = 0.01 }\n";

}  // namespace

TEST(AnalyticWallMotion, PlaneOnATranslationRampLiftsARestingSphere) {
  // The floor z = 0 rises at v = 0.05 m/s after a linear ramp of T = 0.05 s; a 10 mm sphere
  // rests on it from the start at its static overlap. After the ramp the sphere rides on the
  // plane: same speed, same static overlap (a frame moving at constant velocity is inertial).
  const TestDir dir;
  const CaseFile f = CaseFile::parse(
      kHead +
          "[[walls]]\nname = \"floor\"\ntype = \"plane\"\nmaterial = \"ore\"\n"
          "point = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n"
          "motion = { type = \"translation\", velocity = [0.0, 0.0, 0.05], ramp_time = 0.05 }\n",
      (dir / "lift.toml").string());
  io::DemCase c = io::build_dem_case(f.root());
  io::decide_time_step(c);
  Simulation& sim = *c.sim;
  ASSERT_EQ(sim.walls.size(), 1u);
  const auto& moving = dynamic_cast<const PrescribedMotionWall&>(*sim.walls[0]);
  const auto& floor = dynamic_cast<const PlaneWall&>(moving.inner());
  EXPECT_EQ(moving.type(), "plane");
  // static Hertz overlap under m g: F = (4/3) E* sqrt(R) d^(3/2) (Hertz 1882; Johnson, Contact
  // Mechanics 1985, eq. 4.22), E* = E / (2 (1 - nu^2)) for two equal materials
  const double r = 0.005, rho = 2700, g = 9.81, estar = 5e7 / (2 * (1 - 0.25 * 0.25));
  const double m = rho * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double overlap = std::pow(3 * m * g / (4 * estar * std::sqrt(r)), 2.0 / 3.0);
  const std::uint64_t id = add_sphere(sim, {0, 0, r - overlap}, r);
  sim.setup();
  const double v = 0.05, ramp = 0.05;
  const auto steps = static_cast<long>(std::ceil(0.1 / sim.dt));
  sim.run(steps);
  const double t = sim.time;
  // the plane: midpoint velocities of a linear ramp sum exactly; only the step across the kink
  // at t = T errs, by at most v dt^2 / (8 T)
  const double z_plane = v * (t - ramp / 2);
  EXPECT_NEAR(floor.point().z, z_plane,
              v * sim.dt * sim.dt / (8 * ramp) + 1e-15 * static_cast<double>(steps));
  EXPECT_NEAR(moving.kinematics.velocity.z, v, 1e-15);
  const std::size_t i = slot_of(sim, id);
  ASSERT_LT(i, sim.particles.size());
  // the transient of the ramp's end decays as exp(-zeta omega t), zeta ~ 0.36 (e = 0.3), omega ~
  // 2200 rad/s, over 0.05 s: to e^-38; what remains is round-off of the positions (1e-18 m) on a
  // 3 µm overlap: 1e-4 of it is a wide margin
  EXPECT_NEAR(sim.particles.x[i].z - floor.point().z, r - overlap, 1e-4 * overlap);
  EXPECT_NEAR(sim.particles.v[i].z, v, 1e-6);
  EXPECT_NEAR(sim.particles.x[i].x, 0.0, 1e-12);
  std::printf("plane z %.9g m (analytic %.9g), sphere overlap %.6g m (static %.6g)\n",
              floor.point().z, z_plane, floor.point().z + r - sim.particles.x[i].z, overlap);
}

TEST(AnalyticWallMotion, OscillatingPlaneRestartsBitForBit) {
  const CaseFile f = CaseFile::parse(
      "type = \"oscillation\"\ndirection = [0.0, 0.6, 0.8]\namplitude = 0.002\nfrequency = 7.0\n");
  const auto make = [&] {
    return std::make_unique<PrescribedMotionWall>(
        std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}), make_motion(f.root()));
  };
  auto a = make(), b = make();
  const double dt = 1e-4;
  for (int s = 0; s < 700; ++s) a->advance(dt);
  Archive ar;
  a->save(ar, "walls/0/");
  b->load(ar, "walls/0/");
  EXPECT_EQ(b->motion_time(), a->motion_time());
  for (int s = 0; s < 700; ++s) {
    a->advance(dt);
    b->advance(dt);
  }
  const auto& pa = dynamic_cast<const PlaneWall&>(a->inner());
  const auto& pb = dynamic_cast<const PlaneWall&>(b->inner());
  EXPECT_EQ(pa.point(), pb.point());
  EXPECT_EQ(a->kinematics.velocity, b->kinematics.velocity);
  // 1400 steps of 0.1 ms are 0.98 of a 7 Hz period: the displacement is A sin(2 pi f t) to the
  // second order of the midpoint rule, (2 pi f dt)^2 / 24 of A (8e-7 of 2 mm)
  const double t = 1400 * dt, disp = 0.002 * std::sin(2 * std::numbers::pi * 7 * t);
  EXPECT_NEAR(pa.point().y, 0.6 * disp, 1e-9);
  EXPECT_NEAR(pa.point().z, 0.8 * disp, 1e-9);
}

TEST(AnalyticWallMotion, BadMotionKeysAreRefusedWithKeyAndLine) {
  const TestDir dir;
  struct Case {
    std::string wall, key, says;
  };
  const Case cases[] = {
      {"type = \"box\"\nlo = [-1.0, -1.0, -1.0]\nhi = [1.0, 1.0, 1.0]\n"
       "motion = { type = \"rotation\", speed_rpm = 10.0 }\n",
       "walls[0].motion.type", "translate but not rotate"},
      {"type = \"box\"\nlo = [-1.0, -1.0, -1.0]\nhi = [1.0, 1.0, 1.0]\n"
       "motion = { type = \"eccentric\", eccentricity = 0.01, speed_rpm = 10.0, "
       "swing_amplitude = 0.1 }\n",
       "walls[0].motion.swing_amplitude", "translate but not rotate"},
      {"type = \"plane\"\npoint = [0.0, 0.0, 0.0]\nvelocity = [0.0, 0.0, 1.0]\n"
       "motion = { type = \"translation\", velocity = [0.0, 0.0, 1.0] }\n",
       "walls[0].velocity", "not both"},
      {"type = \"cylinder\"\ncenter = [0.0, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]\nradius = 0.1\n"
       "length = 0.2\nside = \"inside\"\nmotion = { type = \"oscillation\", amplitude = 0.01, "
       "frequency = -1.0 }\n",
       "walls[0].motion.frequency", "> 0"},
  };
  for (const Case& c : cases) {
    const CaseFile f = CaseFile::parse(kHead + "[[walls]]\nmaterial = \"ore\"\n" + c.wall,
                                       (dir / "walls.toml").string());
    try {
      io::build_dem_case(f.root());
      ADD_FAILURE() << "accepted: " << c.wall;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), c.key) << e.what();
      EXPECT_GT(e.line(), 0) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
}
