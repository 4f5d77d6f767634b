// A discrete table of diameters with mass or number fractions.
// Keys of [insert.size]: diameters (m, > 0, required), fractions (-, >= 0, one per diameter,
// summing to 1, required), basis ("mass" (default) or "number").
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "comminute/particles/size_distribution_common.hpp"

namespace comminute {
namespace {

// Number weights of the diameters d from `fractions` and `basis`: a mass fraction w_k of size d_k
// holds w_k / d_k^3 particles (same density).
std::vector<double> number_weights(const CaseTable& t, const std::vector<double>& d) {
  const std::vector<double> f = t.numbers("fractions", Limits::non_negative());
  const bool mass_fractions = t.choice("basis", {"mass", "number"}, "mass") == "mass";
  if (d.empty()) t.fail("diameters", "the table is empty");
  if (f.size() != d.size())
    t.fail("fractions", fmt::format("has {} entries but diameters has {}", f.size(), d.size()));
  double sum = 0;
  for (double x : f) sum += x;
  if (std::abs(sum - 1.0) > 1e-6)
    t.fail("fractions", fmt::format("fractions sum to {}, not 1", sum));
  std::vector<double> w(d.size());
  for (std::size_t k = 0; k < d.size(); ++k)
    w[k] = mass_fractions ? f[k] / std::pow(d[k], 3) : f[k];
  return w;
}

class Table final : public SizeDistribution {
 public:
  explicit Table(const CaseTable& t) : d_(t.numbers("diameters", Limits::positive())) {
    const std::vector<double> w = number_weights(t, d_);
    const double total = std::accumulate(w.begin(), w.end(), 0.0);
    double c = 0;
    for (double x : w) cum_.push_back(c += x / total);
    cum_.back() = 1.0;
    for (std::size_t k = 0; k < d_.size(); ++k) mean_v_ += w[k] / total * sphere_volume_d(d_[k]);
  }
  std::string name() const override { return "table"; }
  double sample(Rng& r) const override {
    const double u = r.uniform();
    const auto it = std::lower_bound(cum_.begin(), cum_.end(), u);
    return d_[static_cast<std::size_t>(it - cum_.begin())];
  }
  double min_diameter() const override { return *std::min_element(d_.begin(), d_.end()); }
  double max_diameter() const override { return *std::max_element(d_.begin(), d_.end()); }
  double mean_volume() const override { return mean_v_; }

 private:
  std::vector<double> d_, cum_;
  double mean_v_ = 0;
};

const bool registered = SizeDistributionRegistry::add(
    "table", [](const CaseTable& t) { return std::make_unique<Table>(t); });

}  // namespace
}  // namespace comminute
