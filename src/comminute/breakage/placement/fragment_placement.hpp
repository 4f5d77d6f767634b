#pragma once
// Placing fragments inside the parent sphere (docs/models.md eq. C4, the
// shrink-then-grow scheme). Fragments carry their final mass from the start (so momentum is exact
// and no mass is ever missing); their radius starts shrunk so that overlaps with siblings,
// neighbours and walls are at most eps min(r_i, r_j), and grows afterwards (FragmentGrowth, in the
// module).
#include <algorithm>
#include <functional>
#include <vector>

#include "comminute/core/rng.hpp"
#include "comminute/core/vec3.hpp"

namespace comminute::breakage {

struct Sphere {
  Vec3 x;        // m
  double r = 0;  // m
};

struct PlacementOptions {
  double overlap_ratio = 0.05;    // eps: largest overlap as a fraction of the smaller radius
  int attempts = 30;              // candidate centres tried per fragment (least overlap kept)
  double min_start_ratio = 0.05;  // a fragment starts at least this fraction of its radius
};

// Deepest overlap (m) of sphere (x, r) with the walls (<= 0 when clear); may be empty (no walls).
using WallOverlap = std::function<double(const Vec3& x, double r)>;

// Places fragments of final radii `radii` and masses `masses` (largest first) inside the parent
// sphere `parent`. Centres are drawn uniformly in the ball of radius R - r_i, the candidate with
// the least relative overlap with already placed siblings and with `neighbours` is kept; the set
// is then translated so that its mass centre is exactly the parent centre (angular momentum about
// any point stays exact). Returns centres and starting radii.
std::vector<Sphere> place_fragments(const Sphere& parent, const std::vector<double>& radii,
                                    const std::vector<double>& masses,
                                    const std::vector<Sphere>& neighbours, const WallOverlap& walls,
                                    const PlacementOptions& opt, Rng& rng);

// Largest radius (<= r_want) of a sphere at `x` whose overlap with sphere `other` is at most
// eps min(radius, other.r). (Inline: fragment growth calls it for every pair of a growing
// fragment, every step.)
inline double radius_allowed(const Vec3& x, double r_want, const Sphere& other, double eps) {
  const double d = norm(x - other.x);
  // overlap r + R - d <= eps min(r, R): with r <= R this is r <= (d - R)/(1 - eps), else
  // r <= d - R + eps R; take the branch consistent with the result.
  const double small = (d - other.r) / (1.0 - eps);
  const double r = small <= other.r ? small : d - other.r + eps * other.r;
  return std::min(r_want, r);
}

struct FragmentVelocities {
  std::vector<Vec3> v, w;  // m/s, rad/s
};

// How fragments inherit their parent's spin (docs/breakage.md, "Velocities").
enum class FragmentSpin {
  parent,           // rigid-body inheritance: w_i = w_p, v_i = v_p + w_p x (x_i - x_p)
  angular_momentum  // one w for all, keeping the parent's angular momentum (or its mass share)
};

// Velocities of fragments (centres x_i, masses m_i, moments of inertia I_i about their own
// centres) replacing a parent at x_p with velocity v_p, spin w_p, moment of inertia I_p and mass
// m_p: rigid-body motion v_i = v_p + w x (x_i - x_p), w_i = w, where
// - FragmentSpin::parent: w = w_p, each fragment keeps the velocity its material had in the parent
//   at the instant of fracture (no speed from nowhere; the angular momentum changes by
//   (J_orbit + sum I_i - I_p) w_p as the packed spheres' inertia differs from the parent's);
// - FragmentSpin::angular_momentum: w solves (J_orbit + sum I_i) w = (sum m_i / m_p) I_p w_p, so
//   that the fragments keep exactly the parent's angular momentum when they carry all its mass,
//   and the share of it that goes with their mass when fines booked as mass take the rest (as
//   those take their share of the linear momentum; without that share a family that kept a third
//   of the mass would spin three times as fast); the share is 1 when sum m_i is m_p up to
//   rounding. The fragments spin up by I_p / (J_orbit + sum I_i) (1.5 for three fragments).
// Plus an optional radial release dv_i = c (n_i - <n>) (n_i unit direction from the parent
// centre, <n> its mass mean) with sum m_i dv_i = 0 and sum m_i |dv_i|^2 / 2 = released (J) — or
// less when one off-centre fragment dominates the family (see the .cpp: speeds stay below
// 2 sqrt(8 released/M)). Linear momentum sum m_i v_i = (sum m_i) v_p holds to rounding (the
// residual is removed).
FragmentVelocities fragment_velocities(const Vec3& x_p, const Vec3& v_p, const Vec3& w_p,
                                       double inertia_p, double mass_p, const std::vector<Vec3>& x,
                                       const std::vector<double>& m,
                                       const std::vector<double>& inertia, double released,
                                       FragmentSpin spin);

}  // namespace comminute::breakage
