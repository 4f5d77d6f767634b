#pragma once
// Power-law selection function S = k (x/x_ref)^α, x the particle size (m) or volume (m³) as the
// case says, with Austin's optional turn-down Q(d) = 1/(1 + (d/μ)^Λ) (Austin, Shoji & Luckie,
// Powder Technol. 14 (1976) 71).
#include <optional>

#include "comminute/pbm/selection_function.hpp"
#include "comminute/pbm/size_grid.hpp"

namespace comminute::pbm {

class PowerLawRate : public SelectionFunction {
 public:
  struct Parameters {
    double k = 1.0;      // 1/s, the rate at x = x_ref
    double alpha = 1.0;  // α
    GridCoordinate variable = GridCoordinate::size;
    double reference = 1.0;    // x_ref in m (size) or m³ (volume)
    std::optional<double> mu;  // μ (m): size where Q = ½; none = no turn-down
    double lambda = 2.0;       // Λ
  };
  explicit PowerLawRate(Parameters p) : p_(p) {}
  double rate(double size, double volume) const override;

 private:
  Parameters p_;
};

}  // namespace comminute::pbm
