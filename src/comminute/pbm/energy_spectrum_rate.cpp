#include "comminute/pbm/energy_spectrum_rate.hpp"

namespace comminute::pbm {

EnergySpectrumRate::EnergySpectrumRate(CollisionSpectrum spectrum, double holdup,
                                       double captured_mass, double energy_share,
                                       std::unique_ptr<BreakageProbability> probability)
    : spectrum_(std::move(spectrum)),
      holdup_(holdup),
      captured_(captured_mass),
      share_(energy_share),
      p_(std::move(probability)) {}

// docs/models.md eq. S5: S_i = (1/H) Σ_k λ_k m*_i P_i(η E_k/m*_i).
double EnergySpectrumRate::rate(double size, double /*volume*/) const {
  double s = 0;
  for (std::size_t k = 0; k < spectrum_.energy.size(); ++k)
    s += spectrum_.frequency[k] * captured_ * (*p_)(share_ * spectrum_.energy[k] / captured_, size);
  return s / holdup_;
}

std::unique_ptr<SelectionFunction> read_energy_spectrum_rate(
    const CaseTable& t, std::unique_ptr<BreakageProbability> probability) {
  return std::make_unique<EnergySpectrumRate>(
      read_collision_spectrum(t, "spectrum_file"), t.number("holdup", Limits::positive()),
      t.number("captured_mass", Limits::positive()),
      t.number("energy_share", {0, 1, true, false}, 1.0), std::move(probability));
}

std::unique_ptr<SelectionFunction> read_vogel_peukert_rate(const CaseTable& t) {
  return read_energy_spectrum_rate(
      t, std::make_unique<VogelPeukertProbability>(fracture::read_vogel_peukert(t)));
}

}  // namespace comminute::pbm
