#pragma once
// Diemer–Olson product function (Diemer & Olson, Chem. Eng. Sci. 57 (2002) 4187, generalised
// Beta daughter distribution): p(v|y) = θ(v/y)/y,
//   θ(z) = ν z^(q−1) (1−z)^(r−1) / B(q, r),  r = q(ν−1),
// so ∫θ dz = ν fragments and ∫zθ dz = 1 (mass). q = 1, ν = 2 is the uniform binary kernel 2/y.
#include "comminute/pbm/breakage_function.hpp"

namespace comminute::pbm {

class ProductFunction : public BreakageFunction {
 public:
  ProductFunction(double q, double nu);  // q > 0, ν > 1 (case files demand ν ≥ 2)

  double q() const { return q_; }
  double nu() const { return nu_; }
  double r() const { return r_; }
  double theta(double z) const;
  // Number median: I_z(q, r) = ½; volume (mass) median: I_z(q+1, r) = ½.
  double z50_number() const;
  double z50_volume() const;

  double cumulative_mass(double v, double y) const override;
  bool homogeneous() const override { return true; }
  std::string summary() const override;  // q, ν and both z50
  std::optional<double> cumulative_number(double v, double y) const override;

 private:
  double q_, nu_, r_;
};

}  // namespace comminute::pbm
