#include "comminute/bonds/grain_placement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "comminute/core/error.hpp"

namespace comminute::bonds {

std::array<double, 4> random_quaternion(Rng& rng) {
  // Shoemake, Graphics Gems III, 1992, "Uniform random rotations"
  const double u1 = rng.uniform(), u2 = rng.uniform(), u3 = rng.uniform();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  return {a * std::sin(2 * std::numbers::pi * u2), a * std::cos(2 * std::numbers::pi * u2),
          b * std::sin(2 * std::numbers::pi * u3), b * std::cos(2 * std::numbers::pi * u3)};
}

std::array<Vec3, 3> rotation_matrix(const std::array<double, 4>& q) {
  const auto [w, x, y, z] = q;
  return {Vec3{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
          Vec3{2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
          Vec3{2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
}

std::array<Vec3, 3> random_rotation(Rng& rng) {
  return rotation_matrix(random_quaternion(rng));
}

void SphereGrid::add(const Vec3& x, double r) {
  x_.push_back(x);
  r_.push_back(r);
  cells_[key(cell_of(x, 0), cell_of(x, 1), cell_of(x, 2))].push_back(x_.size() - 1);
}

bool SphereGrid::overlaps(const Vec3& x, double r) const {
  const long cx = cell_of(x, 0), cy = cell_of(x, 1), cz = cell_of(x, 2);
  for (long i = -1; i <= 1; ++i)
    for (long j = -1; j <= 1; ++j)
      for (long k = -1; k <= 1; ++k) {
        const auto it = cells_.find(key(cx + i, cy + j, cz + k));
        if (it == cells_.end()) continue;
        for (std::size_t s : it->second)
          if (norm2(x_[s] - x) < (r_[s] + r) * (r_[s] + r)) return true;
      }
  return false;
}

long SphereGrid::cell_of(const Vec3& x, int a) const {
  return static_cast<long>(std::floor(x[a] / cell_));
}

std::int64_t SphereGrid::key(long i, long j, long k) {
  return (static_cast<std::int64_t>(i) & 0x1FFFFF) << 42 |
         (static_cast<std::int64_t>(j) & 0x1FFFFF) << 21 |
         (static_cast<std::int64_t>(k) & 0x1FFFFF);
}

bool try_place_grain(const GrainTemplate& t, const Region& sample_from, const Region& inside,
                     const SphereGrid& grid, const std::vector<const Wall*>& walls, int attempts,
                     Rng& rng, GrainPose& pose) {
  std::vector<WallContact> touching;
  for (int a = 0; a < attempts; ++a) {
    pose.centre = sample_from.sample(rng, 0);
    pose.rotation = random_quaternion(rng);
    const auto rot = rotation_matrix(pose.rotation);
    pose.spheres.clear();
    bool ok = true;
    for (const Vec3& c : t.centres) {
      const Vec3 x = pose.centre + Vec3{dot(rot[0], c), dot(rot[1], c), dot(rot[2], c)};
      touching.clear();
      if (!inside.contains(x, t.radius) || grid.overlaps(x, t.radius)) ok = false;
      for (const Wall* w : walls)
        if (ok && w->contacts(x, t.radius, 0, touching) > 0)
          for (const WallContact& wc : touching) ok = ok && wc.overlap <= 0;
      if (!ok) break;
      pose.spheres.push_back(x);
    }
    if (ok) return true;
  }
  return false;
}

namespace {

// Slice `layer` (0-based) of `layers` along the region's axis.
Region slice(const Region& g, int layer, int layers) {
  Region s = g;
  const double f0 = static_cast<double>(layer) / layers,
               f1 = static_cast<double>(layer + 1) / layers;
  if (g.shape == Region::Shape::box) {
    s.lo.z = g.lo.z + f0 * (g.hi.z - g.lo.z);
    s.hi.z = g.lo.z + f1 * (g.hi.z - g.lo.z);
  } else {
    s.length = g.length / layers;
    s.center = g.center + ((0.5 * (f0 + f1) - 0.5) * g.length) * g.axis;
  }
  return s;
}

}  // namespace

std::vector<PlacedSphere> place_grains(const std::vector<GrainTemplate>& templates,
                                       const PlacementRequest& request,
                                       const std::vector<const Wall*>& walls,
                                       const std::vector<Vec3>& occupied_x,
                                       const std::vector<double>& occupied_r, Rng& rng) {
  double largest = 0;
  for (const GrainTemplate& t : templates) largest = std::max(largest, t.radius);
  for (double r : occupied_r) largest = std::max(largest, r);
  SphereGrid grid(2 * largest);
  for (std::size_t k = 0; k < occupied_x.size(); ++k) grid.add(occupied_x[k], occupied_r[k]);
  std::vector<PlacedSphere> out;
  GrainPose pose;
  std::uint32_t grain = 0;
  for (int layer = 0; layer < request.layers; ++layer) {
    const Region s = slice(request.region, layer, request.layers);
    const std::uint64_t share = request.grains / static_cast<std::uint64_t>(request.layers) +
                                (static_cast<std::uint64_t>(layer) <
                                         request.grains % static_cast<std::uint64_t>(request.layers)
                                     ? 1
                                     : 0);
    for (std::uint64_t n = 0; n < share; ++n, ++grain) {
      const std::uint32_t ti = grain % static_cast<std::uint32_t>(templates.size());
      const GrainTemplate& t = templates[ti];
      if (!try_place_grain(t, s, request.region, grid, walls, request.attempts, rng, pose))
        throw Error(
            fmt::format("layer {} of {}: grain {} of {} did not fit after {} attempts ({} "
                        "grains placed); enlarge the region or insert fewer grains",
                        layer + 1, request.layers, n + 1, share, request.attempts, grain));
      for (std::size_t k = 0; k < pose.spheres.size(); ++k) {
        grid.add(pose.spheres[k], t.radius);
        out.push_back({pose.spheres[k], t.radius, grain, static_cast<std::uint32_t>(layer + 1),
                       static_cast<std::uint32_t>(k), ti});
      }
    }
  }
  return out;
}

}  // namespace comminute::bonds
