// The HPGR (roll pair) generator: closed, outward-oriented rolls whose vertices lie on the roll
// circle and whose pinch gap is the `gap` key; chute and side plates facing the rolls; the
// case-file machine (parts, speeds, STL files, bad keys refused with file, key and line); and a
// sphere dragged by a turning roll moves at the roll's surface speed at its contact point.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/geometry/ball_mill.hpp"
#include "comminute/geometry/mesh_pieces.hpp"
#include "comminute/geometry/roll_pair.hpp"
#include "comminute/geometry/wall_group.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "dem_fixture.hpp"
#include "machine_fixture.hpp"
#include "mesh_fixture.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

RollPairGeometry press() {
  RollPairGeometry g;
  g.diameter = 1.0;
  g.width = 0.2;
  g.gap = 0.06;
  g.segments = 360;
  g.chute_opening = 0.3;
  g.chute_height = 0.4;
  g.chute_angle = 20 * std::numbers::pi / 180;
  g.chute_clearance = 0.006;
  g.side_plate_clearance = 0.004;
  return g;
}

const char* const kPressToml =
    "diameter = 1.0\nwidth = 0.2\ngap = 0.06\nspeed_rpm = 19.0\nchute_opening = 0.3\n"
    "chute_height = 0.4\nchute_angle = 20.0\n";

}  // namespace

TEST(Hpgr, RollsAreClosedOutwardPrismsOnTheRollCircle) {
  const RollPairGeometry g = press();
  const double R = g.diameter / 2, c = roll_offset(g);
  for (int k = 0; k < 2; ++k) {
    const IndexedMesh m = roll_mesh(g, k);
    EXPECT_TRUE(closed(m)) << "roll " << k;
    EXPECT_NO_THROW(validate_mesh(m));
    // the regular 360-gon of radius R times the width; positive: the normals point out of the
    // roll. 1e-12 relative: round-off of a sum of ~1400 signed tetrahedra
    const double v = g.segments * R * R * std::sin(2 * std::numbers::pi / g.segments) / 2 * g.width;
    EXPECT_NEAR(enclosed_volume(m), v, 1e-12 * v) << "roll " << k;
    // every mantle vertex at distance R from the roll axis (y through (-/+ c, 0)); the two end
    // centres on it. 1e-15 m: a few units of round-off in R cos, R sin and c (~0.5 m)
    const double axis_x = k == 0 ? -c : c;
    const auto mantle = static_cast<std::size_t>((roll_rings(g) + 1) * g.segments);
    EXPECT_EQ(m.vertices.size(), mantle + 2);
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
      const double rho = std::hypot(m.vertices[i].x - axis_x, m.vertices[i].z);
      EXPECT_NEAR(rho, i < mantle ? R : 0.0, 1e-15) << "roll " << k << " vertex " << i;
    }
  }
}

TEST(Hpgr, GapAtThePinchIsTheKey) {
  for (double gap : {0.06, 0.0123, 0.3}) {
    RollPairGeometry g = press();
    g.gap = gap;
    g.chute_opening = gap + 0.1;
    const IndexedMesh a = roll_mesh(g, 0), b = roll_mesh(g, 1);
    double right_of_a = -1e9, left_of_b = 1e9;
    for (const Vec3& v : a.vertices) right_of_a = std::max(right_of_a, v.x);
    for (const Vec3& v : b.vertices) left_of_b = std::min(left_of_b, v.x);
    // the two pinch vertices face each other on the line of centres (z = 0): 1e-15 m, the
    // round-off of (D/2 + gap/2) - D/2 with D/2 = 0.5 m
    EXPECT_NEAR(left_of_b - right_of_a, gap, 1e-15) << gap;
    for (const Vec3& v : a.vertices)
      if (v.x == right_of_a) {
        EXPECT_EQ(v.z, 0.0);
      }
  }
}

