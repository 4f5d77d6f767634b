#include "comminute/calibrate/parameter_space.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "comminute/core/error.hpp"

namespace comminute::calibrate {

Scale auto_scale(double lower, double upper) {
  return lower > 0 && upper / lower >= 10 ? Scale::log : Scale::linear;
}

ParameterSpace::ParameterSpace(std::vector<FreeParameter> parameters) : p_(std::move(parameters)) {
  for (const auto& p : p_) {
    if (!(p.upper > p.lower))
      throw Error(fmt::format("parameter '{}': upper bound must exceed lower bound", p.name));
    if (p.scale == Scale::log && !(p.lower > 0))
      throw Error(fmt::format("parameter '{}': log scale needs a positive lower bound", p.name));
  }
}

std::vector<double> ParameterSpace::to_parameters(const std::vector<double>& u) const {
  std::vector<double> v(p_.size());
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const double w = std::clamp(u[i], 0.0, 1.0);
    const auto& p = p_[i];
    v[i] = p.scale == Scale::log
               ? std::exp(std::log(p.lower) + w * (std::log(p.upper) - std::log(p.lower)))
               : p.lower + w * (p.upper - p.lower);
    v[i] = std::clamp(v[i], p.lower, p.upper);  // exp/log round-off
  }
  return v;
}

double ParameterSpace::outside2(const std::vector<double>& u) {
  double d = 0;
  for (double x : u) {
    const double e = x - std::clamp(x, 0.0, 1.0);
    d += e * e;
  }
  return d;
}

}  // namespace comminute::calibrate
