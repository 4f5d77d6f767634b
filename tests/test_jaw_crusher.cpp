// The jaw-crusher generator: jaws and cheek plates facing the chamber with the gape and closed-side
// setting of the keys; the swing about the top pivot reaches the closed-side setting and the
// throw at the dead centres of the eccentric; the case-file machine and its bad keys.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/geometry/jaw_crusher.hpp"
#include "comminute/geometry/mesh_pieces.hpp"
#include "comminute/geometry/wall_group.hpp"
#include "machine_fixture.hpp"
#include "mesh_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

// The laboratory crusher of the jaw-crusher study: 100 mm gape, 10 mm closed side, 5 mm throw.
const char* const kLabJaw =
    "height = 0.2\nwidth = 0.1\ngape = 0.1\nclosed_side_setting = 0.01\nthrow = 0.005\n"
    "speed_rpm = 300.0\n";

JawCrusherGeometry lab_jaw() {
  JawCrusherGeometry g;
  g.height = 0.2;
  g.width = 0.1;
  g.gape = 0.1;
  g.closed_side_setting = 0.01;
  g.jaw_throw = 0.005;
  return g;
}

}  // namespace

TEST(JawCrusher, JawsAndCheekPlatesFaceTheChamberWithTheKeyedOpenings) {
  const JawCrusherGeometry g = lab_jaw();
  const IndexedMesh fixed = fixed_jaw_mesh(g), swing = swing_jaw_mesh(g),
                    cheeks = cheek_plates_mesh(g);
  for (const IndexedMesh* m : {&fixed, &swing, &cheeks}) EXPECT_NO_THROW(validate_mesh(*m));
  // 16 strips of 12.5 mm down the jaw, 8 tiles of 12.5 mm across its 0.1 m width
  EXPECT_EQ(fixed.triangles.size(), 2u * 16 * 8);
  EXPECT_EQ(swing.triangles.size(), 2u * 16 * 8);
  for (std::size_t t = 0; t < fixed.triangles.size(); ++t)
    EXPECT_EQ(triangle_normal(fixed, t).x, 1.0);  // towards the chamber, exactly
  // the swing jaw faces the fixed jaw (-x) and leans by the nip angle atan((gape - css) / H);
  // 1e-12: round-off of a cross product and atan2
  const double nip = std::atan2(g.gape - g.closed_side_setting, g.height);
  for (std::size_t t = 0; t < swing.triangles.size(); ++t) {
    const Vec3 n = triangle_normal(swing, t);
    EXPECT_LT(n.x, 0);
    EXPECT_NEAR(std::atan2(n.z, -n.x), nip, 1e-12);
  }
  // openings: at the bottom (z = 0) the closed-side setting, at the top the gape; exact (the
  // vertices are the keys themselves, or sums of steps that land on them)
  for (const Vec3& v : swing.vertices) {
    if (v.z == 0) {
      EXPECT_EQ(v.x, g.closed_side_setting);
    }
    if (v.z == g.height) {
      EXPECT_DOUBLE_EQ(v.x, g.gape);
    }
  }
  for (std::size_t t = 0; t < cheeks.triangles.size(); ++t) {
    const Vec3 n = triangle_normal(cheeks, t);
    const double y = cheeks.vertices[cheeks.triangles[t][0]].y;
    EXPECT_EQ(n.y * y, -std::abs(y));
  }
}

TEST(JawCrusher, SwingReachesTheClosedSideSettingAndTheThrow) {
  // The swing jaw driven through two turns of the eccentric (300 rpm, 2000 steps per turn): its
  // bottom edge swings between x = css (t = 0, 1, 2 periods) and css + throw (half periods), and
  // its top edge, on the pivot, stays at the gape.
  const CaseFile f = CaseFile::parse(kLabJaw);
  auto group = WallGroupRegistry::create("jaw_crusher", f.root());
  ASSERT_EQ(group->parts.size(), 3u);
  EXPECT_EQ(group->parts[0].name, "fixed_jaw");
  EXPECT_EQ(group->parts[1].name, "swing_jaw");
  EXPECT_EQ(group->parts[2].name, "side_plates");
  auto& jaw = static_cast<MeshWall&>(*group->parts[1].wall);
  const JawCrusherGeometry g = lab_jaw();
  const double period = 60.0 / 300.0, dt = period / 2000;
  double lo = 1e9, hi = -1e9, top_drift = 0;
  for (int s = 0; s <= 4000; ++s) {
    for (std::size_t i = 0; i < jaw.mesh().vertices().size(); ++i) {
      const Vec3 body = jaw.mesh().vertices()[i], world = jaw.to_world(body);
      if (body.z == 0) {
        lo = std::min(lo, world.x);
        hi = std::max(hi, world.x);
      } else if (body.z == g.height) {
        top_drift = std::max(top_drift, std::abs(world.x - g.gape) + std::abs(world.z - g.height));
      }
    }
    jaw.advance(dt);
  }
  // The mid-step rule sums alpha'(t) = A sin(Omega t) at the mid-steps: over half a turn that is
  // the exact angle times x / sin x, x = Omega dt / 2 (a sum of sines in closed form), i.e. the
  // stroke is overshot by (Omega dt)^2 / 24 = 4e-7 of the throw (2e-9 m); over a full turn it
  // returns to zero exactly. So: the closed side to round-off (1e-15 m on 0.2 m levers), the open
  // side as that sum predicts to round-off, and the throw within the predicted 2.1e-9 m.
  const double x = std::numbers::pi / 2000, L = std::hypot(g.gape - 0.01, g.height);
  const double beta = std::atan2(g.gape - 0.01, g.height);
  const double open = g.gape - L * std::sin(beta + jaw_opening_angle(g) * x / std::sin(x));
  EXPECT_NEAR(lo, g.closed_side_setting, 1e-15);
  EXPECT_NEAR(hi, open, 1e-14);
  EXPECT_NEAR(hi - lo, g.jaw_throw, 2.1e-9);
  // 1e-12 m: the pivot is the rotation centre; round-off of 4000 rotations of a 0.2 m vector
  EXPECT_LT(top_drift, 1e-12);
  std::printf("closed side %.12g m, throw %.12g m\n", lo, hi - lo);
}

TEST(JawCrusher, BadKeysAreRefusedWithFileKeyAndLine) {
  struct Case {
    std::string toml, key, says;
  };
  const std::string base = "height = 0.2\nwidth = 0.1\nspeed_rpm = 300.0\n";
  const Case cases[] = {
      {base + "gape = 0.1\nclosed_side_setting = -0.01\nthrow = 0.005\n", "closed_side_setting",
       "> 0"},
      {base + "gape = 0.012\nclosed_side_setting = 0.01\nthrow = 0.005\n", "gape",
       "must exceed closed_side_setting + throw"},
      {base + "gape = 0.1\nclosed_side_setting = 0.01\nthrow = 0.0\n", "throw", "> 0"},
      {base + "gape = 0.1\nclosed_side_setting = 0.01\nthrow = 0.005\ndivisions = 0\n", "divisions",
       ""},
  };
  for (const Case& c : cases) expect_refused("jaw_crusher", c.toml, "jaw.toml", c.key, c.says);
}
