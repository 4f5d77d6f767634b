#pragma once
// The "capece" breakage rate (Capece, Bilgili & Davé, AIChE J. 60 (2014) 2404; docs/models.md
// eq. S6): the specific breakage rate parameter of a ball mill from the DEM distribution of
// mass-specific impact energies and the Vogel–Peukert material constants,
//   S_i = f_mat x_i ω Σ_k p_k (E_m,k − (x E_m,min)/x_i)⁺
// f_mat (kg/(J·m)) and x·E_m,min (J·m/kg) of Vogel & Peukert (Powder Technol. 129 (2003) 101),
// ω (1/s) the mean impact frequency per particle, p_k the probability of the mass-specific impact
// energy E_m,k (J/kg), Σ_k p_k = 1. The sum is linear in the excess energy (the single-impact
// linearisation of Vogel–Peukert): no cap at P = 1 is applied, as the paper applies none.
#include <vector>

#include "comminute/fracture/vogel_peukert.hpp"
#include "comminute/pbm/selection_function.hpp"

namespace comminute::pbm {

// The DEM's distribution of mass-specific impact energies: E_m,k (J/kg) and p_k (Σ p_k = 1).
struct SpecificEnergyDistribution {
  std::vector<double> energy;       // J/kg
  std::vector<double> probability;  // –
};

// The CSV named by `key` of `t`: columns specific_energy_J_per_kg (≥ 0) and probability (≥ 0,
// summing to 1 within 1e−6). Errors name the file, the line and the key.
SpecificEnergyDistribution read_specific_energy_distribution(const CaseTable& t,
                                                             const std::string& key);

class CapeceRate : public SelectionFunction {
 public:
  CapeceRate(fracture::VogelPeukertModel material, double impact_frequency,
             SpecificEnergyDistribution impacts)
      : material_(material), omega_(impact_frequency), impacts_(std::move(impacts)) {}
  double rate(double size, double volume) const override;

 private:
  fracture::VogelPeukertModel material_;
  double omega_;  // 1/s
  SpecificEnergyDistribution impacts_;
};

}  // namespace comminute::pbm
