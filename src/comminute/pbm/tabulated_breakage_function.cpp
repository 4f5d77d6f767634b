#include "comminute/pbm/tabulated_breakage_function.hpp"

#include <cmath>

namespace comminute::pbm {

double TabulatedBreakageFunction::cumulative_mass(double v, double y) const {
  return table_.passing(std::cbrt(v / y));
}

}  // namespace comminute::pbm
