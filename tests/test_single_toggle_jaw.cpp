// The single-toggle jaw crusher drive (geometry/single_toggle.hpp): the four-bar linkage keeps
// its jaw and toggle lengths to round-off at every crank angle, its bottom edge swings between the
// closed-side setting and css + throw, the moving mesh follows the linkage exactly, and its
// velocity is the derivative of its position; bad keys are refused with file, key and line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "comminute/core/archive.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/geometry/jaw_crusher.hpp"
#include "comminute/geometry/single_toggle.hpp"
#include "comminute/geometry/wall_group.hpp"
#include "machine_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

constexpr double kPi = std::numbers::pi;

// The laboratory crusher (100 mm gape, 10 mm css, 5 mm throw, 0.2 m jaws) on a 0.1 m toggle
// sloping down to its seat by 15 degrees.
const char* const kToggleJaw =
    "height = 0.2\nwidth = 0.1\ngape = 0.1\nclosed_side_setting = 0.01\nthrow = 0.005\n"
    "speed_rpm = 300.0\ndrive = \"single_toggle\"\ntoggle_length = 0.1\ntoggle_angle = 15.0\n";

SingleToggleLinkage lab_linkage(double toggle_angle_deg = 15.0) {
  return single_toggle_linkage(0.2, 0.1, 0.01, 0.005, 0.1, toggle_angle_deg * kPi / 180);
}

// The largest x of the bottom edge over a turn: a fine scan, then golden-section refinement.
double open_side(const SingleToggleLinkage& k) {
  const int n = 20000;
  int best = 0;
  for (int i = 1; i < n; ++i)
    if (k.toggle_end(k.start_angle + 2 * kPi * i / n).x >
        k.toggle_end(k.start_angle + 2 * kPi * best / n).x)
      best = i;
  double a = k.start_angle + 2 * kPi * (best - 1) / n, b = k.start_angle + 2 * kPi * (best + 1) / n;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 100; ++it) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (k.toggle_end(c).x > k.toggle_end(d).x)
      b = d;
    else
      a = c;
  }
  return k.toggle_end(0.5 * (a + b)).x;
}

}  // namespace

TEST(SingleToggleJaw, LinkageKeepsItsLinksAndSwingsBetweenTheSettings) {
  for (double angle : {15.0, 30.0, -10.0}) {
    const SingleToggleLinkage k = lab_linkage(angle);
    // the closed side is drawn: A at the jaw's top edge, B at its bottom edge (1e-15 m: round-off
    // of a circle intersection on 0.2 m links)
    EXPECT_NEAR(norm(k.pin(k.start_angle) - Vec3{0.1, 0, 0.2}), 0, 1e-15);
    EXPECT_NEAR(norm(k.toggle_end(k.start_angle) - Vec3{0.01, 0, 0}), 0, 1e-15);
    double lo = 1e9;
    for (int i = 0; i < 3600; ++i) {
      const double theta = k.start_angle + 2 * kPi * i / 3600;
      const Vec3 a = k.pin(theta), b = k.toggle_end(theta);
      // the jaw and the toggle are rigid: their lengths are constant to round-off (4e-17 m on
      // 0.1-0.2 m lengths: a few ulps)
      EXPECT_NEAR(norm(b - a), k.jaw_length, 1e-15);
      EXPECT_NEAR(norm(b - k.toggle_seat), k.toggle_length, 1e-15);
      EXPECT_NEAR(norm(a - k.shaft), k.eccentricity, 1e-15);
      lo = std::min(lo, b.x);
    }
    // closed side at the start, a limit position of the toggle (nothing smaller on the turn)
    EXPECT_NEAR(lo, 0.01, 1e-15) << angle;
    // the open side is the throw beyond it; 1e-13 m: the eccentric is bisected to round-off
    // and the maximum refined by golden section to ~1e-8 rad, where x is flat to (1e-8)^2 e
    EXPECT_NEAR(open_side(k) - 0.01, 0.005, 1e-13) << angle;
    std::printf("toggle %.0f deg: eccentricity %.9g m\n", angle, k.eccentricity);
    // the top of the jaw moves on the eccentric's circle: its stroke across the chamber (2e)
    // exceeds the bottom's, the single toggle's elliptical motion
    EXPECT_GT(2 * k.eccentricity, 0.005);
  }
}

TEST(SingleToggleJaw, AngularSpeedIsTheDerivativeOfTheJawAngle) {
  const SingleToggleLinkage k = lab_linkage();
  const double omega = 300 * 2 * kPi / 60, h = 1e-6;
  for (int i = 0; i < 36; ++i) {
    const double theta = k.start_angle + 2 * kPi * i / 36;
    const double numeric =
        (k.jaw_angle(theta + omega * h) - k.jaw_angle(theta - omega * h)) / (2 * h);
    // central difference: truncation (omega h)^2/6 ~ 1e-9 relative, round-off 1e-16 / h ~ 1e-10
    // rad/s; jaw speeds are ~1 rad/s
    EXPECT_NEAR(k.jaw_angular_speed(theta, omega), numeric, 1e-8);
  }
}

