#pragma once
// Breakage (daughter-distribution) functions: how the fragments of one breakage event of a parent
// of volume y are distributed over fragment volume v. Every function gives Austin's cumulative
// mass form B(v, y); functions defined by number (Diemer–Olson) also give the cumulative number
// of fragments, which the method of classes integrates exactly over each class.
#include <optional>

namespace comminute::pbm {

class BreakageFunction {
 public:
  virtual ~BreakageFunction() = default;
  // Fraction of the parent's mass in fragments of volume below v (0 ≤ v ≤ y; B(y, y) = 1).
  virtual double cumulative_mass(double v, double y) const = 0;
  // Number of fragments of volume below v; empty for functions defined by mass only.
  virtual std::optional<double> cumulative_number(double /*v*/, double /*y*/) const {
    return std::nullopt;
  }
};

}  // namespace comminute::pbm
