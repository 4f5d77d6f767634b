#include "comminute/fracture/vogel_peukert.hpp"

#include <algorithm>
#include <cmath>

#include "comminute/fracture/renamed_keys.hpp"

namespace comminute::fracture {

// Vogel & Peukert (2003), docs/models.md eq. C3.
double VogelPeukertModel::exponent(double d, double excess) const {
  return f_mat * d * std::max(0.0, excess);
}

double VogelPeukertModel::probability(double d, double excess) const {
  return 1.0 - std::exp(-exponent(d, excess));
}

VogelPeukertModel read_vogel_peukert(const CaseTable& t) {
  reject_renamed_keys(t, {{"x_e_min", "threshold_product"}});
  VogelPeukertModel m;
  m.f_mat = t.number("f_mat", Limits::positive());
  m.threshold_product = t.number("threshold_product", Limits::non_negative(), 0.0);
  return m;
}

}  // namespace comminute::fracture
