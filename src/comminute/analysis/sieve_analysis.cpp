#include "comminute/analysis/sieve_analysis.hpp"

#include <algorithm>
#include <cmath>

namespace comminute::analysis {

std::vector<double> sqrt2_series(double top, double bottom) {
  if (!(top > 0) || !std::isfinite(top)) return {};  // no sizes (also: no float->int of a NaN)
  if (!(bottom > 0)) bottom = top / 1024.0;
  // smallest k with 1e-3 * 2^(k/2) >= top
  auto k = static_cast<long>(std::ceil(2.0 * std::log2(top / 1e-3) - 1e-9));
  std::vector<double> s;
  for (double x = 1e-3 * std::pow(2.0, 0.5 * static_cast<double>(k)); x >= bottom * (1 - 1e-12);
       x = 1e-3 * std::pow(2.0, 0.5 * static_cast<double>(--k)))
    s.push_back(x);
  return s;
}

std::vector<std::vector<double>> mass_passing(const ParticleStore& p,
                                              const std::vector<double>& diameters,
                                              const std::vector<double>& sieves,
                                              std::size_t materials,
                                              const std::vector<double>& extra) {
  std::vector<double> asc(sieves.rbegin(), sieves.rend());
  std::vector<std::vector<double>> in_class(materials, std::vector<double>(asc.size() + 1, 0.0));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto c = static_cast<std::size_t>(std::lower_bound(asc.begin(), asc.end(), diameters[i]) -
                                            asc.begin());
    in_class[p.material[i]][c] +=
        p.physical_mass(i);  // class c: passes asc[c] and all larger sieves
  }
  std::vector<std::vector<double>> out(materials, std::vector<double>(sieves.size(), 0.0));
  for (std::size_t m = 0; m < materials; ++m) {
    double cum = m < extra.size() ? extra[m] : 0.0;
    for (std::size_t c = 0; c < asc.size(); ++c) {
      cum += in_class[m][c];
      out[m][asc.size() - 1 - c] = cum;
    }
  }
  return out;
}

}  // namespace comminute::analysis