TEST(Hpgr, ChuteAndSidePlatesFaceTheRollsWithTheirClearances) {
  const RollPairGeometry g = press();
  const IndexedMesh chute = chute_mesh(g), sides = side_plates_mesh(g);
  ASSERT_EQ(chute.triangles.size(), 4u);
  ASSERT_EQ(sides.triangles.size(), 4u);
  EXPECT_NO_THROW(validate_mesh(chute));
  EXPECT_NO_THROW(validate_mesh(sides));
  for (std::size_t t = 0; t < chute.triangles.size(); ++t) {
    const Vec3 n = triangle_normal(chute, t);
    const double x = chute.vertices[chute.triangles[t][0]].x;
    EXPECT_LT(n.x * x, 0) << "chute triangle " << t << " faces away from the feed";
    // each plate leans outwards by the chute angle: its normal is that far from the horizontal;
    // 1e-12: round-off of tan, a cross product and atan2
    EXPECT_NEAR(std::atan2(n.z, std::abs(n.x)), g.chute_angle, 1e-12);
  }
  for (std::size_t t = 0; t < sides.triangles.size(); ++t) {
    const Vec3 n = triangle_normal(sides, t);
    const double y = sides.vertices[sides.triangles[t][0]].y;
    EXPECT_EQ(n.y * y, -std::abs(y)) << "side plate triangle " << t;  // n = -sign(y) e_y exactly
    EXPECT_NEAR(std::abs(y), g.width / 2 + g.side_plate_clearance, 1e-16);
  }
  // the chute's lower edges: at x = -/+ opening/2 and chute_clearance above the roll circle
  // there; 1e-15 m: round-off of a square root of ~0.25 m^2
  const double R = g.diameter / 2, s = roll_offset(g) - g.chute_opening / 2;
  double lowest = 1e9;
  for (const Vec3& v : chute.vertices) lowest = std::min(lowest, v.z);
  EXPECT_NEAR(lowest - std::sqrt(R * R - s * s), g.chute_clearance, 1e-15);
}

TEST(Hpgr, WithoutSidePlatesTheRollsAndChuteRepeatAcrossTheSlice) {
  // A slice periodic along y with period W must see the same surface from both faces: the rolls
  // and the chute reach at least `overhang` past -/+ W/2, and their vertices repeat with period
  // W (every vertex shifted by W, inside the mesh's reach, is a vertex too; but the centres of
  // the rolls' end discs).
  RollPairGeometry g = press();
  g.side_plates = false;
  g.overhang = 0.5;
  EXPECT_TRUE(side_plates_mesh(g).triangles.empty());
  for (const IndexedMesh& m : {roll_mesh(g, 0), roll_mesh(g, 1), chute_mesh(g)}) {
    double y = 0;
    for (const Vec3& v : m.vertices) y = std::max(y, std::abs(v.y));
    EXPECT_GE(y, g.width / 2 + g.overhang);
    std::size_t shifted = 0;
    for (const Vec3& v : m.vertices) {
      if (!(v.y + g.width <= y)) continue;
      if (v.z == 0 && std::abs(v.x) == roll_offset(g)) continue;  // an end disc's centre
      ++shifted;
      // 1e-12 m: round-off of the tile positions -half + k (2 half / n), half ~ 0.7 m
      bool found = false;
      for (const Vec3& w : m.vertices)
        found = found || norm(w - Vec3{v.x, v.y + g.width, v.z}) < 1e-12;
      EXPECT_TRUE(found) << v.x << " " << v.y << " " << v.z;
    }
    EXPECT_GT(shifted, 0u);
  }
}

