#pragma once
// The size distribution of an outlet's product over a time window, from the outlet log
// (engine/outlet.hpp): the mass of the particles removed in t_from < time ≤ t_to (windows that
// share an end partition the log) with diameter ≤ each sieve — the same convention as
// sieve_analysis.hpp, so a product and a bed are sieved alike.
#include <cstdint>
#include <optional>
#include <vector>

#include "comminute/engine/particle_record.hpp"

namespace comminute::analysis {

struct ProductSizes {
  std::uint64_t count = 0;           // particles removed in the window
  double mass = 0;                   // kg, their total mass
  std::vector<double> mass_passing;  // kg, per sieve: mass with diameter ≤ sieve
  // Fraction of the window's mass passing sieve s (0 when nothing was removed).
  double fraction_passing(std::size_t s) const { return mass > 0 ? mass_passing[s] / mass : 0; }
};

// `outlet`: one outlet's index, or every outlet when empty. Sieves in m, any order.
ProductSizes product_sizes(const std::vector<ParticleRecord>& log, double t_from, double t_to,
                           const std::vector<double>& sieves,
                           std::optional<std::uint32_t> outlet = std::nullopt);

}  // namespace comminute::analysis
