#pragma once
// Scalar measures of a symmetric stress tensor (tension positive): principal stresses
// σ1 ≥ σ2 ≥ σ3, mean stress σm = tr σ / 3 and the largest shear stress τmax = (σ1 − σ3)/2
// (Mohr's circle).
#include <array>

#include "comminute/engine/contact_stress.hpp"

namespace comminute::analysis {

struct StressMeasures {
  std::array<double, 3> principal{};  // Pa, decreasing
  double mean = 0;                    // Pa
  double tau_max = 0;                 // Pa
};

StressMeasures stress_measures(const SymTensor& s);

}  // namespace comminute::analysis
