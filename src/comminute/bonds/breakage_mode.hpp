#pragma once
// How a bonded grain broke, told from where its bonds failed (a rule of this code, written for
// elongated grains such as rice; docs/models.md, "Bonded grains"):
//   e  the grain's long axis: the principal axis of largest spread of its sub-sphere centres at
//      the moment it broke (power iteration on their covariance), c their centroid, a the
//      half-length (largest |(x − c)·e| + sub-sphere radius);
//   α  the mean of |n·e| over the grain's failed bonds, n the unit line of centres at failure;
//   s  the mean of |(p − c)·e| / a over them, p the bond's contact point at failure.
// A crack across the long axis cuts bonds that run along it (α near 2/3 for isotropic bond
// directions, cut in proportion to |n·m|, m the crack normal ∥ e); a crack that contains the
// axis cuts bonds that run across it (α near 0.4). Hence
//   α < 0.55                 → split        (longitudinal crack, the grain split lengthwise)
//   α ≥ 0.55 and s > 0.5     → end_chipping (a transverse crack in the outer halves: a tip off)
//   α ≥ 0.55 and s ≤ 0.5     → central      (a transverse crack near mid-length)
#include <cstdint>
#include <vector>

#include "comminute/core/vec3.hpp"

namespace comminute::bonds {

enum class BreakageMode : std::uint8_t { end_chipping = 1, central = 2, split = 3 };

const char* mode_name(BreakageMode m);

struct FailedBondGeometry {
  Vec3 position;   // m, contact point at failure
  Vec3 direction;  // unit, line of centres at failure
};

// The unit axis of largest spread of the points (about their centroid).
Vec3 long_axis(const std::vector<Vec3>& points);

BreakageMode classify_breakage(const std::vector<Vec3>& sub_sphere_centres, double radius,
                               const std::vector<FailedBondGeometry>& failed);

}  // namespace comminute::bonds
