// Diameters normal with mean `mean` and standard deviation `sd`, truncated to [min, max].
// Keys of [insert.size]: mean, sd, min, max (m, required, max > min).
#include "comminute/particles/size_distribution_common.hpp"

namespace comminute {
namespace {

std::unique_ptr<SizeDistribution> make_normal(const CaseTable& t) {
  const double mean = t.number("mean", Limits::positive());
  const double sd = t.number("sd", Limits::positive());
  return std::make_unique<TruncatedGaussian>("normal", mean, sd, read_diameter_range(t), false);
}

const bool registered = SizeDistributionRegistry::add("normal", &make_normal);

}  // namespace
}  // namespace comminute
