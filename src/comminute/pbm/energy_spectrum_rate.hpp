#pragma once
// Breakage rates of a ball mill from its collision energy spectrum (docs/models.md eq. S5):
//   S_i = (1/H) Σ_k λ_k · m*_i · P_i(e_ik),   e_ik = η E_k / m*_i
// H the powder hold-up (kg), m*_i the powder mass stressed per collision (kg), η the share of the
// collision energy the powder absorbs, P_i the fraction of stressed class-i material that breaks
// at mass-specific energy e. Two rates of this code use the skeleton; both are this code's
// variants (their names say so), not the equations of the papers they stand for:
//   tuzcu_rajamani_variant  P = 1 − exp(−f_mat·x·(e − E_min(x))⁺), Vogel–Peukert for one impact,
//                           standing for the UFLC bed-impact data of Tuzcu & Rajamani (2011);
//                           the paper's E_k weighting is not implemented
//                                                              (tuzcu_rajamani_variant_rate.cpp)
//   datta_rajamani_variant  P = F_i(e), the single-particle fracture-energy distribution,
//                           standing for the drop-weight data of Datta & Rajamani (2002); the
//                           paper's broken-mass function and energy-dependent b_ij(E_k) are not
//                           implemented                        (datta_rajamani_variant_rate.cpp)
// m* is a constant bed mass per collision for both. Capece et al.'s rate is its own equation
// (capece_rate.hpp).
#include <memory>

#include "comminute/fracture/fracture_energy_model.hpp"
#include "comminute/fracture/vogel_peukert.hpp"
#include "comminute/pbm/collision_spectrum.hpp"
#include "comminute/pbm/selection_function.hpp"

namespace comminute::pbm {

// P(e, d): fraction of stressed material of size d broken at specific energy e (J/kg).
class BreakageProbability {
 public:
  virtual ~BreakageProbability() = default;
  virtual double operator()(double energy, double size) const = 0;
};

// Vogel & Peukert (docs/models.md eq. C3) for one impact: P = 1 − exp[−f_mat x (e − xE_min/x)⁺].
class VogelPeukertProbability : public BreakageProbability {
 public:
  // f_mat (kg/(J·m)), threshold_product x·E_min (J·m/kg).
  VogelPeukertProbability(double f_mat, double threshold_product) : m_{f_mat, threshold_product} {}
  explicit VogelPeukertProbability(const fracture::VogelPeukertModel& m) : m_(m) {}
  double operator()(double energy, double size) const override {
    return m_.probability(size, energy - m_.threshold(size));
  }

 private:
  fracture::VogelPeukertModel m_;
};

class FractureEnergyProbability : public BreakageProbability {
 public:
  explicit FractureEnergyProbability(fracture::FractureEnergyModel m) : m_(m) {}
  double operator()(double energy, double size) const override { return m_.cdf(energy, size); }

 private:
  fracture::FractureEnergyModel m_;
};

class EnergySpectrumRate : public SelectionFunction {
 public:
  EnergySpectrumRate(CollisionSpectrum spectrum, double holdup, double captured_mass,
                     double energy_share, std::unique_ptr<BreakageProbability> probability);
  double rate(double size, double volume) const override;

 private:
  CollisionSpectrum spectrum_;
  double holdup_, captured_, share_;
  std::unique_ptr<BreakageProbability> p_;
};

// The skeleton's keys (spectrum_file, holdup, captured_mass, energy_share) with the model's P.
std::unique_ptr<SelectionFunction> read_energy_spectrum_rate(
    const CaseTable& t, std::unique_ptr<BreakageProbability> probability);
// The skeleton with the Vogel–Peukert P (keys f_mat, threshold_product).
std::unique_ptr<SelectionFunction> read_vogel_peukert_rate(const CaseTable& t);

}  // namespace comminute::pbm
