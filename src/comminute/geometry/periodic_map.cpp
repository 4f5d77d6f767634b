#include "comminute/geometry/periodic_map.hpp"

#include <cmath>
#include <numbers>

#include "comminute/core/error.hpp"

namespace comminute {

PeriodicMap PeriodicMap::axes(const std::array<bool, 3>& periodic, const Vec3& lo, const Vec3& hi) {
  PeriodicMap m;
  m.kind_ = Kind::axes;
  m.periodic_ = periodic;
  m.lo_ = lo;
  m.hi_ = hi;
  for (int a = 0; a < 3; ++a)
    if (periodic[static_cast<std::size_t>(a)] && !(hi[a] > lo[a]))
      throw Error("periodic bounds need lo < hi");
  // the positive half of {-1, 0, 1}^3 over the periodic axes: first non-zero component +1
  for (int sx = -1; sx <= 1; ++sx)
    for (int sy = -1; sy <= 1; ++sy)
      for (int sz = -1; sz <= 1; ++sz) {
        const Shift s{sx, sy, sz};
        bool ok = true, positive = false, decided = false;
        for (std::size_t a = 0; a < 3; ++a) {
          if (s[a] != 0 && !periodic[a]) ok = false;
          if (!decided && s[a] != 0) {
            positive = s[a] > 0;
            decided = true;
          }
        }
        if (ok && positive) m.images_.push_back(s);
      }
  return m;
}

PeriodicMap PeriodicMap::sector(int axis, const Vec3& origin, int n) {
  if (axis < 0 || axis > 2 || n < 2) throw Error("a periodic sector needs an axis and n >= 2");
  PeriodicMap m;
  m.kind_ = Kind::sector;
  m.axis_ = axis;
  m.origin_ = origin;
  m.n_ = n;
  m.angle_ = 2 * std::numbers::pi / n;
  m.cos_ = std::cos(m.angle_);
  m.sin_ = std::sin(m.angle_);
  m.images_.push_back({1, 0, 0});
  return m;
}

Vec3 PeriodicMap::rotate(const Vec3& v, double c, double s) const {
  // (e1, e2, axis) right-handed: about z (x, y), about x (y, z), about y (z, x)
  const int a1 = (axis_ + 1) % 3, a2 = (axis_ + 2) % 3;
  Vec3 r = v;
  r[a1] = c * v[a1] - s * v[a2];
  r[a2] = s * v[a1] + c * v[a2];
  return r;
}

Vec3 PeriodicMap::turn_vector(const Vec3& v, int turns) const {
  if (kind_ != Kind::sector || turns == 0) return v;
  if (turns == 1) return rotate(v, cos_, sin_);
  if (turns == -1) return rotate(v, cos_, -sin_);
  const double t = turns * angle_;
  return rotate(v, std::cos(t), std::sin(t));
}

Vec3 PeriodicMap::point(const Vec3& x, const Shift& s) const {
  if (kind_ == Kind::sector) return origin_ + turn_vector(x - origin_, s[0]);
  Vec3 y = x;
  for (int a = 0; a < 3; ++a) y[a] += s[static_cast<std::size_t>(a)] * (hi_[a] - lo_[a]);
  return y;
}

Vec3 PeriodicMap::vector(const Vec3& v, const Shift& s) const {
  return turn_vector(v, s[0]);
}

Vec3 PeriodicMap::inverse_vector(const Vec3& v, const Shift& s) const {
  return turn_vector(v, -s[0]);
}

double PeriodicMap::angle_of(const Vec3& x) const {
  const Vec3 d = x - origin_;
  return std::atan2(d[(axis_ + 2) % 3], d[(axis_ + 1) % 3]);
}

double PeriodicMap::distance_from_axis(const Vec3& x) const {
  const Vec3 d = x - origin_;
  return std::hypot(d[(axis_ + 1) % 3], d[(axis_ + 2) % 3]);
}

bool PeriodicMap::needs_ghost(const Vec3& x, const Shift& s, double halo) const {
  if (kind_ == Kind::sector) {
    // distance to the start face (the half-plane θ = 0): ρ sin θ, or ρ beyond a quarter turn
    const double th = angle_of(x), rho = distance_from_axis(x);
    const double dist = th > 0 && th < 0.5 * std::numbers::pi ? rho * std::sin(th) : rho;
    return dist < halo;
  }
  for (int a = 0; a < 3; ++a) {
    const int sa = s[static_cast<std::size_t>(a)];
    if (sa > 0 && !(x[a] - lo_[a] < halo)) return false;
    if (sa < 0 && !(hi_[a] - x[a] < halo)) return false;
  }
  return true;
}

PeriodicMap::Shift PeriodicMap::wrap_shift(const Vec3& x) const {
  Shift s{0, 0, 0};
  if (kind_ == Kind::sector) {
    const double th = angle_of(x);  // [-π, π]
    if (th < 0 || th >= angle_) s[0] = -static_cast<int>(std::floor(th / angle_));
    return s;
  }
  for (int a = 0; a < 3; ++a)
    if (periodic_[static_cast<std::size_t>(a)]) {
      const double L = hi_[a] - lo_[a];
      if (x[a] < lo_[a] || x[a] >= hi_[a])
        s[static_cast<std::size_t>(a)] = -static_cast<int>(std::floor((x[a] - lo_[a]) / L));
    }
  return s;
}

std::uint64_t PeriodicMap::pack(const Shift& c) {
  std::uint64_t out = 0;
  for (std::size_t a = 0; a < 3; ++a)
    out += static_cast<std::uint64_t>(static_cast<std::int64_t>(c[a])) << (21 * a);
  return out;
}

}  // namespace comminute
