// The ball-mill generator: a closed, consistently oriented mesh with the right volume and lifter
// count; the critical-speed and ball-charge rules against hand values; the case-file wall type.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "comminute/core/case_table.hpp"
#include "comminute/geometry/ball_mill.hpp"
#include "comminute/geometry/mesh_wall.hpp"
#include "mesh_fixture.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

BallMillGeometry bond_mill() {
  BallMillGeometry g;
  g.diameter = 0.305;
  g.length = 0.305;
  g.lifters = 8;
  g.lifter_height = 0.02;
  g.lifter_width = 0.025;
  g.lifter_face_angle = 15 * std::numbers::pi / 180;
  return g;
}

}  // namespace

TEST(BallMill, BareShellIsAClosedPrismOfTheRegularPolygon) {
  BallMillGeometry g;
  g.diameter = 0.3;
  g.length = 0.2;
  g.segments = 60;
  const IndexedMesh m = ball_mill_mesh(g);
  EXPECT_TRUE(closed(m));
  EXPECT_NO_THROW(validate_mesh(m));
  // hand formula: regular N-gon inscribed in radius R, area N R^2 sin(2 pi / N) / 2; 1e-12
  // relative: round-off of a sum of ~200 signed tetrahedra
  const double R = 0.15, N = 60;
  const double v = N * R * R * std::sin(2 * std::numbers::pi / N) / 2 * g.length;
  EXPECT_NEAR(enclosed_volume(m), v, 1e-12 * v);
}

TEST(BallMill, LiftedMillIsClosedWithTheShellVolumeLessTheLifters) {
  const BallMillGeometry g = bond_mill();
  const IndexedMesh m = ball_mill_mesh(g);
  EXPECT_TRUE(closed(m));
  EXPECT_NO_THROW(validate_mesh(m));
  // shell polygon (vertices on the circle) less 8 trapezoids, times L; 1e-12 relative: round-off
  const double v = ball_mill_section_area(g) * g.length;
  EXPECT_NEAR(enclosed_volume(m), v, 1e-12 * v);
  // by hand: the lifters take 8 trapezoids of height b - t and widths w and w - 2 (b - t) tan a
  // out of a circle (less the polygon's sagitta losses, well under 1 %)
  const double R = g.diameter / 2, w = g.lifter_width;
  const double b = std::sqrt(R * R - w * w / 4), t = R - g.lifter_height;
  const double trap = (b - t) * (w - (b - t) * std::tan(g.lifter_face_angle));
  const double rough = (std::numbers::pi * R * R - 8 * trap) * g.length;
  // 0.5 %: a 72-gon has 0.13 % less area than its circle, and the lifter bases cut the segments
  EXPECT_NEAR(enclosed_volume(m), rough, 5e-3 * rough);
  // lifter count: the top-face corners lie at distance t from the axis, four per lifter
  // (two at each end)
  std::set<long> tops;
  for (const Vec3& p : m.vertices)
    if (std::abs(std::hypot(p.x, p.z) -
                 std::hypot(t, w / 2 - (b - t) * std::tan(g.lifter_face_angle))) < 1e-12)
      tops.insert(std::lround(std::atan2(p.z, p.x) * 1e6));
  EXPECT_EQ(tops.size(), 16u);  // two corners per lifter (each at both ends)
}

TEST(BallMill, OpenTubeWithoutEndLiners) {
  BallMillGeometry g = bond_mill();
  g.end_liners = false;
  const IndexedMesh m = ball_mill_mesh(g);
  EXPECT_FALSE(closed(m));
  EXPECT_NO_THROW(validate_mesh(m));
}

TEST(BallMill, LiftersThatDoNotFitAreRefused) {
  BallMillGeometry g = bond_mill();
  g.lifters = 40;  // 40 x 25 mm on a 0.96 m circumference overlap
  EXPECT_THROW(ball_mill_mesh(g), Error);
  g = bond_mill();
  g.lifter_face_angle = 60 * std::numbers::pi / 180;  // 20 mm x tan 60 > 12.5 mm: no top face
  EXPECT_THROW(ball_mill_mesh(g), Error);
}

TEST(BallMill, CriticalSpeedAndBallChargeByHand) {
  // N_c = 42.3 / sqrt(D - d) rpm (Austin, Klimpel & Luckie 1984): D - d = 1 m gives 42.3 rpm;
  // 60 sqrt(2 x 9.81) / (2 pi) = 42.298 by hand; 1e-3 rpm: the last hand digit
  EXPECT_NEAR(critical_speed(1.025, 0.025) * 60 / (2 * std::numbers::pi), 42.298, 1e-3);
  // Bond mill 0.305 m with 25 mm balls: sqrt(2 x 9.81 / 0.28) = 8.3709 rad/s = 79.94 rpm
  EXPECT_NEAR(critical_speed(0.305, 0.025), 8.3709, 1e-4);
  // J = 0.3 of 0.01 m3 with 40 % voids: 0.0018 m3 of steel in balls of 8.1812e-6 m3 -> 220
  EXPECT_EQ(balls_for_filling(0.3, 0.01, 0.025), 220);
}

TEST(BallMill, CaseFileWallTurnsAtTheCriticalFractionAndWritesItsStl) {
  const TestDir dir;
  const std::string stl = (dir / "mill.stl").string();
  const CaseFile f = CaseFile::parse(
      "diameter = 0.305\nlength = 0.305\nlifters = 8\nlifter_height = 0.02\n"
      "lifter_width = 0.025\nlifter_face_angle = 15\ncritical_speed_fraction = 0.7\n"
      "ball_diameter = 0.025\nstl_file = \"" +
      stl + "\"\n");
  auto w = WallRegistry::create("ball_mill", f.root());
  w->advance(1e-6);
  // 0.7 x 8.3709 rad/s about +y, no ramp
  EXPECT_NEAR(w->kinematics.angular_velocity.y, 0.7 * critical_speed(0.305, 0.025), 1e-12);
  // the written file reads back (float coordinates) into the same closed mesh
  const IndexedMesh back = read_stl(stl);
  EXPECT_EQ(back.triangles.size(), ball_mill_mesh(bond_mill()).triangles.size());
  EXPECT_TRUE(closed(back));
}
