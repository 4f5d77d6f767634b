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

Cube sample_cube(const TextureVolume& volume, std::size_t n, double r, Rng& rng) {
  const Vec3 e = volume.extent();
  const Vec3 centre{rng.uniform() * e.x, rng.uniform() * e.y, rng.uniform() * e.z};
  // Uniform random rotation (Shoemake, Graphics Gems III, 1992, "Uniform random rotations").
  const double u1 = rng.uniform(), u2 = 2 * std::numbers::pi * rng.uniform(),
               u3 = 2 * std::numbers::pi * rng.uniform();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const double qw = a * std::sin(u2), qx = a * std::cos(u2), qy = b * std::sin(u3),
               qz = b * std::cos(u3);
  const double m[3][3] = {
      {1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)},
      {2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)},
      {2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)}};
  Cube c;
  c.n = n;
  c.labels.resize(n * n * n);
  std::size_t v = 0;
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i, ++v) {
        const Vec3 p = cell_in_ball(i, j, k, n, r);
        const Vec3 q{m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z,
                     m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z,
                     m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z};
        c.labels[v] = volume.at(centre + q);
      }
  return c;
}

std::vector<std::uint64_t> phase_counts(const Cube& c, std::size_t phases) {
  std::vector<std::uint64_t> n(phases, 0);
  for (std::uint8_t l : c.labels) ++n[l];
  return n;
}

}  // namespace comminute::breakage::texture
