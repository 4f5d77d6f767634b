#include "comminute/breakage/texture/ball_cube_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace comminute::breakage::texture {

namespace {
constexpr double pi = std::numbers::pi;
// Constants of Rosca, Morawiec & De Graef (2014), section 3 (docs/models.md eq. T1):
// kappa = (pi/6)^(1/6) scales the cube onto the Lambert-type ball construction,
// beta = pi^(5/6) / (2 6^(1/6)) (not sqrt(pi/6)), R = (3 pi / 4)^(1/3).
const double kappa = std::pow(pi / 6, 1.0 / 6);
const double beta = std::pow(pi, 5.0 / 6) / (2 * std::pow(6.0, 1.0 / 6));
const double radius = std::cbrt(3 * pi / 4);
const double prefactor = radius * std::pow(2.0, 0.25) / beta;

// The pyramid (apex at the centre) a point lies in: 0 for +-z, 1 for +-x, 2 for +-y (Rosca et
// al. 2014); the same inequalities serve cube and ball points.
int pyramid(const Vec3& v) {
  const double ax = std::abs(v.x), ay = std::abs(v.y), az = std::abs(v.z);
  if (ax <= az && ay <= az) return 0;
  if (ay <= ax && az <= ax) return 1;
  return 2;
}
// Rotates cyclically so that the pyramid's axis becomes z, and back.
Vec3 to_z(const Vec3& v, int p) {
  if (p == 1) return {v.y, v.z, v.x};
  if (p == 2) return {v.z, v.x, v.y};
  return v;
}
Vec3 from_z(const Vec3& v, int p) {
  if (p == 1) return {v.z, v.x, v.y};
  if (p == 2) return {v.y, v.z, v.x};
  return v;
}

// Square -> disk step of the forward map for |Y| <= |X| (Rosca et al. 2014, section 3).
void square_to_disk(double x, double y, double& t1, double& t2) {
  const double q = pi * y / (12 * x);
  const double c = std::cos(q), s = std::sin(q);
  const double den = std::sqrt(std::numbers::sqrt2 - c);
  t1 = prefactor * x * (std::numbers::sqrt2 * c - 1) / den;
  t2 = prefactor * x * std::numbers::sqrt2 * s / den;
}

// Disk -> square step of the inverse map for |y| <= |x| (Rosca et al. 2014, section 3).
void disk_to_square(double x, double y, double& x1, double& y1) {
  const double rho2 = x * x + y * y;
  const double w = rho2 + x * x;
  const double sw = std::sqrt(w);
  const double q =
      std::sqrt(w * rho2 / (w - std::abs(x) * sw)) * beta / (std::numbers::sqrt2 * radius);
  // The paper's angle is arccos t, t = (y^2 + |x| sqrt(w)) / (sqrt2 rho^2) in [0.966, 1]; near
  // t = 1 (y << x) arccos loses half the digits, so 1 - t is formed without cancellation
  // (sqrt(1 + u) - 1 = u / (sqrt(1 + u) + 1), u = y^2 / (2 x^2)) and the angle taken as
  // 2 arcsin(sqrt((1 - t) / 2)).
  const double u = y * y / (2 * x * x);
  const double one_minus_t =
      y * y * ((std::numbers::sqrt2 - 1) - 1 / (std::numbers::sqrt2 * (1 + std::sqrt(1 + u)))) /
      (std::numbers::sqrt2 * rho2);
  const double angle = 2 * std::asin(std::sqrt(std::clamp(0.5 * one_minus_t, 0.0, 1.0)));
  x1 = std::copysign(q, x);
  y1 = std::copysign(q, y) * (12 / pi) * angle;
}
}  // namespace

double cube_edge() {
  return std::pow(pi, 2.0 / 3);
}
double ball_radius() {
  return radius;
}
double unit_ball_radius() {
  return std::cbrt(3 / (4 * pi));
}

Vec3 cube_to_ball(const Vec3& c) {
  const int p = pyramid(c);
  const Vec3 v = to_z(c, p) * kappa;
  if (v.x == 0 && v.y == 0 && v.z == 0) return {};
  const double root = std::sqrt(6 / pi);
  if (v.x == 0 && v.y == 0) return from_z({0, 0, root * v.z}, p);
  double t1 = 0, t2 = 0;
  if (std::abs(v.y) <= std::abs(v.x))
    square_to_disk(v.x, v.y, t1, t2);
  else
    square_to_disk(v.y, v.x, t2, t1);
  // Disk -> ball lift (Rosca et al. 2014, section 3).
  const double rho2 = t1 * t1 + t2 * t2;
  const double lift = std::sqrt(1 - pi * rho2 / (24 * v.z * v.z));
  return from_z({t1 * lift, t2 * lift, root * v.z - std::sqrt(pi / 24) * rho2 / v.z}, p);
}

Vec3 ball_to_cube(const Vec3& b) {
  const int p = pyramid(b);
  const Vec3 v = to_z(b, p);
  const double r = norm(v);
  if (r == 0) return {};
  // Ball -> disk (inverse of the lift).
  const double s = std::sqrt(2 * r / (r + std::abs(v.z)));
  const double x2 = s * v.x, y2 = s * v.y, z2 = std::copysign(r * std::sqrt(pi / 6), v.z);
  double x1 = 0, y1 = 0;
  if (x2 != 0 || y2 != 0) {
    if (std::abs(y2) <= std::abs(x2))
      disk_to_square(x2, y2, x1, y1);
    else
      disk_to_square(y2, x2, y1, x1);
  }
  return from_z(Vec3{x1, y1, z2} / kappa, p);
}

Vec3 unit_cube_to_ball(const Vec3& c) {
  const double a = cube_edge();  // homogeneous of degree 1: f_1(v) = f(a v) / a
  return cube_to_ball(c * a) / a;
}

Vec3 unit_ball_to_cube(const Vec3& b) {
  const double a = cube_edge();
  return ball_to_cube(b * a) / a;
}

}  // namespace comminute::breakage::texture
