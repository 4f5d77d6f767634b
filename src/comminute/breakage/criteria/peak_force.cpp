#include "comminute/breakage/criteria/peak_force.hpp"

#include <cmath>
#include <limits>
#include <string>

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

void CompositionPeakForce::attach(ParticleStore& p) {
  PeakForce::attach(p);
  composition_.clear();
  for (std::size_t k = 0; k < relative_strength_.size(); ++k)
    composition_.push_back(p.add_field("composition." + std::to_string(k), k == 0 ? 1.0 : 0.0));
}

double CompositionPeakForce::critical_force(const ParticleStore& p, std::size_t i, double d) const {
  double s = 0;  // seed 000 eq. 2: sum_k C_k f_rel,k
  for (std::size_t k = 0; k < composition_.size(); ++k)
    s += p.field(composition_[k])[i] * relative_strength_[k];
  return law_(d) * s;
}

double CompositionPeakForce::nominal_critical_force(double d) const {
  return law_(d) * relative_strength_[0];  // default composition: all phase 0
}

namespace {
CriticalForceLaw read_law(const ParameterSource& s) {
  const double inf = std::numeric_limits<double>::infinity();
  return {s.number("a", 0, inf, false, ParameterSource::required),
          s.number("b", -inf, inf, false, ParameterSource::required),
          s.number("c", -inf, inf, false, 0.0)};
}
double read_sigma(const ParameterSource& s) {
  return s.number("factor_sigma", 0, std::numeric_limits<double>::infinity(), false, 0.0);
}
std::unique_ptr<BreakageCriterion> make_peak(const ParameterSource& s, const Material&) {
  return std::make_unique<PeakForce>(read_law(s), read_sigma(s));
}
std::unique_ptr<BreakageCriterion> make_composition(const ParameterSource& s, const Material&) {
  auto law = read_law(s);
  auto sigma = read_sigma(s);
  auto f_rel = s.numbers("relative_strength", 0, std::numeric_limits<double>::infinity());
  if (f_rel.empty()) s.fail("relative_strength", "needs one value per phase");
  return std::make_unique<CompositionPeakForce>(law, sigma, f_rel);
}
const bool registered_peak = CriterionRegistry::add("peak_force", &make_peak);
const bool registered_composition =
    CriterionRegistry::add("composition_peak_force", &make_composition);
}  // namespace

}  // namespace comminute::breakage
