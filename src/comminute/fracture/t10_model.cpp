#include "comminute/fracture/t10_model.hpp"

#include <algorithm>
#include <boost/math/special_functions/beta.hpp>
#include <cmath>
#include <string>

#include "comminute/core/error.hpp"
#include "comminute/core/math_policy.hpp"
#include "comminute/fracture/renamed_keys.hpp"

namespace comminute::fracture {

T10Model::T10Model(const T10Parameters& p) : p_(p) {
  if (!(p.a > 0 && p.a <= 100) || !(p.b_prime > 0))
    throw Error("t10 model needs 0 < A <= 100 and b' > 0");
  for (std::size_t k = 0; k < 5; ++k)
    if (!(p.alpha[k] > 0) || !(p.beta[k] > 0)) throw Error("t_n model needs alpha_n, beta_n > 0");
}

// Tavares & de Carvalho (2009): docs/models.md eq. P1.
double T10Model::t10(double specific_energy, double e50) const {
  return p_.a * (1.0 - std::exp(-p_.b_prime * specific_energy / e50));
}

// UFRJ incomplete-beta t_n family: docs/models.md eq. P2.
std::array<double, 5> T10Model::tn(double t10) const {
  std::array<double, 5> out{};
  const double x = std::clamp(t10 / 100.0, 0.0, 1.0);
  for (std::size_t k = 0; k < 5; ++k)
    out[k] = 100.0 * boost::math::ibeta(p_.alpha[k], p_.beta[k], x, DoublePrecision());
  return out;
}

namespace {
std::array<double, 5> five(const CaseTable& t, const char* key) {
  const auto v = t.numbers(key, Limits::positive());
  if (v.size() != 5)
    t.fail(key, "needs 5 values, for n = 2, 4, 25, 50, 75 (got " + std::to_string(v.size()) + ")");
  return {v[0], v[1], v[2], v[3], v[4]};
}
}  // namespace

T10Model read_t10_model(const CaseTable& t) {
  reject_renamed_keys(t, {{"b", "b_prime"}});
  T10Parameters p;
  p.a = t.number("A", Limits{0.0, 100.0, true, false});
  p.b_prime = t.number("b_prime", Limits::positive());
  p.alpha = five(t, "alpha");
  p.beta = five(t, "beta");
  return T10Model(p);  // every value is in range: the constructor cannot throw
}

}  // namespace comminute::fracture
