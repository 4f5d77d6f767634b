#include "comminute/geometry/single_toggle.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "comminute/geometry/wall_group.hpp"

namespace comminute {

namespace {

// In the x-z plane: v turned a quarter counter-clockwise, and the scalar cross product.
Vec3 quarter_turn(const Vec3& v) {
  return {-v.z, 0, v.x};
}
double cross2(const Vec3& a, const Vec3& b) {
  return a.x * b.z - a.z * b.x;
}

// The point at distance r1 from c1 and r2 from c2 on the side `side` of the line c1 -> c2
// (the sign of cross2(p - c1, c2 - c1)); none when the circles do not meet.
std::optional<Vec3> circles_meet(const Vec3& c1, double r1, const Vec3& c2, double r2,
                                 double side) {
  const Vec3 d = c2 - c1;
  const double len = norm(d);
  const double a = (r1 * r1 - r2 * r2 + len * len) / (2 * len);
  const double h2 = r1 * r1 - a * a;
  if (!(len > 0) || h2 < 0) return std::nullopt;
  const Vec3 u = d / len;
  // cross2(quarter_turn(u), u) = -1: the offset -side h J(u) lies on side `side`
  return c1 + a * u - (side * std::sqrt(h2)) * quarter_turn(u);
}

double sign(double x) {
  return x < 0 ? -1.0 : 1.0;
}

}  // namespace

Vec3 SingleToggleLinkage::pin(double theta) const {
  return shaft + eccentricity * Vec3{std::cos(theta), 0, std::sin(theta)};
}

Vec3 SingleToggleLinkage::toggle_end(double theta) const {
  // position analysis of the four-bar: B on the circles about A (l3) and T (l4), on the branch of
  // the start (Norton, Design of Machinery, 5th ed. 2012, sec. 4.5, eq. 4.10 in vector form)
  const Vec3 a = pin(theta);
  const auto b = circles_meet(a, jaw_length, toggle_seat, toggle_length, assembly);
  // a Grashof crank-rocker (checked when built) closes at every crank angle
  return b ? *b : a;
}

double SingleToggleLinkage::jaw_angle(double theta) const {
  const Vec3 d = toggle_end(theta) - pin(theta);
  return std::atan2(d.z, d.x);
}

double SingleToggleLinkage::jaw_angular_speed(double theta, double omega) const {
  // v_B = v_A + w3 J(B - A) is perpendicular to the toggle B - T (Norton 2012, sec. 6.7,
  // eq. 6.18a in vector form): w3 = -v_A . (B - T) / (J(B - A) . (B - T))
  const Vec3 a = pin(theta), b = toggle_end(theta);
  const Vec3 va = omega * eccentricity * Vec3{-std::sin(theta), 0, std::cos(theta)};
  return -dot(va, b - toggle_seat) / dot(quarter_turn(b - a), b - toggle_seat);
}

SingleToggleLinkage single_toggle_linkage(double height, double gape, double closed_side_setting,
                                          double jaw_throw, double toggle_length,
                                          double toggle_angle) {
  SingleToggleLinkage k;
  const Vec3 a0{gape, 0, height}, b0{closed_side_setting, 0, 0};
  k.hang_start = a0;
  k.toggle_start = b0;
  k.jaw_length = norm(a0 - b0);
  k.toggle_length = toggle_length;
  if (!(toggle_length > 0)) throw GeometryError("toggle_length", "must be > 0");
  if (!(std::abs(toggle_angle) < std::numbers::pi / 2))
    throw GeometryError("toggle_angle", "must lie strictly between -90 and 90 degrees");
  k.toggle_seat = b0 + toggle_length * Vec3{std::cos(toggle_angle), 0, -std::sin(toggle_angle)};
  k.assembly = sign(cross2(b0 - a0, k.toggle_seat - a0));
  // the direction B leaves its closed side in: along its circle about T, towards larger x
  Vec3 t = quarter_turn(b0 - k.toggle_seat) / toggle_length;
  if (t.x < 0) t = -1.0 * t;
  const Vec3 down = (b0 - a0) / k.jaw_length;  // along the jaw, from A to B
  const double lean = dot(down, t);
  if (!(t.x > 1e-3) || !(std::abs(lean) > 1e-3))
    throw GeometryError("toggle_angle",
                        "the jaw's bottom edge would move (nearly) along the fixed jaw: choose a "
                        "toggle that is not (nearly) horizontal nor in line with the jaw");
  // lean < 0: opening shortens O-B, so the closed side has crank and jaw extended in line (O, A, B
  // in this order, |OB| = l3 + e); lean > 0: folded (A, O, B, |OB| = l3 - e)
  const double fold = lean < 0 ? 1.0 : -1.0;
  const auto place = [&](double e) {
    k.eccentricity = e;
    k.shaft = a0 - (fold * e) * down;
    const Vec3 to_pin = a0 - k.shaft;
    k.start_angle = std::atan2(to_pin.z, to_pin.x);
  };
  // the open side: the other limit position, |OB| = l3 -/+ e, on the start's side of O-T
  const auto stroke = [&](double e) -> std::optional<double> {
    place(e);
    const double side = sign(cross2(b0 - k.shaft, k.toggle_seat - k.shaft));
    const auto b =
        circles_meet(k.shaft, k.jaw_length - fold * e, k.toggle_seat, toggle_length, side);
    if (!b) return std::nullopt;
    return b->x - closed_side_setting;
  };
  // the stroke grows with e from 0: bracket the throw, then bisect to round-off
  const double longest = std::max({k.jaw_length, toggle_length, norm(k.toggle_seat - a0)});
  double lo = 0, hi = jaw_throw;
  for (;;) {
    const auto s = stroke(hi);
    if (s && *s >= jaw_throw) break;
    if (!s || 2 * hi > 0.25 * longest)
      throw GeometryError(
          "throw", fmt::format("no eccentric up to {:.6g} m gives this linkage a throw of {:.6g} m "
                               "(toggle_length {:.6g} m, toggle_angle {:.6g} rad)",
                               hi, jaw_throw, toggle_length, toggle_angle));
    lo = hi;
    hi *= 2;
  }
  for (int i = 0; i < 200 && hi - lo > 1e-16 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    const auto s = stroke(mid);
    (s && *s < jaw_throw ? lo : hi) = mid;
  }
  place(hi);
  // Grashof: the crank turns fully (a crank-rocker) when it is the shortest link and
  // shortest + longest <= the sum of the other two (Norton 2012, sec. 2.12, eq. 2.8)
  const double ground = norm(k.toggle_seat - k.shaft);
  const double links[] = {k.eccentricity, k.jaw_length, toggle_length, ground};
  const double longest_link = *std::max_element(std::begin(links), std::end(links));
  const double sum = links[0] + links[1] + links[2] + links[3];
  if (!(k.eccentricity < std::min({k.jaw_length, toggle_length, ground})) ||
      !(k.eccentricity + longest_link <= sum - k.eccentricity - longest_link))
    throw GeometryError("toggle_length",
                        fmt::format("the linkage (eccentric {:.6g} m, jaw {:.6g} m, toggle {:.6g} "
                                    "m, frame {:.6g} m) is not a crank-rocker",
                                    k.eccentricity, k.jaw_length, toggle_length, ground));
  return k;
}

}  // namespace comminute