TEST(Hpgr, CaseFileMachineHasItsPartsSpeedsAndStlFiles) {
  const TestDir dir;
  const CaseFile f = CaseFile::parse(std::string(kPressToml) + "ramp_time = 0.5\nstl_file = \"" +
                                     (dir / "hpgr.stl").string() + "\"\n");
  const auto group = WallGroupRegistry::create("hpgr", f.root());
  ASSERT_NE(group, nullptr);
  ASSERT_EQ(group->parts.size(), 4u);
  const char* names[] = {"roll1", "roll2", "chute", "side_plates"};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(group->parts[k].name, names[k]);
    const IndexedMesh back = read_stl(dir / ("hpgr_" + group->parts[k].name + ".stl"));
    EXPECT_EQ(back.triangles.size(),
              static_cast<const MeshWall&>(*group->parts[k].wall).mesh().triangles().size());
    if (k < 2) {
      EXPECT_TRUE(closed(back));
    }
  }
  // after the 0.5 s ramp: 19 rpm, the roll at -x about +y (its pinch side moving down), the
  // other about -y, each about its own axis; the plates stand still
  const double omega = 19 * 2 * std::numbers::pi / 60, c = 0.5 + 0.03;
  for (Wall* w : {group->parts[0].wall.get(), group->parts[1].wall.get()})
    for (int s = 0; s < 1000; ++s) w->advance(1e-3);
  EXPECT_DOUBLE_EQ(group->parts[0].wall->kinematics.angular_velocity.y, omega);
  EXPECT_DOUBLE_EQ(group->parts[1].wall->kinematics.angular_velocity.y, -omega);
  EXPECT_DOUBLE_EQ(group->parts[0].wall->kinematics.center.x, -c);
  EXPECT_DOUBLE_EQ(group->parts[1].wall->kinematics.center.x, c);
  const Vec3 pinch_speed =
      group->parts[0].wall->kinematics.velocity_at({-0.03, 0, 0});  // the pinch point of roll 1
  EXPECT_LT(pinch_speed.z, 0);
  EXPECT_FALSE(group->parts[2].wall->kinematics.moving());
}

TEST(Hpgr, BadKeysAreRefusedWithFileKeyAndLine) {
  struct Case {
    std::string toml, key, says;
  };
  const std::string base = "diameter = 1.0\nwidth = 0.2\nspeed_rpm = 19.0\nchute = false\n";
  const Case cases[] = {
      {base + "gap = -0.06\n", "gap", "> 0"},
      {base + "gap = 1.2\n", "gap", "smaller than the roll diameter"},
      {base + "gap = 1.0\n", "gap", "smaller than the roll diameter"},
      {"diameter = 1.0\nwidth = 0.2\nspeed_rpm = 19.0\ngap = 0.06\nchute_opening = 0.05\n"
       "chute_height = 0.3\n",
       "chute_opening", "between the gap"},
      {base + "gap = 0.06\nside_plates = false\noverhang = 0.0\n", "overhang", "> 0"},
      {"diameter = 1.0\nwidth = 0.2\ngap = 0.06\nchute = false\nspeed_rpm = -3.0\n", "speed_rpm",
       "> 0"},
  };
  for (const Case& c : cases) expect_refused("hpgr", c.toml, "press.toml", c.key, c.says);
}

TEST(Hpgr, TurningRollDragsASphereAtItsSurfaceSpeed) {
  // A sphere set down on top of a roll turning at omega slides until friction makes its contact
  // point move with the roll surface, omega R (then it rolls along without slip). The roll is the
  // generator's roll 1 (fine facets, 3600 segments: the facet sag R (1 - cos(pi/N)) = 0.04 um is
  // 0.5 % of the sphere's static overlap, so the passing facets barely shake it; with 360 the
  // mean slip is 8e-6 m/s instead of 1e-6, the spring handed from facet to facet ten times as
  // often).
  const double R = 0.1, omega = 19 * 2 * std::numbers::pi / 60;
  const CaseFile f = CaseFile::parse(
      "diameter = 0.2\nwidth = 0.05\ngap = 0.02\nspeed_rpm = 19.0\nsegments = 3600\n"
      "axial_divisions = 4\nchute = false\n");
  auto group = WallGroupRegistry::create("hpgr", f.root());
  DemSetup s;
  s.friction = 0.5;
  s.gravity = {0, 0, -9.81};
  auto sim = make_simulation(s);
  sim->walls.push_back(std::move(group->parts[0].wall));
  const double r = 0.005, c = 0.1 + 0.01;  // the roll's axis at x = -(D/2 + gap/2)
  add_sphere(*sim, {-c, 0, R + r + 1e-6}, r);
  sim->dt = 5e-6;  // 1 % of the sphere's Rayleigh time
  sim->setup();
  // slip ends after omega R / ((1 + 5/2) mu g) = 12 ms; measure over 30-40 ms, still near the
  // top (the sphere has moved about 2 mm)
  sim->run(6000);
  double slip = 0, samples = 0;
  std::vector<WallContact> hits;
  for (int k = 0; k < 2000; ++k) {
    sim->step();
    const Vec3 x = sim->particles.x[0], v = sim->particles.v[0], w = sim->particles.w[0];
    hits.clear();
    ASSERT_EQ(sim->walls[0]->contacts(x, r, 0.0, hits), 1) << "step " << k;
    // the sphere's material at the contact (the lever r - overlap, as the wall force loop takes
    // it) against the roll's material at the contact point
    const WallContact& h = hits[0];
    const Vec3 surface_velocity = sim->walls[0]->kinematics.velocity_at(h.point);
    const Vec3 dv = v - cross(w, (r - h.overlap) * h.normal) - surface_velocity;
    slip += norm(dv - dot(dv, h.normal) * h.normal);  // tangential: the normal part is vibration
    samples += 1;
    if (k == 0) {
      // the roll's surface speed at the contact is omega R to the overlap and the facet sag
      EXPECT_NEAR(norm(surface_velocity), omega * R, 1e-4 * omega * R);
    }
  }
  // 1e-4 omega R: after sticking the contact creeps only at the rate of the tangential spring's
  // stretch, dF_t/dt / k_t: F_t ~ (2/7) m g sin(phi) changes at ~2e-3 N/s as the sphere rolls off
  // the crown, k_t = 8 G* a ~ 1.9e3 N/m, so ~1e-6 m/s = 5e-6 omega R; 1e-4 leaves room for the
  // facets' passing (each a face -> edge -> face hand-over of the spring)
  std::printf("mean slip at the contact %.3g m/s, surface speed %.6g m/s, sphere speed %.6g\n",
              slip / samples, omega * R, norm(sim->particles.v[0]));
  EXPECT_LT(slip / samples, 1e-4 * omega * R);
  EXPECT_GT(sim->particles.v[0].x, 0.2 * omega * R);  // carried towards the pinch
}

