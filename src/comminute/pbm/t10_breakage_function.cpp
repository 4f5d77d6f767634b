#include "comminute/pbm/t10_breakage_function.hpp"

#include <algorithm>
#include <boost/math/special_functions/beta.hpp>
#include <cmath>
#include <vector>

namespace comminute::pbm {

// t_n = 100 I_{t10/100}(α_n, β_n); points (1/n, t_n) plus (1/10, t10) and (1, 100).
CumulativeTable TnFamily::progeny(double t10) const {
  const double x = t10 / 100.0;
  std::vector<std::pair<double, double>> pts;
  for (std::size_t k = 0; k < n.size(); ++k)
    pts.emplace_back(1.0 / n[k], boost::math::ibeta(alpha[k], beta[k], x));
  pts.emplace_back(0.1, x);
  pts.emplace_back(1.0, 1.0);
  std::sort(pts.begin(), pts.end());
  std::vector<double> r, p;
  for (const auto& [s, v] : pts) {
    r.push_back(s);
    // keep the table monotone if a user family crosses at t10
    p.push_back(p.empty() ? v : std::max(v, p.back()));
  }
  return CumulativeTable(std::move(r), std::move(p));
}

// Tavares (UFRJ), t10 = A[1 − exp(−b' e/E50)].
double t10_at_energy(double A, double b_prime, double specific_energy, double e50) {
  return A * (1 - std::exp(-b_prime * specific_energy / e50));
}

T10BreakageFunction::T10BreakageFunction(Parameters p, std::function<double(double)> e50,
                                         double shape_factor)
    : p_(p), e50_(std::move(e50)), shape_factor_(shape_factor) {}

double T10BreakageFunction::t10(double parent_size) const {
  return t10_at_energy(p_.A, p_.b_prime, p_.specific_energy, e50_(parent_size));
}

double T10BreakageFunction::cumulative_mass(double v, double y) const {
  const double t = t10(std::cbrt(y / shape_factor_));
  return p_.family.progeny(t).passing(std::cbrt(v / y));
}

}  // namespace comminute::pbm
