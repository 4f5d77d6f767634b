#include "comminute/breakage/progeny/t10_model.hpp"

#include <boost/math/special_functions/beta.hpp>
#include <cmath>

#include "comminute/core/error.hpp"
#include "comminute/core/math_policy.hpp"

namespace comminute::breakage {

T10Model::T10Model(const T10Parameters& p) : p_(p) {
  if (!(p.a > 0 && p.a <= 100) || !(p.b_prime > 0))
    throw Error("t10 model needs 0 < A <= 100 and b' > 0");
  for (std::size_t k = 0; k < 5; ++k)
    if (!(p.alpha[k] > 0) || !(p.beta[k] > 0)) throw Error("t_n model needs alpha_n, beta_n > 0");
}

double T10Model::t10(double specific_energy, double e50b) const {
  return p_.a * (1.0 - std::exp(-p_.b_prime * specific_energy / e50b));  // seed 002 eq. 16
}

std::array<double, 5> T10Model::tn(double t10) const {
  std::array<double, 5> out{};
  const double x = std::clamp(t10 / 100.0, 0.0, 1.0);
  for (std::size_t k = 0; k < 5; ++k)
    out[k] = 100.0 *
             boost::math::ibeta(p_.alpha[k], p_.beta[k], x, DoublePrecision());  // seed 002 eq. 17
  return out;
}

}  // namespace comminute::breakage
