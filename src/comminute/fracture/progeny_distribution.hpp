#pragma once
// The cumulative progeny size distribution of one breakage event (docs/models.md eq. P3): mass %
// passing size x for a parent of diameter d, through the points (d/n, t_n) with t_1 = 100 and
// t_10, interpolated monotonically (PCHIP, Fritsch & Carlson 1980) in (ln x, P), and extrapolated
// below d/75 by the power law through (d/50, t_50) and (d/75, t_75).
// One implementation for DEM breakage (fragment sizes of an event) and the population balance
// (the t10 breakage function and the UFRJ mill evaluate it at d = 1 against d/D).
#include <array>
#include <vector>

namespace comminute::fracture {

class ProgenyDistribution {
 public:
  // tn: t_2, t_4, t_25, t_50, t_75 (%), as from T10Model::tn. Points that would make the curve
  // decrease with size are raised to the value of the next finer point (monotone by construction).
  ProgenyDistribution(double d, double t10, const std::array<double, 5>& tn);
  // Mass % passing size x (m); 100 for x >= d, 0 for x <= 0.
  double passing(double x) const;
  double diameter() const { return d_; }

 private:
  double d_;
  std::vector<double> u_, p_, slope_;  // ln x, P (%), dP/d ln x at the points
  double tail_exponent_ = 0;           // P = t75 (x/(d/75))^m below d/75
};

}  // namespace comminute::fracture
