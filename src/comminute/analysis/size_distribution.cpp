#include "comminute/analysis/size_distribution.hpp"

#include <algorithm>
#include <cmath>

#include "comminute/core/error.hpp"

namespace comminute::analysis {

Basis basis_from_name(const std::string& name) {
  if (name == "number") return Basis::number;
  if (name == "volume") return Basis::volume;
  if (name == "mass") return Basis::mass;
  throw Error("unknown basis '" + name + "' (number, volume, mass)");
}

SizeDistribution::SizeDistribution(std::vector<double> size_edges,
                                   std::vector<double> particle_volume, std::vector<double> number,
                                   double density)
    : edges_(std::move(size_edges)),
      volume_(std::move(particle_volume)),
      number_(std::move(number)),
      density_(density) {
  if (edges_.size() != number_.size() + 1 || volume_.size() != number_.size())
    throw Error("SizeDistribution: need n + 1 edges and n particle volumes for n classes");
}

std::vector<double> SizeDistribution::amounts(Basis b) const {
  std::vector<double> a(number_);
  if (b == Basis::number) return a;
  for (std::size_t i = 0; i < a.size(); ++i)
    a[i] *= volume_[i] * (b == Basis::mass ? density_ : 1.0);
  return a;
}

double SizeDistribution::total(Basis b) const {
  const auto a = amounts(b);
  double s = 0;
  for (double x : a) s += x;
  return s;
}

std::vector<double> SizeDistribution::fractions(Basis b) const {
  auto a = amounts(b);
  const double t = total(b);
  for (double& x : a) x = t > 0 ? x / t : 0.0;
  return a;
}

std::vector<double> SizeDistribution::density(Basis b) const {
  auto f = fractions(b);
  for (std::size_t i = 0; i < f.size(); ++i) f[i] /= edges_[i + 1] - edges_[i];
  return f;
}

std::vector<double> SizeDistribution::cumulative(Basis b) const {
  auto f = fractions(b);
  for (std::size_t i = 1; i < f.size(); ++i) f[i] += f[i - 1];
  return f;
}

double SizeDistribution::cumulative_at(double size, Basis b) const {
  if (size <= edges_.front()) return 0.0;
  if (size >= edges_.back()) return 1.0;
  const auto c = cumulative(b);
  const std::size_t i = static_cast<std::size_t>(
      std::upper_bound(edges_.begin(), edges_.end(), size) - edges_.begin() - 1);
  const double lo = i == 0 ? 0.0 : c[i - 1], hi = c[i];
  const double w = edges_[i] > 0 ? std::log(size / edges_[i]) / std::log(edges_[i + 1] / edges_[i])
                                 : size / edges_[i + 1];
  return lo + w * (hi - lo);
}

}  // namespace comminute::analysis
