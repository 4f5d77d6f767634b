#include "comminute/fracture/damage.hpp"

#include <cmath>

#include "comminute/core/error.hpp"
#include "comminute/fracture/renamed_keys.hpp"

namespace comminute::fracture {

// Tavares & King (2002): docs/models.md eq. D1, smallest root by fixed-point iteration.
double tavares_king_damage(double gamma, double r) {
  if (!(gamma > 0) || !(r >= 0) || !(r < 1))
    throw Error("damage equation needs gamma > 0 and 0 <= eE/E < 1");
  if (r == 0) return 0.0;
  const double expo = 2.0 * gamma / 5.0;
  double d = 0.0;
  for (int it = 0; it < 1000000; ++it) {
    const double next = std::pow(2.0 * gamma / (2.0 * gamma - 5.0 * d + 5.0) * r, expo);
    if (std::abs(next - d) <= 1e-15 * (1.0 + next)) return next;
    d = next;
  }
  return d;
}

double read_damage_gamma(const CaseTable& t) {
  reject_renamed_keys(t, {{"gamma", "damage_gamma"}});
  return t.number("damage_gamma", Limits::positive(), 5.0);
}

}  // namespace comminute::fracture
