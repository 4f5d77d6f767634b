#pragma once
// Particle size distributions for insertion, chosen by name ([insert.size] distribution = ...).
// All sizes are diameters in m; sample() returns one diameter.
#include <memory>
#include <string>
#include <vector>

#include "comminute/core/registry.hpp"
#include "comminute/core/rng.hpp"

namespace comminute {

class SizeDistribution {
 public:
  virtual ~SizeDistribution() = default;
  virtual std::string name() const = 0;
  virtual double sample(Rng& rng) const = 0;
  virtual double min_diameter() const = 0;
  virtual double max_diameter() const = 0;
  virtual double mean_volume() const = 0;  // m3, expected sphere volume of one draw
};

// Parameters read from the case file; which ones a distribution needs is its own business
// (the case builder checks them per name).
struct SizeParameters {
  double diameter = 0;           // fixed
  double min = 0, max = 0;       // uniform bounds; truncation of normal/lognormal (0 = none)
  double mean = 0, sd = 0;       // normal
  double median = 0, sigma = 0;  // lognormal: median diameter, sd of ln d
  std::vector<double> diameters, fractions;  // table
  bool mass_fractions = true;                // table fractions by mass (else by number)
};

using SizeDistributionRegistry = Registry<SizeDistribution, const SizeParameters&>;

}  // namespace comminute
