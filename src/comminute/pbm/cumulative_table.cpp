#include "comminute/pbm/cumulative_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "comminute/core/error.hpp"

namespace comminute::pbm {

namespace {
std::vector<double> checked_logs(const std::vector<double>& ratios,
                                 const std::vector<double>& passing) {
  if (ratios.size() != passing.size() || ratios.size() < 4)
    throw Error("cumulative table: need at least 4 (ratio, passing) pairs of equal length");
  if (std::abs(ratios.back() - 1.0) > 1e-12 || std::abs(passing.back() - 1.0) > 1e-12)
    throw Error("cumulative table: the last point must be ratio 1, passing 1");
  std::vector<double> out;
  for (std::size_t i = 0; i < ratios.size(); ++i) {
    if (!(ratios[i] > 0) || (i > 0 && !(ratios[i] > ratios[i - 1])))
      throw Error(
          fmt::format("cumulative table: ratio {} ({}) not increasing in (0, 1]", i, ratios[i]));
    if (!(passing[i] > 0) || passing[i] > 1 || (i > 0 && passing[i] < passing[i - 1]))
      throw Error(fmt::format("cumulative table: passing {} ({}) not non-decreasing in (0, 1]", i,
                              passing[i]));
    out.push_back(std::log(ratios[i]));
  }
  return out;
}
}  // namespace

CumulativeTable::CumulativeTable(std::vector<double> ratios, std::vector<double> passing)
    : s_min_(ratios.empty() ? 0 : ratios.front()),
      p_min_(passing.empty() ? 0 : passing.front()),
      tail_exponent_(ratios.size() < 2
                         ? 0
                         : std::log(passing[1] / passing[0]) / std::log(ratios[1] / ratios[0])),
      interp_(checked_logs(ratios, passing), std::vector<double>(passing)) {}

double CumulativeTable::passing(double ratio) const {
  if (ratio >= 1) return 1.0;
  if (ratio <= 0) return 0.0;
  if (ratio < s_min_) return p_min_ * std::pow(ratio / s_min_, tail_exponent_);
  return std::clamp(interp_(std::log(ratio)), 0.0, 1.0);
}

}  // namespace comminute::pbm
