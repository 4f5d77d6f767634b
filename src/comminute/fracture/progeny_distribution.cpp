#include "comminute/fracture/progeny_distribution.hpp"

#include <algorithm>
#include <cmath>

namespace comminute::fracture {

ProgenyDistribution::ProgenyDistribution(double d, double t10, const std::array<double, 5>& tn)
    : d_(d) {
  // docs/models.md eq. P3. Ascending in size: d/75, d/50, d/25, d/10, d/4, d/2, d.
  const double n[] = {75, 50, 25, 10, 4, 2, 1};
  const double p[] = {tn[4], tn[3], tn[2], t10, tn[1], tn[0], 100.0};
  double floor_value = 0.0;
  for (int k = 0; k < 7; ++k) {
    u_.push_back(std::log(d / n[k]));
    floor_value = std::clamp(p[k], floor_value, 100.0);
    p_.push_back(floor_value);
  }
  // Fritsch-Carlson monotone slopes: harmonic mean of neighbouring secants, 0 at extrema.
  const std::size_t m = u_.size();
  std::vector<double> secant(m - 1);
  for (std::size_t k = 0; k + 1 < m; ++k) secant[k] = (p_[k + 1] - p_[k]) / (u_[k + 1] - u_[k]);
  slope_.assign(m, 0.0);
  slope_[0] = secant[0];
  slope_[m - 1] = secant[m - 2];
  for (std::size_t k = 1; k + 1 < m; ++k) {
    if (secant[k - 1] * secant[k] <= 0) continue;
    const double h0 = u_[k] - u_[k - 1], h1 = u_[k + 1] - u_[k];
    const double w0 = 2 * h1 + h0, w1 = h1 + 2 * h0;  // Fritsch-Butland weights
    slope_[k] = (w0 + w1) / (w0 / secant[k - 1] + w1 / secant[k]);
  }
  for (std::size_t k : {std::size_t{0}, m - 1}) {  // keep end slopes within 3x the secant
    const double s = secant[k == 0 ? 0 : m - 2];
    slope_[k] = std::clamp(slope_[k], 0.0, 3 * s);
  }
  if (p_[0] > 0 && p_[1] > p_[0]) tail_exponent_ = std::log(p_[1] / p_[0]) / std::log(1.5);
}

double ProgenyDistribution::passing(double x) const {
  if (x >= d_) return 100.0;
  if (x <= 0) return 0.0;
  const double u = std::log(x);
  if (u <= u_[0]) return p_[0] > 0 ? p_[0] * std::pow(x / (d_ / 75.0), tail_exponent_) : 0.0;
  const auto it = std::upper_bound(u_.begin(), u_.end(), u);
  const std::size_t k = static_cast<std::size_t>(it - u_.begin()) - 1;
  const double h = u_[k + 1] - u_[k], s = (u - u_[k]) / h;
  // Cubic Hermite on [u_k, u_k+1].
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  return h00 * p_[k] + h10 * h * slope_[k] + h01 * p_[k + 1] + h11 * h * slope_[k + 1];
}

}  // namespace comminute::fracture
