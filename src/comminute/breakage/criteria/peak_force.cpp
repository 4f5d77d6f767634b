#include "comminute/breakage/criteria/peak_force.hpp"

#include <cmath>

namespace comminute::breakage {

double CriticalForceLaw::operator()(double x) const {
  return a * std::pow(x, b) + c;
}

void PeakForce::attach(ParticleStore& p) {
  factor_ = p.add_field("peak_force.factor", 1.0);  // per-particle random strength factor
}

void PeakForce::initialize(ParticleStore& p, std::size_t i, double, Rng& rng) const {
  p.field(factor_)[i] = factor_sigma_ > 0 ? std::exp(factor_sigma_ * rng.normal()) : 1.0;
}

double PeakForce::critical_force(const ParticleStore&, std::size_t, double d) const {
  return law_(d);
}

double PeakForce::strength(const ParticleStore& p, std::size_t i, double d) const {
  return critical_force(p, i, d) * p.field(factor_)[i];
}

bool PeakForce::breaks(const ParticleStore& p, std::size_t i, double d,
                       const StressingEvent& e) const {
  return e.peak_force >= strength(p, i, d);
}

double PeakForce::probability(double d, const StressingEvent& e) const {
  const double f = nominal_critical_force(d);
  if (factor_sigma_ <= 0) return e.peak_force >= f ? 1.0 : 0.0;
  if (e.peak_force <= 0) return 0.0;
  // factor = exp(sigma z): P(F >= f factor) = Phi(ln(F/f)/sigma).
  return 0.5 * std::erfc(-std::log(e.peak_force / f) / (factor_sigma_ * std::sqrt(2.0)));
}

CriticalForceLaw read_critical_force_law(const CaseTable& t) {
  return {t.number("a", Limits::non_negative()), t.number("b", Limits::any()),
          t.number("c", Limits::any(), 0.0)};
}

double read_factor_sigma(const CaseTable& t) {
  return t.number("factor_sigma", Limits::non_negative(), 0.0);
}

namespace {
std::unique_ptr<BreakageCriterion> make_peak(const CaseTable& t, const Material&) {
  return std::make_unique<PeakForce>(read_critical_force_law(t), read_factor_sigma(t));
}
const bool registered_peak = CriterionRegistry::add("peak_force", &make_peak);
}  // namespace

}  // namespace comminute::breakage
