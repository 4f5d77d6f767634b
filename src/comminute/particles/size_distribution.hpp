#pragma once
// Particle size distributions for insertion, chosen by name ([insert.size] distribution = ...).
// Each distribution is a plug-in: its factory in SizeDistributionRegistry takes the view of the
// [insert.size] table and the model reads its own keys. All sizes are diameters in m; sample()
// returns one diameter.
#include <string>

#include "comminute/core/case_table.hpp"
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

using SizeDistributionRegistry = Registry<SizeDistribution, const CaseTable&>;

}  // namespace comminute
