#include "comminute/pbm/population_split.hpp"

#include <fmt/format.h>

#include "comminute/core/error.hpp"

namespace comminute::pbm {

PopulationSplit::PopulationSplit(std::vector<Population> populations)
    : pops_(std::move(populations)) {
  if (pops_.empty()) throw Error("PopulationSplit: no population");
  for (std::size_t i = 1; i + 1 < pops_.size(); ++i)
    if (!(pops_[i].upper_volume > pops_[i - 1].upper_volume))
      throw Error("PopulationSplit: size limits must increase");
}

const BreakageFunction& PopulationSplit::of_parent(double y) const {
  for (std::size_t i = 0; i + 1 < pops_.size(); ++i)
    if (y < pops_[i].upper_volume) return *pops_[i].function;
  return *pops_.back().function;
}

double PopulationSplit::cumulative_mass(double v, double y) const {
  return of_parent(y).cumulative_mass(v, y);
}

std::optional<double> PopulationSplit::cumulative_number(double v, double y) const {
  return of_parent(y).cumulative_number(v, y);
}

}  // namespace comminute::pbm

namespace comminute::pbm {

std::string PopulationSplit::summary() const {
  std::string out;
  for (std::size_t i = 0; i < pops_.size(); ++i) {
    const std::string s = pops_[i].function->summary();
    if (s.empty()) continue;
    if (!out.empty()) out += "\n";
    out += i + 1 < pops_.size() ? fmt::format("population {} (parent volume < {:.4g} m3): {}", i,
                                              pops_[i].upper_volume, s)
                                : fmt::format("population {} (larger parents): {}", i, s);
  }
  return out;
}

}  // namespace comminute::pbm
