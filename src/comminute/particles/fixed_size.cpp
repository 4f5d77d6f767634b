// Every particle of one diameter.
// Keys of [insert.size]: diameter (m, required).
#include "comminute/particles/size_distribution_common.hpp"

namespace comminute {
namespace {

class Fixed final : public SizeDistribution {
 public:
  explicit Fixed(const CaseTable& t) : d_(t.number("diameter", Limits::positive())) {}
  std::string name() const override { return "fixed"; }
  double sample(Rng&) const override { return d_; }
  double min_diameter() const override { return d_; }
  double max_diameter() const override { return d_; }
  double mean_volume() const override { return sphere_volume_d(d_); }

 private:
  double d_;
};

const bool registered = SizeDistributionRegistry::add(
    "fixed", [](const CaseTable& t) { return std::make_unique<Fixed>(t); });

}  // namespace
}  // namespace comminute
