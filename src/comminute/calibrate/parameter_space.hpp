#pragma once
// Free parameters with bounds, preconditioned for the optimiser: each parameter is mapped to
// u ∈ [0, 1] — through ln p where the bounds span a wide range (or the case asks for it), else
// linearly — so that every direction of the simplex has the same scale.
#include <string>
#include <vector>

namespace comminute::calibrate {

enum class Scale { linear, log };

struct FreeParameter {
  std::string name;
  double lower = 0, upper = 1;
  Scale scale = Scale::linear;
};

// "auto" scaling: log when 0 < lower and upper/lower ≥ 10.
Scale auto_scale(double lower, double upper);

class ParameterSpace {
 public:
  explicit ParameterSpace(std::vector<FreeParameter> parameters);  // checks bounds
  std::size_t size() const { return p_.size(); }
  const FreeParameter& operator[](std::size_t i) const { return p_[i]; }
  // u (clamped to [0, 1]) → parameter values.
  std::vector<double> to_parameters(const std::vector<double>& u) const;
  // Squared distance of u outside the unit box (0 inside).
  static double outside2(const std::vector<double>& u);

 private:
  std::vector<FreeParameter> p_;
};

}  // namespace comminute::calibrate