TEST(SingleToggleJaw, MeshFollowsTheLinkageAndMovesWithItsVelocity) {
  const CaseFile f = CaseFile::parse(kToggleJaw);
  auto group = WallGroupRegistry::create("jaw_crusher", f.root());
  auto& jaw = static_cast<MeshWall&>(*group->parts[1].wall);
  const SingleToggleLinkage k = lab_linkage();
  const double period = 0.2, dt = period / 2000;
  const Vec3 top{0.1, 0, 0.2}, bottom{0.01, 0, 0}, middle{0.055, 0.03, 0.1};
  Vec3 before = jaw.to_world(middle);
  double lo = 1e9, hi = -1e9;
  for (int s = 1; s <= 4000; ++s) {
    const Vec3 v = jaw.kinematics.velocity_at(jaw.to_world(middle));
    jaw.advance(dt);
    const Vec3 b = jaw.to_world(bottom), a = jaw.to_world(top), after = jaw.to_world(middle);
    // the pose is the linkage's closed form, not integrated: the toggle and the eccentric keep
    // their lengths to round-off (1e-15 m) after 4000 steps, the jaw's width axis stays y
    ASSERT_NEAR(norm(b - k.toggle_seat), k.toggle_length, 1e-15) << s;
    ASSERT_NEAR(norm(a - k.shaft), k.eccentricity, 1e-15) << s;
    ASSERT_NEAR(after.y, 0.03, 1e-15);
    lo = std::min(lo, b.x);
    hi = std::max(hi, b.x);
    // the velocity of a point of the jaw at the start of a step, times dt, is its displacement
    // over the step to first order; the step's midpoint velocity would be second order, so
    // compare the mean of the start and end velocities: error (Omega dt)^2 / 12 relative
    // (~2.5e-6) of speeds ~0.2 m/s
    const Vec3 v_end = jaw.kinematics.velocity_at(after);
    EXPECT_NEAR(norm((after - before) / dt - 0.5 * (v + v_end)), 0, 1e-6) << s;
    before = after;
  }
  // the steps land on the closed side exactly (t = 0, 0.2, 0.4 s); the open side lies between
  // steps: x is flat there to (pi/2000)^2 / 2 of its curvature, < 1e-8 m here
  EXPECT_NEAR(lo, 0.01, 1e-15);
  EXPECT_NEAR(hi - lo, 0.005, 1e-8);
}

TEST(SingleToggleJaw, RestartsBitForBit) {
  const CaseFile f = CaseFile::parse(kToggleJaw);
  auto ga = WallGroupRegistry::create("jaw_crusher", f.root());
  auto gb = WallGroupRegistry::create("jaw_crusher", f.root());
  auto& a = static_cast<MeshWall&>(*ga->parts[1].wall);
  auto& b = static_cast<MeshWall&>(*gb->parts[1].wall);
  const double dt = 0.2 / 2000;
  for (int s = 0; s < 777; ++s) a.advance(dt);
  Archive ar;
  a.save(ar, "walls/1/");
  b.load(ar, "walls/1/");
  for (int s = 0; s < 1500; ++s) {
    a.advance(dt);
    b.advance(dt);
  }
  const Vec3 p{0.03, 0.02, 0.05};
  EXPECT_EQ(a.to_world(p), b.to_world(p));
  EXPECT_EQ(a.kinematics.center, b.kinematics.center);
  EXPECT_EQ(a.kinematics.angular_velocity, b.kinematics.angular_velocity);
}

TEST(SingleToggleJaw, BadKeysAreRefusedWithFileKeyAndLine) {
  const std::string base =
      "height = 0.2\nwidth = 0.1\ngape = 0.1\nclosed_side_setting = 0.01\nspeed_rpm = 300.0\n"
      "drive = \"single_toggle\"\n";
  expect_refused("jaw_crusher", base + "throw = 0.005\ntoggle_length = -0.1\ntoggle_angle = 15\n",
                 "jaw.toml", "toggle_length", "> 0");
  expect_refused("jaw_crusher", base + "throw = 0.005\ntoggle_length = 0.1\ntoggle_angle = 0.0\n",
                 "jaw.toml", "toggle_angle", "nearly");
  expect_refused("jaw_crusher", base + "throw = 0.005\ntoggle_length = 0.1\ntoggle_angle = 95\n",
                 "jaw.toml", "toggle_angle", "between -90 and 90");
  // a 60 mm throw needs an eccentric longer than a quarter of the longest link
  expect_refused("jaw_crusher", base + "throw = 0.06\ntoggle_length = 0.1\ntoggle_angle = 15\n",
                 "jaw.toml", "throw", "no eccentric");
  expect_refused("jaw_crusher",
                 "height = 0.2\nwidth = 0.1\ngape = 0.1\nclosed_side_setting = 0.01\n"
                 "speed_rpm = 300.0\nthrow = 0.005\ndrive = \"double\"\n",
                 "jaw.toml", "drive", "");
}
