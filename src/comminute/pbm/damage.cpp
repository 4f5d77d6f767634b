#include "comminute/pbm/damage.hpp"

#include <algorithm>
#include <cmath>

namespace comminute::pbm {

// Tavares & King (2002): D = [2γ/(2γ − 5D + 5) r]^(2γ/5).
double damage(double gamma, double r) {
  if (r <= 0) return 0.0;
  if (r >= 1) return 1.0;  // stressed at or above its fracture energy: broken, not damaged
  double d = 0;
  for (int it = 0; it < 10000; ++it) {
    const double next = std::pow(2 * gamma / (2 * gamma - 5 * d + 5) * r, 2 * gamma / 5);
    if (!(next < 1)) return 1.0;  // no root below 1: the particle is broken through
    if (std::abs(next - d) <= 1e-15 * std::max(1.0, next)) return next;
    d = next;
  }
  return d;
}

}  // namespace comminute::pbm
