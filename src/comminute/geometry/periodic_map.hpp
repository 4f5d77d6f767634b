#pragma once
// The map of a periodic domain: translation along one to three coordinate axes (box [lo, hi) on
// each periodic axis), or rotation about a coordinate axis by the sector angle 2π/n (the sector
// 0 ≤ θ < 2π/n, θ measured from the next axis: from +x about z, from +y about x, from +z about y).
//
// Images: the engine keeps one ghost per owned particle and image for the images listed here, the
// "positive half" of the neighbouring images (translations by s·L with s in {-1, 0, 1}^3 whose
// first non-zero component is +1; the rotation by +2π/n). Each pair across the boundary is then
// seen exactly once, as (owned, ghost of the other) — the image of the other direction would be
// its mirror pair (other, ghost of the first).
//
// Labels: a slot (owned particle or ghost) is the copy x = M^{-c} u of its particle's unwrapped
// position u, with c an integer (per axis for translations, a turn count for the sector). Wrapping
// a particle into the domain changes its c; a ghost of image s has c_owner - s. Contact history is
// keyed by the particle ids and the difference of the two labels, which neither wraps nor ghost
// rebuilds change (docs/models.md, "Periodic boundaries").
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/core/vec3.hpp"

namespace comminute {

class PeriodicMap {
 public:
  using Shift = std::array<int, 3>;  // per axis for translations; [0] = turns for the sector

  PeriodicMap() = default;
  // Periodic along the axes with periodic[a]: bounds lo[a] < hi[a] (m).
  static PeriodicMap axes(const std::array<bool, 3>& periodic, const Vec3& lo, const Vec3& hi);
  // Sector of angle 2π/n (n ≥ 2) about coordinate axis `axis` (0, 1, 2) through `origin`.
  static PeriodicMap sector(int axis, const Vec3& origin, int n);

  bool active() const { return kind_ != Kind::none; }
  bool is_sector() const { return kind_ == Kind::sector; }
  bool periodic(int a) const { return periodic_[static_cast<std::size_t>(a)]; }
  double length(int a) const { return hi_[a] - lo_[a]; }
  const Vec3& lo() const { return lo_; }
  const Vec3& hi() const { return hi_; }
  int sector_axis() const { return axis_; }
  int sector_count() const { return n_; }
  const Vec3& origin() const { return origin_; }
  double sector_angle() const { return angle_; }
  // The images a ghost can take (see above); a ghost stores the index into this list.
  const std::vector<Shift>& images() const { return images_; }

  // The copy of point x under image s (x + s·L, or the rotation by s turns about the axis).
  Vec3 point(const Vec3& x, const Shift& s) const;
  // A vector (velocity, force, spring) under image s: unchanged by translations, rotated by s
  // turns in a sector; inverse_vector undoes it.
  Vec3 vector(const Vec3& v, const Shift& s) const;
  Vec3 inverse_vector(const Vec3& v, const Shift& s) const;
  Vec3 turn_vector(const Vec3& v, int turns) const;  // rotation by turns·2π/n (sector only)
  // Whether a particle at x needs a ghost of image s: it lies within `halo` (m) of the face that
  // image moves it across.
  bool needs_ghost(const Vec3& x, const Shift& s, double halo) const;
  // The image that brings x into the domain (zero when it is inside); the caller applies it to
  // position (and, for a sector, velocity and angular velocity) and subtracts it from the label.
  Shift wrap_shift(const Vec3& x) const;
  // Polar angle θ in [-π, π) of x about the sector axis, and distance from it (sector only).
  double angle_of(const Vec3& x) const;
  double distance_from_axis(const Vec3& x) const;

  // The label packed into one integer (three signed 21-bit fields); packed differences of two
  // labels are differences of the fields while they stay within ±2^20.
  static std::uint64_t pack(const Shift& c);

 private:
  enum class Kind { none, axes, sector };
  Kind kind_ = Kind::none;
  std::array<bool, 3> periodic_{};
  Vec3 lo_, hi_;
  int axis_ = 2, n_ = 0;
  Vec3 origin_;
  double angle_ = 0, cos_ = 1, sin_ = 0;
  std::vector<Shift> images_;
  Vec3 rotate(const Vec3& v, double c, double s) const;  // about the axis, through the origin
};

}  // namespace comminute
