#pragma once
// Vogel & Peukert breakage probability (Vogel & Peukert, Powder Technol. 129 (2003) 101;
// docs/models.md eq. C3):
//   P = 1 - exp[-f_mat x k (W_m,kin - W_m,min)],   W_m,min(x) = (x W_m,min)/x,
// with the impacts' excess energies summed in the incremental form (Morrison, Shi & Whyte,
// Minerals Eng. 20 (2007) 303). Used by the DEM criterion "vogel_peukert" and the population-
// balance rates "capece" (its linearised excess, f_mat and threshold) and "tuzcu_rajamani_variant".
//
// Edge rules: f_mat > 0, threshold_product >= 0; an excess below zero counts as zero.
// Case keys: f_mat (kg/(J m), required), threshold_product (x W_m,min, J m/kg, default 0); the
// old population-balance key x_e_min is an error naming threshold_product.
#include "comminute/core/case_table.hpp"

namespace comminute::fracture {

struct VogelPeukertModel {
  double f_mat = 0;              // kg/(J m)
  double threshold_product = 0;  // x W_m,min, J m/kg

  double threshold(double d) const { return threshold_product / d; }  // W_m,min(d), J/kg
  // f_mat d max(0, excess): the exponent of P for an accumulated excess energy (J/kg).
  double exponent(double d, double excess) const;
  double probability(double d, double excess) const;  // 1 - exp(-exponent)
};

VogelPeukertModel read_vogel_peukert(const CaseTable& t);

}  // namespace comminute::fracture
