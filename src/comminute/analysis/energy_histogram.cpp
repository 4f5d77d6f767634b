#include "comminute/analysis/energy_histogram.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numeric>

#include "comminute/core/error.hpp"

namespace comminute::analysis {

EnergyHistogram::EnergyHistogram(double lo, double hi, int bins)
    : lo_(lo),
      log_lo_(std::log(lo)),
      log_step_((std::log(hi) - std::log(lo)) / bins),
      counts_(static_cast<std::size_t>(bins), 0),
      sums_(static_cast<std::size_t>(bins), 0.0) {
  if (!(lo > 0) || !(hi > lo) || bins < 1)
    throw Error(
        fmt::format("energy histogram: need 0 < lo < hi and bins >= 1 (lo {}, hi {}, "
                    "bins {})",
                    lo, hi, bins));
}

void EnergyHistogram::add(double energy) {
  if (!(energy >= lo_)) {  // zero, below the range (or not a number: counted, never binned)
    ++below_;
    return;
  }
  auto k = static_cast<long>(std::floor((std::log(energy) - log_lo_) / log_step_));
  if (k < 0) k = 0;
  // an energy a rounding away from an edge: the edge itself decides (edge(k) <= E < edge(k+1))
  if (k > 0 && energy < edge(static_cast<int>(k))) --k;
  if (k + 1 < bins() && energy >= edge(static_cast<int>(k + 1))) ++k;
  if (k >= bins()) {
    ++above_;
    return;
  }
  ++counts_[static_cast<std::size_t>(k)];
  sums_[static_cast<std::size_t>(k)] += energy;
}

double EnergyHistogram::edge(int k) const {
  return std::exp(log_lo_ + k * log_step_);
}

double EnergyHistogram::bin_energy(int k) const {
  const auto n = count(k);
  if (n > 0) return energy_sum(k) / static_cast<double>(n);
  return std::exp(log_lo_ + (k + 0.5) * log_step_);
}

std::uint64_t EnergyHistogram::total() const {
  return std::accumulate(counts_.begin(), counts_.end(), below_ + above_);
}

double EnergyHistogram::cumulative(int k) const {
  const std::uint64_t n = total();
  if (n == 0) return 0;
  std::uint64_t c = below_;
  for (int b = 0; b < k && b < bins(); ++b) c += count(b);
  return static_cast<double>(c) / static_cast<double>(n);
}

void EnergyHistogram::save(Archive& a, const std::string& prefix) const {
  a.put(prefix + "counts", counts_);
  a.put(prefix + "sums", sums_);
  a.put(prefix + "outside", std::vector<std::uint64_t>{below_, above_});
}

void EnergyHistogram::load(const Archive& a, const std::string& prefix) {
  auto counts = a.get<std::uint64_t>(prefix + "counts");
  auto sums = a.get<double>(prefix + "sums");
  const auto outside = a.get<std::uint64_t>(prefix + "outside");
  if (counts.size() != counts_.size() || sums.size() != sums_.size() || outside.size() != 2)
    throw Error(
        fmt::format("checkpoint entries '{}counts', '{}sums', '{}outside' do not hold a "
                    "histogram of {} bins",
                    prefix, prefix, prefix, counts_.size()));
  for (double s : sums)
    if (!std::isfinite(s) || s < 0)
      throw Error(
          fmt::format("checkpoint entry '{}sums' holds a value that is not an energy", prefix));
  counts_ = std::move(counts);
  sums_ = std::move(sums);
  below_ = outside[0];
  above_ = outside[1];
}

}  // namespace comminute::analysis
