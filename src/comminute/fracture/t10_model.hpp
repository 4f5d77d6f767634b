#pragma once
// Breakage index t10 and the t_n family of the progeny (docs/models.md eq. P1-P2):
//   t10 = A [1 - exp(-b' E / E50)]   (%)     (Tavares & de Carvalho, Minerals Eng. 22 (2009) 650;
//                                              JKMRC form of Napier-Munn et al. 1996)   (eq. P1)
//   t_n = 100 I_{t10/100}(alpha_n, beta_n),  n = 2, 4, 25, 50, 75  (regularised incomplete beta;
//                                              UFRJ form, Tavares 2009)                 (eq. P2)
// E is the specific energy of the stressing event (J/kg), E50 the median fracture energy of the
// parent's size (J/kg). Used by DEM breakage (progeny of one event) and the population balance
// (breakage function "t10", UFRJ mill).
//
// Edge rules: 0 < A <= 100, b' > 0, alpha_n, beta_n > 0, else comminute::Error; t10/100 is
// clamped to [0, 1] before I_x is evaluated.
//
// Case keys (DEM [materials.<m>.breakage.progeny], population balance [breakage] function "t10"
// and [mill.progeny]): A (%), b_prime (-), alpha, beta (5 values each, n = 2, 4, 25, 50, 75).
// The old population-balance key `b` is an error naming b_prime.
#include <array>

#include "comminute/core/case_table.hpp"

namespace comminute::fracture {

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
  // t10 (%) for the event's specific energy E (J/kg) and E50 of the parent's size (J/kg).
  double t10(double specific_energy, double e50) const;
  // t_n (%) for n = 2, 4, 25, 50, 75.
  std::array<double, 5> tn(double t10) const;
  const T10Parameters& parameters() const { return p_; }

 private:
  T10Parameters p_;
};

// Reads A, b_prime, alpha and beta from `t`; bad values are InputErrors naming the key.
T10Model read_t10_model(const CaseTable& t);

}  // namespace comminute::fracture
