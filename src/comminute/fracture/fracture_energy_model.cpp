#include "comminute/fracture/fracture_energy_model.hpp"

#include "comminute/fracture/renamed_keys.hpp"

namespace comminute::fracture {

FractureEnergyDistribution FractureEnergyModel::distribution(double d) const {
  return {size_effect.e50(d), sigma, emax_ratio};
}

FractureEnergyModel read_fracture_energy_model(const CaseTable& t) {
  reject_renamed_keys(t, {{"max_ratio", "emax_ratio"}});
  const double inf = std::numeric_limits<double>::infinity();
  FractureEnergyModel m;
  m.size_effect = read_size_effect(t);
  m.sigma = t.number("sigma", Limits::positive());
  m.emax_ratio = t.number("emax_ratio", Limits{1.0, inf, true, false}, inf);
  return m;
}

}  // namespace comminute::fracture
