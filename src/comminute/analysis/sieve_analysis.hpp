#pragma once
// Sieve analysis of a particle set: mass passing each sieve, per material (SI: m, kg).
#include <cstdint>
#include <vector>

#include "comminute/particles/particle_store.hpp"

namespace comminute::analysis {

// Sieve apertures (m), descending.
struct SieveOptions {
  std::vector<double> sieves;  // user sieves; empty = a sqrt2 series
  double bottom = 0;           // m, smallest sieve of the series (0: top / 2^10)
};

// The sqrt2 series anchored at 1 mm (1e-3 * 2^(k/2)): from the smallest member >= top down to
// the largest member <= bottom (bottom 0: top / 2^10). Descending.
std::vector<double> sqrt2_series(double top, double bottom);

// mass_passing[m][s]: mass (kg) of material m in particles with diameter <= sieves[s], plus
// extra[m] (fines booked as mass, finer than every sieve). `diameter_of` gives each particle's
// size (fragments still growing count at their final size).
std::vector<std::vector<double>> mass_passing(const ParticleStore& p,
                                              const std::vector<double>& diameters,
                                              const std::vector<double>& sieves,
                                              std::size_t materials,
                                              const std::vector<double>& extra);

}  // namespace comminute::analysis
