#include "comminute/pbm/power_law_rate.hpp"

#include <cmath>
#include <memory>

namespace comminute::pbm {

// Austin, Shoji & Luckie (1976), docs/models.md eq. S1: S_i = A (x_i/x_0)^α Q_i, Q_i = 1/(1 +
// (x_i/μ)^Λ).
double PowerLawRate::rate(double size, double volume) const {
  const double x = p_.variable == GridCoordinate::size ? size : volume;
  double s = p_.k * std::pow(x / p_.reference, p_.alpha);
  if (p_.mu) s /= 1 + std::pow(size / *p_.mu, p_.lambda);
  return s;
}

namespace {
std::unique_ptr<SelectionFunction> make(const CaseTable& t, const ModelContext&) {
  PowerLawRate::Parameters p;
  p.k = t.number("k", Limits::non_negative());
  p.alpha = t.number("alpha");
  p.variable = t.choice("variable", {"size", "volume"}) == "size" ? GridCoordinate::size
                                                                  : GridCoordinate::volume;
  p.reference = t.number("reference", Limits::positive(), 1.0);
  if (t.has("mu")) p.mu = t.number("mu", Limits::positive());
  p.lambda = t.number("lambda", Limits::positive(), 2.0);
  return std::make_unique<PowerLawRate>(p);
}
const bool registered = SelectionFunctionRegistry::add("power_law", &make);
}  // namespace

}  // namespace comminute::pbm
