#include "comminute/analysis/stat_grid.hpp"

#include <cmath>
#include <numbers>

#include "comminute/core/error.hpp"

namespace comminute::analysis {

namespace {
constexpr double two_pi = 2 * std::numbers::pi;
// The bin of u in [a, b) cut into n, or -1.
long bin(double u, double a, double b, std::size_t n) {
  if (!(u >= a && u < b)) return -1;
  const auto k = static_cast<long>((u - a) / (b - a) * static_cast<double>(n));
  return std::min(k, static_cast<long>(n) - 1);
}
}  // namespace

StatGrid::StatGrid(const StatGridSpec& spec) : s_(spec) {
  for (std::size_t n : s_.cells)
    if (n == 0) throw Error("statistics grid: every direction needs at least one cell");
  if (s_.cylindrical) {
    s_.axis = s_.axis / norm(s_.axis);
    const Vec3 a = std::abs(s_.axis.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    e2_ = cross(s_.axis, a);
    e2_ = e2_ / norm(e2_);
    e1_ = cross(e2_, s_.axis);
  }
}

std::size_t StatGrid::cell_of(const Vec3& x) const {
  const auto [nx, ny, nz] = s_.cells;
  long a, b, c;
  if (!s_.cylindrical) {
    a = bin(x.x, s_.lo.x, s_.hi.x, nx);
    b = bin(x.y, s_.lo.y, s_.hi.y, ny);
    c = bin(x.z, s_.lo.z, s_.hi.z, nz);
  } else {
    const Vec3 d = x - s_.origin;
    const double z = dot(d, s_.axis);
    const double u = dot(d, e1_), v = dot(d, e2_);
    double th = std::atan2(v, u) - angle_;
    th -= two_pi * std::floor(th / two_pi);
    a = bin(std::hypot(u, v), s_.r_min, s_.r_max, nx);
    b = bin(th, 0.0, two_pi, ny);
    c = bin(z, s_.z_min, s_.z_max, nz);
  }
  if (a < 0 || b < 0 || c < 0) return outside;
  return static_cast<std::size_t>(a) +
         nx * (static_cast<std::size_t>(b) + ny * static_cast<std::size_t>(c));
}

std::array<std::size_t, 3> StatGrid::index(std::size_t cell) const {
  const auto [nx, ny, nz] = s_.cells;
  return {cell % nx, (cell / nx) % ny, cell / (nx * ny)};
}

std::array<double, 3> StatGrid::centre(std::size_t cell) const {
  const auto [i, j, k] = index(cell);
  const auto [nx, ny, nz] = s_.cells;
  auto mid = [](double a, double b, std::size_t m, std::size_t n) {
    return a + (b - a) * (static_cast<double>(m) + 0.5) / static_cast<double>(n);
  };
  if (!s_.cylindrical)
    return {mid(s_.lo.x, s_.hi.x, i, nx), mid(s_.lo.y, s_.hi.y, j, ny),
            mid(s_.lo.z, s_.hi.z, k, nz)};
  return {mid(s_.r_min, s_.r_max, i, nx), mid(0, two_pi, j, ny), mid(s_.z_min, s_.z_max, k, nz)};
}

double StatGrid::volume(std::size_t cell) const {
  const auto [nx, ny, nz] = s_.cells;
  if (!s_.cylindrical) {
    const Vec3 e = s_.hi - s_.lo;
    return e.x * e.y * e.z / static_cast<double>(size());
  }
  const std::size_t i = index(cell)[0];
  const double dr = (s_.r_max - s_.r_min) / static_cast<double>(nx);
  const double r0 = s_.r_min + dr * static_cast<double>(i), r1 = r0 + dr;
  return 0.5 * (r1 * r1 - r0 * r0) * two_pi / static_cast<double>(ny) * (s_.z_max - s_.z_min) /
         static_cast<double>(nz);
}

std::vector<Vec3> StatGrid::corners() const {
  const auto [nx, ny, nz] = s_.cells;
  std::vector<Vec3> pts;
  pts.reserve((nx + 1) * (ny + 1) * (nz + 1));
  auto at = [](double a, double b, std::size_t m, std::size_t n) {
    return a + (b - a) * static_cast<double>(m) / static_cast<double>(n);
  };
  for (std::size_t k = 0; k <= nz; ++k)
    for (std::size_t j = 0; j <= ny; ++j)
      for (std::size_t i = 0; i <= nx; ++i) {
        if (!s_.cylindrical) {
          pts.push_back({at(s_.lo.x, s_.hi.x, i, nx), at(s_.lo.y, s_.hi.y, j, ny),
                         at(s_.lo.z, s_.hi.z, k, nz)});
          continue;
        }
        const double r = at(s_.r_min, s_.r_max, i, nx), th = at(0, two_pi, j, ny) + angle_;
        const double z = at(s_.z_min, s_.z_max, k, nz);
        pts.push_back(s_.origin + r * (std::cos(th) * e1_ + std::sin(th) * e2_) + z * s_.axis);
      }
  return pts;
}

std::array<Vec3, 3> StatGrid::basis_at(const Vec3& x) const {
  if (!s_.cylindrical) return {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  const Vec3 d = x - s_.origin;
  const double u = dot(d, e1_), v = dot(d, e2_), r = std::hypot(u, v);
  const Vec3 er = r > 0 ? (u * e1_ + v * e2_) / r : e1_;
  return {er, cross(s_.axis, er), s_.axis};
}

Vec3 in_basis(const Vec3& v, const std::array<Vec3, 3>& e) {
  return {dot(v, e[0]), dot(v, e[1]), dot(v, e[2])};
}

SymTensor in_basis(const SymTensor& t, const std::array<Vec3, 3>& e) {
  auto apply = [&](const Vec3& b) {  // T b
    return Vec3{t[0] * b.x + t[3] * b.y + t[4] * b.z, t[3] * b.x + t[1] * b.y + t[5] * b.z,
                t[4] * b.x + t[5] * b.y + t[2] * b.z};
  };
  const Vec3 t0 = apply(e[0]), t1 = apply(e[1]), t2 = apply(e[2]);
  return {dot(e[0], t0), dot(e[1], t1), dot(e[2], t2), dot(e[0], t1), dot(e[0], t2), dot(e[1], t2)};
}

}  // namespace comminute::analysis
