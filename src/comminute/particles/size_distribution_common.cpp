#include "comminute/particles/size_distribution_common.hpp"

#include <fmt/format.h>

#include <cmath>

namespace comminute {

DiameterRange read_diameter_range(const CaseTable& t) {
  DiameterRange r;
  r.min = t.number("min", Limits::positive());
  r.max = t.number("max", Limits::positive());
  if (!(r.max > r.min)) t.fail("max", fmt::format("max ({}) must exceed min ({})", r.max, r.min));
  return r;
}

double TruncatedGaussian::mean_volume() const {
  return mean_volume_of([this](double u) { return quantile(u); });
}

// Normal CDF Phi(z) = erfc(-z / sqrt 2) / 2 (Abramowitz & Stegun 26.2.29).
double TruncatedGaussian::cdf(double d) const {
  const double z = ((log_ ? std::log(d) : d) - mu_) / s_;
  return 0.5 * std::erfc(-z / std::sqrt(2.0));
}

double TruncatedGaussian::quantile(double u) const {
  // bisection on the truncated CDF: robust and reproducible (insertion is not a hot path)
  const double c0 = cdf(lo_), c1 = cdf(hi_), target = c0 + u * (c1 - c0);
  double a = lo_, b = hi_;
  for (int it = 0; it < 60; ++it) {
    const double m = 0.5 * (a + b);
    (cdf(m) < target ? a : b) = m;
  }
  return 0.5 * (a + b);
}

}  // namespace comminute
