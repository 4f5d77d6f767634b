#pragma once
// Regions for insertion: an axis-aligned box or a finite cylinder.
#include "comminute/core/rng.hpp"
#include "comminute/core/vec3.hpp"

namespace comminute {

struct Region {
  enum class Shape { box, cylinder } shape = Shape::box;
  Vec3 lo, hi;                    // box corners, m
  Vec3 center, axis{0, 0, 1};     // cylinder: centre of the axis, unit axis
  double radius = 0, length = 0;  // cylinder, m

  double volume() const;
  // True if the whole sphere lies inside.
  bool contains(const Vec3& x, double r) const;
  // Uniform random point such that a sphere of radius r fits (rejection from the bounding box).
  Vec3 sample(Rng& rng, double r) const;
  void bounds(Vec3& lo_out, Vec3& hi_out) const;
};

}  // namespace comminute
