// Diameters lognormal: ln d normal with mean ln(median) and standard deviation `sigma`, truncated
// to [min, max].
// Keys of [insert.size]: median (m), sigma (-), min, max (m); all required, max > min.
#include <cmath>

#include "comminute/particles/size_distribution_common.hpp"

namespace comminute {
namespace {

std::unique_ptr<SizeDistribution> make_lognormal(const CaseTable& t) {
  const double median = t.number("median", Limits::positive());
  const double sigma = t.number("sigma", Limits::positive());
  return std::make_unique<TruncatedGaussian>("lognormal", std::log(median), sigma,
                                             read_diameter_range(t), true);
}

const bool registered = SizeDistributionRegistry::add("lognormal", &make_lognormal);

}  // namespace
}  // namespace comminute
