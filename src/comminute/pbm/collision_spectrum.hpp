#pragma once
// A mill's collision energy spectrum, as the DEM of the grinding media records it: energy classes
// E_k (J per collision; dissipated, impact or kinetic — the case says which it is) and the
// frequency λ_k (collisions per second in the whole charge) of each.
#include <vector>

namespace comminute::pbm {

struct CollisionSpectrum {
  std::vector<double> energy;     // J
  std::vector<double> frequency;  // 1/s
};

}  // namespace comminute::pbm
