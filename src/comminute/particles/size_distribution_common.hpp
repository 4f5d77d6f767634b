#pragma once
// What several size distributions share: the sphere volume of a diameter, the mean volume by
// quadrature over an inverse CDF, the [min, max] diameter range, and the truncated Gaussian (in d
// for "normal", in ln d for "lognormal").
#include <string>
#include <utility>

#include "comminute/core/units.hpp"
#include "comminute/particles/size_distribution.hpp"

namespace comminute {

inline double sphere_volume_d(double d) {
  return units::pi / 6 * d * d * d;
}

// Mean of the sphere volume by Monte Carlo-free quadrature over the sampler's inverse CDF
// (midpoint, 2000 nodes).
template <class InverseCdf>
double mean_volume_of(InverseCdf q) {
  double s = 0;
  const int n = 2000;
  for (int k = 0; k < n; ++k) s += sphere_volume_d(q((k + 0.5) / n));
  return s / n;
}

struct DiameterRange {
  double min = 0, max = 0;  // m
};

// Keys `min` and `max` (m, > 0) of the table; fails on `max` unless max > min.
DiameterRange read_diameter_range(const CaseTable& t);

// Normal in d (log = false) or in ln d (log = true) with mean mu and standard deviation s,
// truncated to [range.min, range.max] by inversion of the truncated CDF.
class TruncatedGaussian final : public SizeDistribution {
 public:
  TruncatedGaussian(std::string name, double mu, double s, DiameterRange range, bool log)
      : name_(std::move(name)), mu_(mu), s_(s), lo_(range.min), hi_(range.max), log_(log) {}
  std::string name() const override { return name_; }
  double sample(Rng& r) const override { return quantile(r.uniform()); }
  double min_diameter() const override { return lo_; }
  double max_diameter() const override { return hi_; }
  double mean_volume() const override;

 private:
  double cdf(double d) const;
  double quantile(double u) const;

  std::string name_;
  double mu_, s_, lo_, hi_;
  bool log_;
};

}  // namespace comminute
