#include "comminute/pbm/product_function.hpp"

#include <fmt/format.h>
#include <algorithm>

#include <boost/math/special_functions/beta.hpp>
#include <cmath>

#include "comminute/core/error.hpp"

namespace comminute::pbm {

namespace bm = boost::math;

namespace {
double ratio(double v, double y) {
  return std::clamp(v / y, 0.0, 1.0);
}
}  // namespace

ProductFunction::ProductFunction(double q, double nu) : q_(q), nu_(nu), r_(q * (nu - 1)) {
  if (!(q > 0 && nu > 1)) throw Error("ProductFunction: need q > 0 and nu > 1");
}

// Diemer & Olson (2002), generalised Beta θ(z): docs/models.md eq. B2.
double ProductFunction::theta(double z) const {
  if (z <= 0 || z >= 1) return 0.0;
  return nu_ * std::pow(z, q_ - 1) * std::pow(1 - z, r_ - 1) / bm::beta(q_, r_);
}

double ProductFunction::z50_number() const {
  return bm::ibeta_inv(q_, r_, 0.5);
}
double ProductFunction::z50_volume() const {
  return bm::ibeta_inv(q_ + 1, r_, 0.5);
}

// ∫_0^z ζθ(ζ) dζ = I_z(q+1, r) (zθ is the Beta(q+1, r) density).
std::string ProductFunction::summary() const {
  return fmt::format(
      "Diemer-Olson q = {:g}, nu = {:g}: z50 (number median) = {:.4g}, "
      "z50 (volume median) = {:.4g}",
      q_, nu_, z50_number(), z50_volume());
}

double ProductFunction::cumulative_mass(double v, double y) const {
  return bm::ibeta(q_ + 1, r_, ratio(v, y));
}

// ∫_0^z θ dζ = ν I_z(q, r).
std::optional<double> ProductFunction::cumulative_number(double v, double y) const {
  return nu_ * bm::ibeta(q_, r_, ratio(v, y));
}

namespace {
// Keys q (> 0) and nu (>= 2: at least binary breakage).
std::unique_ptr<BreakageFunction> make(const CaseTable& t, const ModelContext&) {
  const double q = t.number("q", Limits::positive());
  const double nu = t.number("nu", Limits::at_least(2.0));
  return std::make_unique<ProductFunction>(q, nu);
}
const bool registered = BreakageFunctionRegistry::add("diemer_olson", &make);
}  // namespace

}  // namespace comminute::pbm
