#pragma once
// A cumulative fragment-size distribution tabulated against the size ratio s = d/D ∈ (0, 1]:
// P(s) mass fraction passing. Monotone (PCHIP) interpolation in (ln s, P); below the smallest
// tabulated ratio a power law through the two smallest points (the usual Schuhmann-type tail).
// Boost 1.74's pchip.hpp calls isnan unqualified; <math.h> puts it in the global namespace.
#include <math.h>  // NOLINT(modernize-deprecated-headers)

#include <boost/math/interpolators/pchip.hpp>
#include <vector>

namespace comminute::pbm {

class CumulativeTable {
 public:
  // ratios strictly increasing in (0, 1], the last equal to 1 with passing 1; passing
  // non-decreasing in [0, 1]; at least four points (PCHIP). Throws comminute::Error otherwise.
  CumulativeTable(std::vector<double> ratios, std::vector<double> passing);

  double passing(double ratio) const;

 private:
  double s_min_, p_min_, tail_exponent_;
  boost::math::interpolators::pchip<std::vector<double>> interp_;
};

}  // namespace comminute::pbm
