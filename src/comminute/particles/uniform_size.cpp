// Diameters uniform in [min, max].
// Keys of [insert.size]: min, max (m, required, max > min).
#include "comminute/particles/size_distribution_common.hpp"

namespace comminute {
namespace {

class Uniform final : public SizeDistribution {
 public:
  explicit Uniform(const CaseTable& t) : range_(read_diameter_range(t)) {}
  std::string name() const override { return "uniform"; }
  double sample(Rng& r) const override { return r.uniform(range_.min, range_.max); }
  double min_diameter() const override { return range_.min; }
  double max_diameter() const override { return range_.max; }
  double mean_volume() const override {
    return mean_volume_of([this](double u) { return range_.min + u * (range_.max - range_.min); });
  }

 private:
  DiameterRange range_;
};

const bool registered = SizeDistributionRegistry::add(
    "uniform", [](const CaseTable& t) { return std::make_unique<Uniform>(t); });

}  // namespace
}  // namespace comminute
