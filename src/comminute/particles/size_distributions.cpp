// The built-in size distributions: fixed, uniform (in diameter), normal and lognormal
// (truncated to [min, max] by rejection), and a discrete table with mass or number fractions.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "comminute/core/units.hpp"
#include "comminute/particles/size_distribution.hpp"

namespace comminute {
namespace {

double sphere_volume_d(double d) {
  return units::pi / 6 * d * d * d;
}

// Mean of d^3 by Monte Carlo-free quadrature over the sampler's inverse CDF (midpoint, 2000 nodes).
template <class InverseCdf>
double mean_volume_of(InverseCdf q) {
  double s = 0;
  const int n = 2000;
  for (int k = 0; k < n; ++k) s += sphere_volume_d(q((k + 0.5) / n));
  return s / n;
}

class Fixed final : public SizeDistribution {
 public:
  explicit Fixed(const SizeParameters& p) : d_(p.diameter) {}
  std::string name() const override { return "fixed"; }
  double sample(Rng&) const override { return d_; }
  double min_diameter() const override { return d_; }
  double max_diameter() const override { return d_; }
  double mean_volume() const override { return sphere_volume_d(d_); }

 private:
  double d_;
};

class Uniform final : public SizeDistribution {
 public:
  explicit Uniform(const SizeParameters& p) : lo_(p.min), hi_(p.max) {}
  std::string name() const override { return "uniform"; }
  double sample(Rng& r) const override { return r.uniform(lo_, hi_); }
  double min_diameter() const override { return lo_; }
  double max_diameter() const override { return hi_; }
  double mean_volume() const override {
    return mean_volume_of([this](double u) { return lo_ + u * (hi_ - lo_); });
  }

 private:
  double lo_, hi_;
};

// Normal in d or in ln d, truncated to [lo, hi] by inversion of the truncated CDF.
class Gaussian final : public SizeDistribution {
 public:
  Gaussian(double mu, double s, double lo, double hi, bool log)
      : mu_(mu), s_(s), lo_(lo), hi_(hi), log_(log) {}
  std::string name() const override { return log_ ? "lognormal" : "normal"; }
  double sample(Rng& r) const override { return quantile(r.uniform()); }
  double min_diameter() const override { return lo_; }
  double max_diameter() const override { return hi_; }
  double mean_volume() const override {
    return mean_volume_of([this](double u) { return quantile(u); });
  }

 private:
  double cdf(double d) const {
    const double z = ((log_ ? std::log(d) : d) - mu_) / s_;
    return 0.5 * std::erfc(-z / std::sqrt(2.0));
  }
  double quantile(double u) const {
    // bisection on the truncated CDF: robust and reproducible (insertion is not a hot path)
    const double c0 = cdf(lo_), c1 = cdf(hi_), target = c0 + u * (c1 - c0);
    double a = lo_, b = hi_;
    for (int it = 0; it < 60; ++it) {
      const double m = 0.5 * (a + b);
      (cdf(m) < target ? a : b) = m;
    }
    return 0.5 * (a + b);
  }
  double mu_, s_, lo_, hi_;
  bool log_;
};

class Table final : public SizeDistribution {
 public:
  explicit Table(const SizeParameters& p) : d_(p.diameters) {
    // number weights: a mass fraction w_k of size d_k holds w_k / d_k^3 particles (same density)
    std::vector<double> w(d_.size());
    for (std::size_t k = 0; k < d_.size(); ++k)
      w[k] = p.mass_fractions ? p.fractions[k] / std::pow(d_[k], 3) : p.fractions[k];
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

const bool r1 = SizeDistributionRegistry::add(
    "fixed", [](const SizeParameters& p) { return std::make_unique<Fixed>(p); });
const bool r2 = SizeDistributionRegistry::add(
    "uniform", [](const SizeParameters& p) { return std::make_unique<Uniform>(p); });
const bool r3 = SizeDistributionRegistry::add("normal", [](const SizeParameters& p) {
  return std::make_unique<Gaussian>(p.mean, p.sd, p.min, p.max, false);
});
const bool r4 = SizeDistributionRegistry::add("lognormal", [](const SizeParameters& p) {
  return std::make_unique<Gaussian>(std::log(p.median), p.sigma, p.min, p.max, true);
});
const bool r5 = SizeDistributionRegistry::add(
    "table", [](const SizeParameters& p) { return std::make_unique<Table>(p); });

}  // namespace
}  // namespace comminute
