#pragma once
// Stress-based breakage rate (carbon-black mixer study; docs/models.md eq. S2):
//   b(d) = λ ∫_{σcrit(d)}^{σmax} ṅ(σ) dσ
// with ṅ(σ) the specific contact frequency (1/(s·Pa)) per stress level, tabulated (e.g. from the
// DEM's grid statistics) and taken piecewise linear; σmax = the largest tabulated stress.
#include <memory>
#include <vector>

#include "comminute/pbm/critical_stress.hpp"
#include "comminute/pbm/selection_function.hpp"

namespace comminute::pbm {

// ṅ(σ) at increasing stresses; integral from a stress to the end of the table.
class ContactFrequencySpectrum {
 public:
  ContactFrequencySpectrum(std::vector<double> stress, std::vector<double> frequency);
  double integral_above(double sigma) const;  // ∫_σ^σmax ṅ dσ (1/s)

 private:
  std::vector<double> s_, n_, tail_;  // tail_[i] = ∫_{s_i}^{σmax}
};

class StressRate : public SelectionFunction {
 public:
  StressRate(double lambda, ContactFrequencySpectrum spectrum,
             std::unique_ptr<CriticalStress> strength)
      : lambda_(lambda), spectrum_(std::move(spectrum)), strength_(std::move(strength)) {}
  double rate(double size, double volume) const override;

 private:
  double lambda_;
  ContactFrequencySpectrum spectrum_;
  std::unique_ptr<CriticalStress> strength_;
};

}  // namespace comminute::pbm
