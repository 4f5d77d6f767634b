#include "comminute/breakage/placement/fragment_placement.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace comminute::breakage {

namespace {
Vec3 uniform_in_ball(double radius, Rng& rng) {
  const Vec3 dir{rng.normal(), rng.normal(), rng.normal()};
  const double n = norm(dir);
  if (n == 0) return {};
  return (radius * std::cbrt(rng.uniform()) / n) * dir;
}
// Overlap of two spheres relative to the smaller radius (<= 0 when apart).
double relative_overlap(const Sphere& a, const Sphere& b) {
  return (a.r + b.r - norm(a.x - b.x)) / std::min(a.r, b.r);
}
}  // namespace

std::vector<Sphere> place_fragments(const Sphere& parent, const std::vector<double>& radii,
                                    const std::vector<double>& masses,
                                    const std::vector<Sphere>& neighbours, const WallOverlap& walls,
                                    const PlacementOptions& opt, Rng& rng) {
  const std::size_t n = radii.size();
  std::vector<Sphere> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (int a = 0; a < std::max(1, opt.attempts); ++a) {
      const Sphere c{parent.x + uniform_in_ball(std::max(0.0, parent.r - radii[i]), rng), radii[i]};
      double worst = 0;
      for (std::size_t j = 0; j < i; ++j) worst = std::max(worst, relative_overlap(c, out[j]));
      for (const auto& nb : neighbours) worst = std::max(worst, relative_overlap(c, nb));
      if (walls) worst = std::max(worst, walls(c.x, c.r) / c.r);
      if (worst < best) {
        best = worst;
        out[i] = c;
      }
      if (worst <= 0) break;
    }
  }
  // Mass centre onto the parent centre.
  Vec3 cm;
  double mt = 0;
  for (std::size_t i = 0; i < n; ++i) {
    cm += masses[i] * out[i].x;
    mt += masses[i];
  }
  const Vec3 shift = parent.x - cm / mt;
  for (auto& s : out) s.x += shift;
  // Shrink: a common scale per sibling pair, then each fragment against neighbours and walls.
  std::vector<double> start(radii);
  const double eps = opt.overlap_ratio;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const double d = norm(out[i].x - out[j].x);
      const double s = d / (radii[i] + radii[j] - eps * std::min(radii[i], radii[j]));
      start[i] = std::min(start[i], s * radii[i]);
      start[j] = std::min(start[j], s * radii[j]);
    }
  for (std::size_t i = 0; i < n; ++i) {
    for (const auto& nb : neighbours) start[i] = radius_allowed(out[i].x, start[i], nb, eps);
    if (walls) {
      const double ov = walls(out[i].x, start[i]);
      if (ov > eps * start[i]) start[i] = std::max(0.0, start[i] - ov) / (1.0 - eps);
    }
    out[i].r = std::max(start[i], opt.min_start_ratio * radii[i]);
  }
  return out;
}

namespace {
// The one spin w of the fragments that keeps their mass share of the parent's angular momentum:
// (J_orbit + sum I_i) w = (sum m_i / m_p) I_p w_p about the parent's centre.
Vec3 conserving_spin(const Vec3& x_p, const Vec3& w_p, double inertia_p, double mass_p,
                     const std::vector<Vec3>& x, const std::vector<double>& m,
                     const std::vector<double>& inertia, double mt) {
  // J = sum_i [I_i 1 + m_i (|r_i|^2 1 - r_i r_i^T)], r_i = x_i - x_p.
  Eigen::Matrix3d jm = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Eigen::Vector3d r(x[i].x - x_p.x, x[i].y - x_p.y, x[i].z - x_p.z);
    jm += (inertia[i] + m[i] * r.squaredNorm()) * Eigen::Matrix3d::Identity() -
          m[i] * r * r.transpose();
  }
  // the fragments' share of the parent's angular momentum: that of the mass they carry (1e-12:
  // a family holding the whole mass differs from m_p by rounding only)
  const double share = mt < (1 - 1e-12) * mass_p ? mt / mass_p : 1.0;
  const Eigen::Vector3d lp = share * inertia_p * Eigen::Vector3d(w_p.x, w_p.y, w_p.z);
  if (lp.squaredNorm() == 0) return {};
  const Eigen::Vector3d we = jm.ldlt().solve(lp);
  return {we.x(), we.y(), we.z()};
}
}  // namespace

FragmentVelocities fragment_velocities(const Vec3& x_p, const Vec3& v_p, const Vec3& w_p,
                                       double inertia_p, double mass_p, const std::vector<Vec3>& x,
                                       const std::vector<double>& m,
                                       const std::vector<double>& inertia, double released,
                                       FragmentSpin spin) {
  const std::size_t n = x.size();
  double mt = 0;
  for (double mi : m) mt += mi;
  Vec3 w = w_p;
  if (spin == FragmentSpin::angular_momentum)
    w = conserving_spin(x_p, w_p, inertia_p, mass_p, x, m, inertia, mt);
  // Radial release along the unit directions n_i from the parent centre, minus their mass mean
  // <n> so that sum m_i dv_i = 0: dv_i = c (n_i - <n>), kinetic energy c^2 M (1 - |<n>|^2) / 2.
  // c is set for exactly `released`, but the directional spread 1 - |<n>|^2 is taken as at least
  // 1/4, so no fragment exceeds 2 c <= 2 sqrt(8 released / M) (a family dominated by one
  // off-centre fragment then gets less than `released`; the caller books what it really got).
  std::vector<Vec3> dir(n);
  Vec3 mean_dir;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 r = x[i] - x_p;
    const double len = norm(r);
    dir[i] = len > 0 ? r / len : Vec3{};
    mean_dir += m[i] * dir[i];
  }
  mean_dir /= mt;
  double spread = 0;
  for (std::size_t i = 0; i < n; ++i) spread += m[i] * norm2(dir[i] - mean_dir);
  const double c =
      released > 0 && spread > 0 ? std::sqrt(2 * released / std::max(spread, 0.25 * mt)) : 0.0;
  FragmentVelocities out;
  Vec3 momentum;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 r = x[i] - x_p;
    out.v.push_back(v_p + cross(w, r) + c * (dir[i] - mean_dir));
    out.w.push_back(w);
    momentum += m[i] * out.v.back();
  }
  const Vec3 residual = (momentum - mt * v_p) / mt;  // rounding only
  for (auto& v : out.v) v -= residual;
  return out;
}

}  // namespace comminute::breakage
