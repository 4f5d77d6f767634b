#pragma once
// Breakage index and the t_n family (seed 002 eq. 16-17; MODELS.md "Progeny").
#include <array>

namespace comminute::breakage {

// The t_n family is given at these n (t_n: mass % of progeny passing d/n).
inline constexpr std::array<double, 5> tn_sizes = {2, 4, 25, 50, 75};

struct T10Parameters {
  double a = 50.0;       // A, %: largest t10
  double b_prime = 1.0;  // b', -
  // Incomplete-beta parameters alpha_n, beta_n for n = 2, 4, 25, 50, 75 (material inputs; no
  // published default set exists, examples say their values are illustrative).
  std::array<double, 5> alpha{}, beta{};
};

class T10Model {
 public:
  explicit T10Model(const T10Parameters& p);
  // t10 (%) = A [1 - exp(-b' E / E50b)], E the absorbed specific energy e E_k (J/kg) and E50b
  // the median fracture energy of the parent's size (J/kg).
  double t10(double specific_energy, double e50b) const;
  // t_n (%) = 100 I_{t10/100}(alpha_n, beta_n) for n = 2, 4, 25, 50, 75.
  std::array<double, 5> tn(double t10) const;
  const T10Parameters& parameters() const { return p_; }

 private:
  T10Parameters p_;
};

}  // namespace comminute::breakage
