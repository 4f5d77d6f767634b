#include "comminute/bonds/cluster_packing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "comminute/bonds/fragments.hpp"
#include "comminute/core/error.hpp"

namespace comminute::bonds {

double GrainTemplate::solid_fraction() const {
  const double v = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  return static_cast<double>(centres.size()) * v / volume;
}

namespace {

Vec3 random_inside(const ClusterShape& shape, double r, Rng& rng) {
  const Vec3 h = shape.half_extent();
  for (int k = 0; k < 100000; ++k) {
    const Vec3 x{rng.uniform(-h.x, h.x), rng.uniform(-h.y, h.y), rng.uniform(-h.z, h.z)};
    if (shape.signed_distance(x) <= -r) return x;
  }
  throw Error("pack_cluster: found no point of the shape where a sub-sphere fits");
}

// Moves x back inside so that the sphere of radius r fits (a few Newton steps on the distance).
void push_inside(const ClusterShape& shape, double r, Vec3& x) {
  for (int k = 0; k < 20; ++k) {
    const double d = shape.signed_distance(x) + r;
    if (d <= 0) return;
    x -= (d + 1e-9 * r) * shape.outward_normal(x);
  }
}

}  // namespace

GrainTemplate pack_cluster(const ClusterShape& shape, int n, double solid_fraction, Rng& rng) {
  if (n < 1) throw Error("pack_cluster: at least one sub-sphere");
  GrainTemplate g;
  g.volume = shape.volume();
  g.equivalent_diameter = shape.equivalent_diameter();
  const double r0 = std::cbrt(solid_fraction * g.volume / (n * 4.0 / 3.0 * std::numbers::pi));
  double r = r0;
  const std::size_t m = static_cast<std::size_t>(n);
  std::vector<Vec3> x(m), shift(m);
  for (Vec3& c : x) c = random_inside(shape, 1e-3 * r, rng);
  for (int round = 0; round < 200; ++round) {
    double worst = 0;
    for (int it = 0; it < 200; ++it) {
      worst = 0;
      std::fill(shift.begin(), shift.end(), Vec3{});
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = i + 1; j < m; ++j) {
          Vec3 d = x[j] - x[i];
          double l = norm(d);
          if (l >= 2 * r) continue;
          if (l == 0) {  // coincident: any direction
            d = Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
            l = norm(d);
          }
          const Vec3 u = d / l;
          const double o = 2 * r - norm(x[j] - x[i]);
          worst = std::max(worst, o);
          shift[i] -= 0.5 * o * u;
          shift[j] += 0.5 * o * u;
        }
      for (std::size_t i = 0; i < m; ++i) {
        x[i] += shift[i];
        push_inside(shape, r, x[i]);
      }
      if (worst < 1e-4 * r) break;
    }
    if (worst < 1e-4 * r) {
      g.centres = x;
      g.radius = r;
      return g;
    }
    r *= 0.99;
    if (r < 0.5 * r0) break;
  }
  throw Error(fmt::format("pack_cluster: {} sub-spheres do not fit the shape", n));
}

std::vector<std::array<std::uint32_t, 2>> pairs_within_gap(const std::vector<Vec3>& centres,
                                                           double radius, double gap) {
  std::vector<std::array<std::uint32_t, 2>> out;
  for (std::size_t i = 0; i < centres.size(); ++i)
    for (std::size_t j = i + 1; j < centres.size(); ++j)
      if (norm(centres[j] - centres[i]) - 2 * radius <= gap)
        out.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
  return out;
}

std::size_t count_components(std::size_t n,
                             const std::vector<std::array<std::uint32_t, 2>>& pairs) {
  UnionFind u(n);
  for (const auto& p : pairs) u.join(p[0], p[1]);
  std::size_t c = 0;
  for (std::size_t i = 0; i < n; ++i) c += u.find(i) == i ? 1 : 0;
  return c;
}

}  // namespace comminute::bonds