namespace {

// A slice of the press without side plates, rolls at full speed from the start, periodic along
// `axis` over [-W/2, W/2] = [-0.1, 0.1] m.
std::string periodic_press(const std::string& axis) {
  return "[simulation]\nend_time = 0.1\n[contact]\nmodel = \"hertz_mindlin\"\n"
         "[materials.ore]\ndensity = 2700.0\nyoungs_modulus = 5.0e7\npoisson_ratio = 0.25\n"
         "[periodic]\n" +
         axis +
         " = [-0.1, 0.1]\n"
         "[[walls]]\nname = \"press\"\ntype = \"hpgr\"\nmaterial = \"ore\"\ndiameter = 1.0\n"
         "width = 0.2\ngap = 0.06\nspeed_rpm = 19.0\nchute_opening = 0.3\nchute_height = 0.3\n"
         "side_plates = false\noverhang = 0.4\n"
         "[[insert]]\ntype = \"fill\"\nmaterial = \"ore\"\ncount = 5\n"
         "region = { shape = \"box\", lo = [-0.1, -0.09, 0.4], hi = [0.1, 0.09, 0.6] }\n"
         "size = { distribution = \"fixed\", diameter = 0.03 }\n";
}

}  // namespace

TEST(Hpgr, PeriodicSliceAcrossTheRollWidthIsAccepted) {
  // Rolls turning about y, the periodic axis, are the same on both faces at every instant (the
  // rotation commutes with the shift along its axis), and the faceted rolls and the chute repeat
  // with the period: the case builds with the rolls at speed from t = 0.
  const TestDir dir;
  const CaseFile f = CaseFile::parse(periodic_press("y"), (dir / "press.toml").string());
  io::DemCase c = io::build_dem_case(f.root());
  ASSERT_EQ(c.sim->walls.size(), 3u);
  EXPECT_GT(norm(c.sim->walls[0]->kinematics.angular_velocity), 0);
  // periodic along x instead, across the rolls' axes: their rotation would not follow the images
  const CaseFile g = CaseFile::parse(periodic_press("x"), (dir / "press_x.toml").string());
  try {
    io::build_dem_case(g.root());
    ADD_FAILURE() << "a slice periodic across the roll axes was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "periodic");
    EXPECT_NE(std::string(e.what()).find("wall 'press_roll1' rotates"), std::string::npos)
        << e.what();
  }
}
