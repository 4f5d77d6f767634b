#include "comminute/io/case/periodic_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "comminute/geometry/periodic_images_wall.hpp"

namespace comminute::io {

namespace {

const char* const kAxisNames[3] = {"x", "y", "z"};

// Probe points on the faces a periodic image maps onto each other: x on the face the image moves
// a particle across, and its image. A wall is consistent when every probe sees it the same.
struct Probe {
  Vec3 x;
  PeriodicMap::Shift image;
};

std::vector<Probe> face_probes(const PeriodicMap& map, const Vec3& lo, const Vec3& hi) {
  std::vector<Probe> out;
  const int m = 9;  // probes per direction on each face
  auto along = [&](double a, double b, int k) { return a + (b - a) * (k + 0.5) / m; };
  if (map.is_sector()) {
    const int ax = map.sector_axis(), a1 = (ax + 1) % 3;
    double rho = 0;
    for (int c = 0; c < 8; ++c) {  // farthest corner of the particle box from the axis
      const Vec3 corner{(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z};
      rho = std::max(rho, map.distance_from_axis(corner));
    }
    for (int i = 0; i < m; ++i)
      for (int k = 0; k < m; ++k) {
        Vec3 x = map.origin();
        x[a1] += along(0, rho, i);
        x[ax] = along(lo[ax], hi[ax], k);
        out.push_back({x, {1, 0, 0}});
      }
    return out;
  }
  for (int a = 0; a < 3; ++a) {
    if (!map.periodic(a)) continue;
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    // along the other axes: their periodic bounds, else where the particles start
    const double b0 = map.periodic(b) ? map.lo()[b] : lo[b],
                 b1 = map.periodic(b) ? map.hi()[b] : hi[b];
    const double c0 = map.periodic(c) ? map.lo()[c] : lo[c],
                 c1 = map.periodic(c) ? map.hi()[c] : hi[c];
    PeriodicMap::Shift s{0, 0, 0};
    s[static_cast<std::size_t>(a)] = 1;
    for (int i = 0; i < m; ++i)
      for (int k = 0; k < m; ++k) {
        Vec3 x;
        x[a] = map.lo()[a];
        x[b] = along(b0, b1, i);
        x[c] = along(c0, c1, k);
        out.push_back({x, s});
      }
  }
  return out;
}

bool wall_matches(const Wall& w, const PeriodicMap& map, const Probe& pr, double margin,
                  double tol) {
  // the contacts a sphere of radius `margin` would feel (a mesh reports one per planar patch, at
  // its nearest point: independent of how the patch is cut into triangles)
  std::vector<WallContact> here, there;
  w.contacts(pr.x, margin, 0.0, here);
  w.contacts(map.point(pr.x, pr.image), margin, 0.0, there);
  if (here.size() != there.size()) return false;
  // each contact here has its image there (same overlap, normal turned by the image); contacts
  // with equal overlaps (mirror features of a mesh) are matched by their normals
  std::vector<bool> used(there.size(), false);
  for (const WallContact& c : here) {
    const Vec3 n = map.vector(c.normal, pr.image);
    bool found = false;
    for (std::size_t k = 0; k < there.size() && !found; ++k)
      if (!used[k] && std::abs(c.overlap - there[k].overlap) <= tol &&
          norm(n - there[k].normal) <= 1e-9)
        used[k] = found = true;
    if (!found) return false;
  }
  return true;
}

}  // namespace

void read_periodic(const CaseTable& root, Simulation& sim, const ParticleReach& reach) {
  const auto t = root.optional_table("periodic");
  const auto wall_tables = root.tables("walls");
  std::vector<bool> imaged(sim.walls.size(), false);
  for (std::size_t k = 0; k < wall_tables.size() && k < sim.walls.size(); ++k) {
    imaged[k] = wall_tables[k].boolean("periodic_images", false);
    if (imaged[k] && !t)
      wall_tables[k].fail("periodic_images", "needs a [periodic] table (axes or a sector)");
  }
  if (!t) return;
  const double dmax = reach.largest_diameter;
  // the automatic skin is 0.2 × the mean diameter at the first build: at most 0.2 × the largest
  const double skin = sim.options.skin > 0 ? sim.options.skin : 0.2 * dmax;
  PeriodicMap map;
  if (auto sec = t->optional_table("sector")) {
    for (const char* a : kAxisNames)
      if (t->has(a)) t->fail(a, "give either periodic axes or a [periodic.sector], not both");
    const std::string axis = sec->choice("axis", {"x", "y", "z"});
    const int ax = axis == "x" ? 0 : (axis == "y" ? 1 : 2);
    const Vec3 origin = sec->vec3("origin", Limits::any(), {});
    const auto n = static_cast<int>(sec->integer("n", 2, 3600));
    map = PeriodicMap::sector(ax, origin, n);
    // gravity must be the same in every sector: along the axis
    Vec3 g_perp = sim.gravity;
    g_perp[ax] = 0;
    if (norm(g_perp) > 1e-12 * norm(sim.gravity))
      sec->fail("axis", fmt::format("gravity ({}, {}, {}) m/s2 is not along the sector axis '{}': "
                                    "a sector is periodic only when gravity is",
                                    sim.gravity.x, sim.gravity.y, sim.gravity.z, axis));
    for (const auto& w : sim.walls) {
      const Kinematics& k = w->kinematics;
      Vec3 v_perp = k.velocity, w_perp = k.angular_velocity, c_off = k.center - origin;
      v_perp[ax] = w_perp[ax] = c_off[ax] = 0;
      if (norm(v_perp) > 0 || norm(w_perp) > 0 ||
          (norm2(k.angular_velocity) > 0 && norm(c_off) > 0))
        sec->fail("axis", fmt::format("wall '{}' moves other than along or about the sector axis: "
                                      "its motion would differ between sectors",
                                      w->name));
    }
  } else {
    std::array<bool, 3> periodic{};
    Vec3 lo, hi;
    for (int a = 0; a < 3; ++a) {
      if (!t->has(kAxisNames[a])) continue;
      const auto b = t->numbers(kAxisNames[a], Limits::any());
      if (b.size() != 2 || !(b[1] > b[0]))
        t->fail(kAxisNames[a], "expects the bounds [lo, hi] (m) with lo < hi");
      const double need = 2 * (dmax + skin);
      if (b[1] - b[0] < need)
        t->fail(kAxisNames[a],
                fmt::format("the periodic length {:.6g} m is shorter than 2 × (largest diameter "
                            "{:.6g} m + skin {:.6g} m) = {:.6g} m: a particle would meet two "
                            "images of another",
                            b[1] - b[0], dmax, skin, need));
      periodic[static_cast<std::size_t>(a)] = true;
      lo[a] = b[0];
      hi[a] = b[1];
    }
    if (!(periodic[0] || periodic[1] || periodic[2]))
      t->fail({}, "give the bounds of at least one periodic axis (x, y, z) or a [periodic.sector]");
    map = PeriodicMap::axes(periodic, lo, hi);
    // a rotation about an axis along every periodic axis (a roll or a drum turning about the
    // slice's axis) commutes with the periodic shifts: the wall stays the same on both sides
    for (const auto& w : sim.walls) {
      const Vec3& omega = w->kinematics.angular_velocity;
      bool along = true;
      for (int a = 0; a < 3; ++a) {
        Vec3 e;
        e[a] = 1;
        if (periodic[static_cast<std::size_t>(a)] && norm(cross(omega, e)) > 1e-12 * norm(omega))
          along = false;
      }
      if (norm2(omega) > 0 && w->surface_moves() && !along)
        t->fail({}, fmt::format("wall '{}' rotates about an axis across a periodic axis: its "
                                "image across a periodic face would not follow it",
                                w->name));
    }
  }
  // a wall given for one period stands for all its images (it is the same on both sides of each
  // face by construction); every other wall must be the same on both sides of each face
  for (std::size_t k = 0; k < sim.walls.size(); ++k)
    if (imaged[k])
      sim.walls[k] = std::make_unique<PeriodicImagesWall>(std::move(sim.walls[k]), map);
  Vec3 lo = reach.lo, hi = reach.hi;
  for (int a = 0; a < 3; ++a)
    if (!(lo[a] <= hi[a])) lo[a] = hi[a] = 0;
  double extent = 0;
  for (int a = 0; a < 3; ++a) extent = std::max(extent, hi[a] - lo[a]);
  const double margin = std::max(extent, 2 * (dmax + skin));
  for (std::size_t k = 0; k < sim.walls.size(); ++k) {
    if (imaged[k]) continue;
    const Wall* w = sim.walls[k].get();
    for (const Probe& pr : face_probes(map, lo, hi))
      if (!wall_matches(*w, map, pr, margin, 1e-9 * (margin + norm(pr.x))))
        t->fail({}, fmt::format("wall '{}' crosses a periodic face: it is not the same on both "
                                "sides (seen differently from ({:.6g}, {:.6g}, {:.6g}) m and its "
                                "periodic image); give the wall for one period with "
                                "periodic_images = true, or make it periodic itself",
                                w->name, pr.x.x, pr.x.y, pr.x.z));
  }
  sim.set_periodic(map);
}

}  // namespace comminute::io
