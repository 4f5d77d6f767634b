#pragma once
// Breakage rates of a ball mill from its collision energy spectrum (MODELS-pbm-notes.md §5):
//   S_i = (1/H) Σ_k λ_k · m*_i · P_i(e_ik),   e_ik = η E_k / m*_i
// H the powder hold-up (kg), m*_i the powder mass stressed per collision (kg), η the share of the
// collision energy the powder absorbs, P_i the fraction of stressed class-i material that breaks
// at mass-specific energy e. The published models differ in m* and P; the forms coded here:
//   capece          P = min(1, f_mat·x·(e − E_min(x))⁺), E_min(x) = (x·E_min)/x — Vogel–Peukert
//                   linearised for one impact (Capece, Bilgili & Davé 2014)
//   tuzcu_rajamani  P = 1 − exp(−f_mat·x·(e − E_min(x))⁺) — bed breakage probability in
//                   Vogel–Peukert form standing for the UFLC bed-impact data of Tuzcu & Rajamani
//                   (2011) [structure per the notes; the form is this code's choice]
//   datta_rajamani  P = F_i(e), the single-particle fracture-energy distribution standing for the
//                   drop-weight data of Datta & Rajamani (2002) [same caveat]
// m* is a constant bed mass per collision for all three.
#include <memory>

#include "comminute/pbm/collision_spectrum.hpp"
#include "comminute/pbm/fracture_energy.hpp"
#include "comminute/pbm/selection_function.hpp"

namespace comminute::pbm {

// P(e, d): fraction of stressed material of size d broken at specific energy e (J/kg).
class BreakageProbability {
 public:
  virtual ~BreakageProbability() = default;
  virtual double operator()(double energy, double size) const = 0;
};

// Vogel & Peukert (Powder Technol. 129 (2003) 101): P = 1 − exp[−f_mat x (e − xE_min/x)⁺];
// `linearised` gives Capece's single-impact form min(1, f_mat x (e − xE_min/x)⁺).
class VogelPeukertProbability : public BreakageProbability {
 public:
  VogelPeukertProbability(double f_mat, double x_e_min, bool linearised)
      : f_mat_(f_mat), x_e_min_(x_e_min), linearised_(linearised) {}
  double operator()(double energy, double size) const override;

 private:
  double f_mat_, x_e_min_;  // kg/(J·m), J·m/kg
  bool linearised_;
};

class FractureEnergyProbability : public BreakageProbability {
 public:
  explicit FractureEnergyProbability(FractureEnergyModel m) : m_(m) {}
  double operator()(double energy, double size) const override { return m_.cdf(energy, size); }

 private:
  FractureEnergyModel m_;
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

}  // namespace comminute::pbm
