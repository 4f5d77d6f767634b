#include "comminute/fracture/size_effect.hpp"

#include <cmath>

#include "comminute/fracture/renamed_keys.hpp"

namespace comminute::fracture {

// Tavares & King (1998): docs/models.md eq. F3.
double SizeEffect::e50(double d) const {
  if (d0 == 0) return e_inf * partition;
  return e_inf * partition * (1.0 + std::pow(d0 / d, phi));
}

SizeEffect read_size_effect(const CaseTable& t) {
  reject_renamed_keys(t, {{"e50_inf", "e_inf"}});
  SizeEffect s;
  s.e_inf = t.number("e_inf", Limits::positive());
  s.d0 = t.number("d0", Limits::non_negative(), 0.0);
  s.phi = t.number("phi", Limits::non_negative(), 1.0);
  return s;
}

}  // namespace comminute::fracture
