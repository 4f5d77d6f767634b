#pragma once
// Size-dependent strength of a particle (Pa) for the stress-based rate ([rate] strength = ...):
//   power_law   sigma_crit = sigma0 (d/d_ref)^(-1/m)                 (docs/models.md eq. S3)
//   sigma50     sigma50 = sigma_inf (1 + x0/(d - x_p))^phi, unbreakable (infinite strength) for
//               d <= x_p                                             (docs/models.md eq. S4)
// (a carbon-black fragmentation study in a mixer; see docs/models.md).
#include "comminute/core/case_table.hpp"
#include "comminute/core/registry.hpp"

namespace comminute::pbm {

class CriticalStress {
 public:
  virtual ~CriticalStress() = default;
  virtual double of_size(double d) const = 0;
};

// Each strength model's file registers its factory, which reads its keys from the [rate] table.
using CriticalStressRegistry = Registry<CriticalStress, const CaseTable&>;

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
