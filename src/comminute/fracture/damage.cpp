#include "comminute/fracture/damage.hpp"

#include <cmath>

#include "comminute/core/error.hpp"
#include "comminute/fracture/renamed_keys.hpp"

namespace comminute::fracture {

namespace {

// Tavares, KONA Powder Part. J. 34 (2017) 106, eq. 20 (docs/models.md eq. D1): the one root in
// (0, 1) by bisection (h(D) = D - rhs(D) rises strictly from h(0) < 0 to h(1) = 1).
double with_factor(double gamma, double r) {
  const double expo = 2.0 * gamma / 5.0;
  double lo = 0.0, hi = 1.0;
  while (hi - lo > 1e-15) {
    const double mid = 0.5 * (lo + hi);
    const double rhs =
        std::pow(2.0 * gamma * (1.0 - mid) / (2.0 * gamma - 5.0 * mid + 5.0) * r, expo);
    (mid < rhs ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Tavares & King, Powder Technol. 123 (2002) 138 (docs/models.md eq. D1'): smallest root by
// fixed-point iteration from D = 0.
double without_factor(double gamma, double r) {
  const double expo = 2.0 * gamma / 5.0;
  double d = 0.0;
  for (int it = 0; it < 1000000; ++it) {
    const double next = std::pow(2.0 * gamma / (2.0 * gamma - 5.0 * d + 5.0) * r, expo);
    if (std::abs(next - d) <= 1e-15 * (1.0 + next)) return next;
    d = next;
  }
  return d;
}

}  // namespace

double tavares_king_damage(double gamma, double r, DamageForm form) {
  if (!(gamma > 0) || !(r >= 0) || !(r < 1))
    throw Error("damage equation needs gamma > 0 and 0 <= eE/E < 1");
  if (r == 0) return 0.0;
  return form == DamageForm::one_minus_d ? with_factor(gamma, r) : without_factor(gamma, r);
}

DamageLaw read_damage_law(const CaseTable& t) {
  reject_renamed_keys(t, {{"gamma", "damage_gamma"}});
  DamageLaw law;
  law.gamma = t.number("damage_gamma", Limits::positive(), 5.0);
  const std::string form = t.choice("damage_form", {"one_minus_d", "no_factor"}, "one_minus_d");
  law.form = form == "one_minus_d" ? DamageForm::one_minus_d : DamageForm::no_factor;
  return law;
}

}  // namespace comminute::fracture
