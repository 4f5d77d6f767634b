// Candidate triangle lists of a mesh wall (Wall::near_elements at a neighbour-list build, then
// Wall::contacts_among every step): while a sphere moved less than half the skin and the mesh
// travelled less than half the skin, the look-up among the listed triangles returns exactly what
// the search of the whole cell grid returns, bit for bit, and the lists are short.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <random>

#include "mesh_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

// The side of a drum: radius R, length L along y, n facets of two triangles (the peer drum has
// 180 facets of 3.5 mm x 50 mm: long thin triangles).
IndexedMesh drum_side(int n, double R, double L) {
  IndexedMesh m;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    m.vertices.push_back({R * std::cos(a), 0, R * std::sin(a)});
    m.vertices.push_back({R * std::cos(a), L, R * std::sin(a)});
  }
  for (int k = 0; k < n; ++k) {
    const auto a = static_cast<std::uint32_t>(2 * k), b = a + 1,
               c = static_cast<std::uint32_t>(2 * ((k + 1) % n)), d = c + 1;
    m.triangles.push_back({a, c, d});
    m.triangles.push_back({a, d, b});
  }
  return m;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same(const WallContact& a, const WallContact& b) {
  bool ok = a.feature == b.feature && a.element == b.element && same_bits(a.overlap, b.overlap);
  for (int k = 0; k < 3; ++k)
    ok = ok && same_bits(a.normal[k], b.normal[k]) && same_bits(a.point[k], b.point[k]);
  return ok;
}

}  // namespace

TEST(MeshElementLists, LookUpAmongListedTrianglesEqualsTheGridSearchWhileWithinTheSkin) {
  const double R = 0.1, L = 0.05, r = 0.001, skin = 0.0004;
  auto wall = mesh_wall(drum_side(180, R, L));
  wall->kinematics.angular_velocity = {0, std::numbers::pi, 0};  // 30 rpm about the drum axis
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(0, 1);
  int touching = 0, listed = 0, spheres = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // a sphere whose centre lies within 2 r of the drum side (touching or just off it)
    const double a = 2 * std::numbers::pi * u(rng), rho = R - 2 * r * u(rng) - 0.5 * r;
    const Vec3 x0{rho * std::cos(a), L * u(rng), rho * std::sin(a)};
    std::vector<std::uint32_t> list;
    ASSERT_TRUE(wall->near_elements(x0, r, skin, list));
    ASSERT_TRUE(std::is_sorted(list.begin(), list.end()));
    listed += static_cast<int>(list.size());
    ++spheres;
    // the mesh turns and the sphere moves, each by less than skin / 2 in all
    double travel = 0;
    Vec3 x = x0;
    for (int step = 0; step < 200; ++step) {
      const double dt = 1e-5;
      if (travel + wall->travel(dt) >= 0.5 * skin) break;
      travel += wall->travel(dt);
      wall->advance(dt);
      const Vec3 dir{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5};
      const Vec3 cand = x + dir * (0.01 * skin);
      if (norm(cand - x0) < 0.5 * skin) x = cand;
      std::vector<WallContact> all, among;
      wall->contacts(x, r, 0.0, all);
      wall->contacts_among(x, r, 0.0, list, among);
      ASSERT_EQ(all.size(), among.size()) << "trial " << trial << " step " << step;
      for (std::size_t k = 0; k < all.size(); ++k) ASSERT_TRUE(same(all[k], among[k]));
      touching += static_cast<int>(all.size());
    }
  }
  EXPECT_GT(touching, 1000);  // the comparison saw many real contacts, not only empty look-ups
  // The point of the lists: a sphere near the drum side lists a handful of its 360 triangles
  // (facets 3.5 mm wide, reach r + skin = 1.4 mm: at most a few facets, each two triangles).
  EXPECT_LT(static_cast<double>(listed) / spheres, 8.0);
}

