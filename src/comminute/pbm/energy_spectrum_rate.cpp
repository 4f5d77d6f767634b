#include "comminute/pbm/energy_spectrum_rate.hpp"

#include <algorithm>
#include <cmath>

namespace comminute::pbm {

// Vogel & Peukert (2003): P = 1 − exp[−f_mat x k (W_m − W_m,min)], k = 1 impact.
double VogelPeukertProbability::operator()(double energy, double size) const {
  const double excess = std::max(0.0, energy - x_e_min_ / size);
  const double a = f_mat_ * size * excess;
  return linearised_ ? std::min(1.0, a) : 1 - std::exp(-a);
}

EnergySpectrumRate::EnergySpectrumRate(CollisionSpectrum spectrum, double holdup,
                                       double captured_mass, double energy_share,
                                       std::unique_ptr<BreakageProbability> probability)
    : spectrum_(std::move(spectrum)),
      holdup_(holdup),
      captured_(captured_mass),
      share_(energy_share),
      p_(std::move(probability)) {}

// Notes §5: S_i = (1/H) Σ_k λ_k m*_i P_i(η E_k/m*_i).
double EnergySpectrumRate::rate(double size, double /*volume*/) const {
  double s = 0;
  for (std::size_t k = 0; k < spectrum_.energy.size(); ++k)
    s += spectrum_.frequency[k] * captured_ * (*p_)(share_ * spectrum_.energy[k] / captured_, size);
  return s / holdup_;
}

}  // namespace comminute::pbm
