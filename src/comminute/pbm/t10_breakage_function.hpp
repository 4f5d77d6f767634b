#pragma once
// The t10 / tn family (JKMRC; incomplete-beta form of the UFRJ model, Tavares): at mass-specific
// stressing energy e,
//   t10 = A [1 − exp(−b' e / E50)]   (%),  E50 the median fracture energy of the parent's size
//   t_n = 100 I_{t10/100}(α_n, β_n),  n ∈ {2, 4, 25, 50, 75}
// and the progeny passes t_n % at d = D/n (t_1 = 100 %); see CumulativeTable for interpolation.
#include <array>
#include <functional>

#include "comminute/pbm/breakage_function.hpp"
#include "comminute/pbm/cumulative_table.hpp"

namespace comminute::pbm {

// The α_n, β_n of the t_n–t10 relation for n = 2, 4, 25, 50, 75 (material inputs).
struct TnFamily {
  static constexpr std::array<double, 5> n = {2, 4, 25, 50, 75};
  std::array<double, 5> alpha{}, beta{};
  // t10 in % (0, 100) → progeny cumulative mass passing against d/D.
  CumulativeTable progeny(double t10) const;
};

// t10 = A [1 − exp(−b' e/E50)] in %.
double t10_at_energy(double A, double b_prime, double specific_energy, double e50);

class T10BreakageFunction : public BreakageFunction {
 public:
  struct Parameters {
    double A = 50;               // %
    double b_prime = 1.0;        // b'
    double specific_energy = 0;  // e, J/kg
    TnFamily family;
  };
  // e50(d): median fracture energy (J/kg) of a parent of size d (m).
  T10BreakageFunction(Parameters p, std::function<double(double)> e50, double shape_factor);

  double t10(double parent_size) const;
  double cumulative_mass(double v, double y) const override;

 private:
  Parameters p_;
  std::function<double(double)> e50_;
  double shape_factor_;
};

}  // namespace comminute::pbm
