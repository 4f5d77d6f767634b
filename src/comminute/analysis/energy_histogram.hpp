#pragma once
// A histogram of energies on logarithmically spaced bins, filled one value at a time (a stream of
// collision events is never held): counts and energy sums per bin, plus the values below the
// first edge (zero included) and above the last. Its cumulative distribution is exact at the bin
// edges: F(E_k) = (below + n_1 + ... + n_k) / total.
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/core/archive.hpp"

namespace comminute::analysis {

class EnergyHistogram {
 public:
  EnergyHistogram() = default;
  // `bins` bins spanning [lo, hi] (J, 0 < lo < hi) with equal ratios.
  EnergyHistogram(double lo, double hi, int bins);

  void add(double energy);
  int bins() const { return static_cast<int>(counts_.size()); }
  double edge(int k) const;  // J, k = 0 .. bins()
  std::uint64_t count(int k) const { return counts_[static_cast<std::size_t>(k)]; }
  double energy_sum(int k) const { return sums_[static_cast<std::size_t>(k)]; }  // J
  // The mean energy of bin k's values (J), or its geometric centre when it is empty.
  double bin_energy(int k) const;
  std::uint64_t below() const { return below_; }
  std::uint64_t above() const { return above_; }
  std::uint64_t total() const;
  // Fraction of the values <= edge(k).
  double cumulative(int k) const;

  void save(Archive& a, const std::string& prefix) const;
  // Throws Error when the entries do not hold this histogram's bins.
  void load(const Archive& a, const std::string& prefix);

 private:
  double lo_ = 1, log_lo_ = 0, log_step_ = 1;
  std::vector<std::uint64_t> counts_;
  std::vector<double> sums_;
  std::uint64_t below_ = 0, above_ = 0;
};

}  // namespace comminute::analysis
