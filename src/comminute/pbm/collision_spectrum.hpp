#pragma once
// A mill's collision energy spectrum, as the DEM of the grinding media records it: energy classes
// E_k (J per collision; dissipated, impact or kinetic — the case says which it is) and the
// frequency λ_k (collisions per second in the whole charge) of each.
#include <string>
#include <vector>

#include "comminute/core/case_table.hpp"

namespace comminute::pbm {

struct CollisionSpectrum {
  std::vector<double> energy;     // J
  std::vector<double> frequency;  // 1/s
};

// The CSV named by `key` of `t`, columns energy_J (> 0) and frequency_per_s (>= 0).
CollisionSpectrum read_collision_spectrum(const CaseTable& t, const std::string& key);

}  // namespace comminute::pbm
