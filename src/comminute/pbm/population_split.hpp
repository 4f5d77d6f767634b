#pragma once
// Several particle populations, each with its own breakage function, split by parent size (the
// brittle/soft agglomerate split of the carbon-black study): a parent of volume y breaks by the
// function of the first population whose upper volume limit exceeds y; the last has none.
#include <memory>
#include <vector>

#include "comminute/pbm/breakage_function.hpp"

namespace comminute::pbm {

class PopulationSplit : public BreakageFunction {
 public:
  struct Population {
    double upper_volume;  // m³; ignored for the last population
    std::unique_ptr<BreakageFunction> function;
  };
  explicit PopulationSplit(std::vector<Population> populations);

  const BreakageFunction& of_parent(double y) const override;
  double cumulative_mass(double v, double y) const override;
  std::optional<double> cumulative_number(double v, double y) const override;
  std::string summary() const override;  // one line per population

 private:
  std::vector<Population> pops_;
};

}  // namespace comminute::pbm
