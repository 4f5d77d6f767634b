#pragma once
// Austin's cumulative breakage function (Austin, Klimpel & Luckie, Process Engineering of Size
// Reduction: Ball Milling, 1984):
//   B(d, D) = Φ_D (d/D)^γ + (1 − Φ_D) (d/D)^β,   d/D = (v/y)^(1/3) (size ratio),
// normalised when Φ_D = Φ for every parent; otherwise Φ_D = min(1, Φ (D/D_ref)^(−δ)).
#include "comminute/pbm/breakage_function.hpp"

namespace comminute::pbm {

class AustinBreakageFunction : public BreakageFunction {
 public:
  struct Parameters {
    double phi = 0.5;              // Φ, fraction of the fast (fine-producing) term
    double gamma = 1.0;            // γ
    double beta = 4.0;             // β
    double delta = 0.0;            // δ; 0 = normalised
    double reference_size = 1e-3;  // D_ref (m), where Φ_D = Φ when δ ≠ 0
  };
  // parent_size(y) converts a parent volume to its size (m) for the non-normalised Φ_D.
  AustinBreakageFunction(Parameters p, double shape_factor);

  double phi_of_parent(double parent_size) const;
  double cumulative_mass(double v, double y) const override;
  bool homogeneous() const override { return p_.delta == 0.0; }

 private:
  Parameters p_;
  double shape_factor_;
};

}  // namespace comminute::pbm