TEST(MeshElementLists, CandidateSearchAmongTheListEqualsTheGridSearch) {
  // At a build the candidate features (margin = skin) come from the listed triangles too.
  const double R = 0.1, L = 0.05, r = 0.001, skin = 0.0004;
  auto wall = mesh_wall(drum_side(180, R, L));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  int found = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const double a = 2 * std::numbers::pi * u(rng), rho = R - 3 * r * u(rng);
    const Vec3 x{rho * std::cos(a), (L + 4 * r) * u(rng) - 2 * r, rho * std::sin(a)};
    std::vector<std::uint32_t> list;
    wall->near_elements(x, r, skin, list);
    std::vector<WallContact> all, among;
    wall->contacts(x, r, skin, all);
    wall->contacts_among(x, r, skin, list, among);
    ASSERT_EQ(all.size(), among.size()) << "trial " << trial;
    for (std::size_t k = 0; k < all.size(); ++k) ASSERT_TRUE(same(all[k], among[k]));
    found += static_cast<int>(all.size());
  }
  EXPECT_GT(found, 1000);
}

TEST(MeshElementLists, TravelOfATurningMeshIsItsDistanceFromTheRotationAxis) {
  // The lists are rebuilt once the mesh travelled skin/2 in all. A vertex p moves at
  // |v + w x (p - c)| <= |v| + |w| d(p), d(p) its distance from the rotation axis: a drum turning
  // about its own axis travels w R dt per step (R = 0.1 m), not w |p - c| dt (up to
  // sqrt(R^2 + L^2) = 0.112 m from a centre on one end), which rebuilt 12 % more often.
  const double R = 0.1, L = 0.05, w = std::numbers::pi, dt = 1e-5;
  auto wall = mesh_wall(drum_side(180, R, L));
  wall->kinematics.angular_velocity = {0, w, 0};
  // tolerance: the vertices are R (cos a, sin a) rounded, a few ulps off R
  EXPECT_NEAR(wall->travel(dt), w * R * dt, 1e-14 * w * R * dt);
  // about the x axis the farthest vertex is (0, L, R): the cache follows the new axis
  wall->kinematics.angular_velocity = {w, 0, 0};
  EXPECT_NEAR(wall->travel(dt), w * std::hypot(R, L) * dt, 1e-14 * w * R * dt);
}

TEST(MeshElementLists, TravelBoundsEveryVertexDisplacementOfAStep) {
  // Rotation about a tilted axis through an off-centre point, without and with a translation:
  // over each step no vertex moves farther than travel(dt) (the bound the rebuild trigger relies
  // on). Without the translation the bound is tight (the farthest vertex from the axis moves
  // within 1 % of it); with it, |v| + |w| d exceeds |v + w x r| where the two are not aligned.
  const double dt = 1e-4;
  for (const Vec3 v : {Vec3{0, 0, 0}, Vec3{0.05, 0.0, -0.02}}) {
    auto wall = mesh_wall(drum_side(36, 0.1, 0.05));
    wall->kinematics.center = {0.02, -0.01, 0.03};
    wall->kinematics.angular_velocity = {1.0, 2.0, -0.5};
    wall->kinematics.velocity = v;
    const auto& body = wall->mesh().vertices();
    for (int step = 0; step < 50; ++step) {
      std::vector<Vec3> before;
      for (const Vec3& b : body) before.push_back(wall->to_world(b));
      wall->advance(dt);
      const double bound = wall->travel(dt);
      double largest = 0;
      for (std::size_t k = 0; k < body.size(); ++k)
        largest = std::max(largest, norm(wall->to_world(body[k]) - before[k]));
      // a vertex moves along a chord (<= the arc |v + w x r| dt); 1e-12: round-off of the pose
      EXPECT_LE(largest, bound * (1 + 1e-12)) << "step " << step;
      if (norm(v) == 0) {
        EXPECT_GT(largest, 0.99 * bound) << "step " << step;
      }
    }
  }
}
