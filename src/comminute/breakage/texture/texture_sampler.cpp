#include "comminute/breakage/texture/texture_sampler.hpp"

#include <cmath>
#include <numbers>

#include "comminute/breakage/texture/ball_cube_map.hpp"

namespace comminute::breakage::texture {

Vec3 cell_in_ball(std::size_t i, std::size_t j, std::size_t k, std::size_t n, double r) {
  const double h = 1.0 / static_cast<double>(n);
  const Vec3 u{(static_cast<double>(i) + 0.5) * h - 0.5, (static_cast<double>(j) + 0.5) * h - 0.5,
               (static_cast<double>(k) + 0.5) * h - 0.5};
  return unit_cube_to_ball(u) * (r / unit_ball_radius());
}

const std::vector<Vec3>& CubeSampler::unit_points(std::size_t n) {
  auto it = points_.find(n);
  if (it != points_.end()) return it->second;
  std::vector<Vec3> pts;
  pts.reserve(n * n * n);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) pts.push_back(cell_in_ball(i, j, k, n, 1.0));
  return points_.emplace(n, std::move(pts)).first->second;
}

Cube CubeSampler::sample(const TextureVolume& volume, std::size_t n, double r, Rng& rng) {
  const Vec3 e = volume.extent();
  const Vec3 centre{rng.uniform() * e.x, rng.uniform() * e.y, rng.uniform() * e.z};
  // Uniform random rotation (Shoemake, Graphics Gems III, 1992, "Uniform random rotations").
  const double u1 = rng.uniform(), u2 = 2 * std::numbers::pi * rng.uniform(),
               u3 = 2 * std::numbers::pi * rng.uniform();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const double qw = a * std::sin(u2), qx = a * std::cos(u2), qy = b * std::sin(u3),
               qz = b * std::cos(u3);
  // rotation matrix of the quaternion, scaled by the radius
  const double m[3][3] = {
      {r * (1 - 2 * (qy * qy + qz * qz)), r * 2 * (qx * qy - qz * qw), r * 2 * (qx * qz + qy * qw)},
      {r * 2 * (qx * qy + qz * qw), r * (1 - 2 * (qx * qx + qz * qz)), r * 2 * (qy * qz - qx * qw)},
      {r * 2 * (qx * qz - qy * qw), r * 2 * (qy * qz + qx * qw),
       r * (1 - 2 * (qx * qx + qy * qy))}};
  const auto& pts = unit_points(n);
  Cube c;
  c.n = n;
  c.labels.resize(pts.size());
  for (std::size_t v = 0; v < pts.size(); ++v) {
    const Vec3& p = pts[v];
    const Vec3 q{m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z,
                 m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z,
                 m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z};
    c.labels[v] = volume.at(centre + q);
  }
  return c;
}

Cube sample_cube(const TextureVolume& volume, std::size_t n, double r, Rng& rng) {
  return CubeSampler().sample(volume, n, r, rng);
}

std::vector<std::uint64_t> phase_counts(const Cube& c, std::size_t phases) {
  std::vector<std::uint64_t> n(phases, 0);
  for (std::uint8_t l : c.labels) ++n[l];
  return n;
}

}  // namespace comminute::breakage::texture
