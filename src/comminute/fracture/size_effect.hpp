#pragma once
// Size effect of the median fracture energy (Tavares & King, Int. J. Miner. Process. 54 (1998) 1;
// docs/models.md eq. F3):  E50(d) = E_inf * partition * [1 + (d0/d)^phi].
//
// partition = 1/(1 + k_p/k_s) when E_inf was measured as energy applied against a device of
// stiffness k_s, so that E50 is an absorbed energy (energy_share.hpp); 1 when E_inf is already
// an absorbed energy (always so in the population balance).
// Edge rule: d0 = 0 switches the size effect off (E50 = E_inf * partition for every phi).
//
// Case keys: e_inf (J/kg, required, > 0), d0 (m, default 0, >= 0), phi (-, default 1, >= 0); the
// old population-balance key e50_inf is an error naming e_inf.
#include "comminute/core/case_table.hpp"

namespace comminute::fracture {

struct SizeEffect {
  double e_inf = 0;            // J/kg
  double d0 = 0;               // m
  double phi = 1;              // -
  double partition = 1;        // -
  double e50(double d) const;  // J/kg, d in m
};

// Reads e_inf, d0 and phi (partition stays 1).
SizeEffect read_size_effect(const CaseTable& t);

}  // namespace comminute::fracture
