#include "comminute/pbm/austin_breakage_function.hpp"

#include <algorithm>
#include <cmath>

#include "comminute/core/error.hpp"

namespace comminute::pbm {

AustinBreakageFunction::AustinBreakageFunction(Parameters p, double shape_factor)
    : p_(p), shape_factor_(shape_factor) {
  if (!(p.phi >= 0 && p.phi <= 1 && p.gamma > 0 && p.beta > 0 && p.reference_size > 0))
    throw Error("AustinBreakageFunction: need 0 <= phi <= 1, gamma, beta, reference size > 0");
}

// Austin, Klimpel & Luckie (1984), docs/models.md eq. B3: Φ_j = Φ (x_j/x_ref)^(−δ), capped at 1.
double AustinBreakageFunction::phi_of_parent(double parent_size) const {
  if (p_.delta == 0.0) return p_.phi;
  return std::min(1.0, p_.phi * std::pow(parent_size / p_.reference_size, -p_.delta));
}

// Austin, Klimpel & Luckie (1984), docs/models.md eq. B3: B = Φ (d/D)^γ + (1−Φ)(d/D)^β.
double AustinBreakageFunction::cumulative_mass(double v, double y) const {
  const double s = std::cbrt(std::clamp(v / y, 0.0, 1.0));
  const double phi = phi_of_parent(std::cbrt(y / shape_factor_));
  return phi * std::pow(s, p_.gamma) + (1 - phi) * std::pow(s, p_.beta);
}

namespace {
std::unique_ptr<BreakageFunction> make(const CaseTable& t, const ModelContext& ctx) {
  AustinBreakageFunction::Parameters p;
  p.phi = t.number("phi", Limits::unit_interval());
  p.gamma = t.number("gamma", Limits::positive());
  p.beta = t.number("beta", Limits::positive());
  p.delta = t.number("delta", Limits::any(), 0.0);
  p.reference_size = t.number("reference_size", Limits::positive(), 1e-3);
  return std::make_unique<AustinBreakageFunction>(p, ctx.grid.shape_factor());
}
const bool registered = BreakageFunctionRegistry::add("austin", &make);
}  // namespace

}  // namespace comminute::pbm
