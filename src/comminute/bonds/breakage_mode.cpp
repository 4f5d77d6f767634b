#include "comminute/bonds/breakage_mode.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace comminute::bonds {

const char* mode_name(BreakageMode m) {
  switch (m) {
    case BreakageMode::end_chipping:
      return "end_chipping";
    case BreakageMode::central:
      return "central";
    case BreakageMode::split:
      return "split";
  }
  return "unknown";
}

namespace {

Vec3 centroid(const std::vector<Vec3>& points) {
  Vec3 c;
  for (const Vec3& x : points) c += x;
  return points.empty() ? c : c / static_cast<double>(points.size());
}

}  // namespace

Vec3 long_axis(const std::vector<Vec3>& points) {
  const Vec3 c = centroid(points);
  std::array<Vec3, 3> cov{};  // rows of the covariance matrix
  for (const Vec3& x : points) {
    const Vec3 d = x - c;
    for (int a = 0; a < 3; ++a) cov[static_cast<std::size_t>(a)] += d[a] * d;
  }
  // power iteration from the direction of the largest diagonal entry and a tilt, so that a
  // start orthogonal to the answer is unlikely
  Vec3 v{1, 0.1, 0.01};
  for (int it = 0; it < 100; ++it) {
    const Vec3 w{dot(cov[0], v), dot(cov[1], v), dot(cov[2], v)};
    const double n = norm(w);
    if (!(n > 0)) break;
    v = w / n;
  }
  return v / norm(v);
}

BreakageMode classify_breakage(const std::vector<Vec3>& centres, double radius,
                               const std::vector<FailedBondGeometry>& failed) {
  const Vec3 c = centroid(centres), e = long_axis(centres);
  double a = 0;
  for (const Vec3& x : centres) a = std::max(a, std::abs(dot(x - c, e)) + radius);
  double alpha = 0, s = 0;
  for (const FailedBondGeometry& f : failed) {
    alpha += std::abs(dot(f.direction, e));
    s += std::abs(dot(f.position - c, e)) / a;
  }
  const double n = std::max<double>(1.0, static_cast<double>(failed.size()));
  alpha /= n;
  s /= n;
  if (alpha < 0.55) return BreakageMode::split;
  return s > 0.5 ? BreakageMode::end_chipping : BreakageMode::central;
}

}  // namespace comminute::bonds
