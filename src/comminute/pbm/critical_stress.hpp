#pragma once
// Size-dependent strength of a particle (Pa) for the stress-based rate:
//   power law   σ_crit = σ0 (d/d_ref)^(−1/m)
//   σ50 model   σ50 = σ∞ (1 + x0/(d − x_p))^φ, unbreakable (infinite strength) for d ≤ x_p
// (carbon-black mixer study, seed 003).
namespace comminute::pbm {

class CriticalStress {
 public:
  virtual ~CriticalStress() = default;
  virtual double of_size(double d) const = 0;
};

class PowerLawStrength : public CriticalStress {
 public:
  // sigma0 (Pa) at d = reference (m); m the Weibull-like exponent.
  PowerLawStrength(double sigma0, double m, double reference)
      : sigma0_(sigma0), m_(m), ref_(reference) {}
  double of_size(double d) const override;

 private:
  double sigma0_, m_, ref_;
};

class Sigma50Strength : public CriticalStress {
 public:
  Sigma50Strength(double sigma_inf, double x0, double phi, double x_p)
      : sigma_inf_(sigma_inf), x0_(x0), phi_(phi), x_p_(x_p) {}
  double of_size(double d) const override;

 private:
  double sigma_inf_, x0_, phi_, x_p_;
};

}  // namespace comminute::pbm
