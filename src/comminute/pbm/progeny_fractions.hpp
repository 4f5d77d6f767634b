#pragma once
// The progeny curve of one breakage event (fracture::ProgenyDistribution, docs/models.md eq. P3)
// as the population balance uses it: mass fraction passing against the size ratio d/D.
#include <utility>

#include "comminute/fracture/progeny_distribution.hpp"
#include "comminute/fracture/t10_model.hpp"

namespace comminute::pbm {

class ProgenyFractions {
 public:
  explicit ProgenyFractions(fracture::ProgenyDistribution curve) : curve_(std::move(curve)) {}
  // Mass fraction of the progeny finer than `ratio` = d/D (1 for ratio >= 1, 0 for ratio <= 0).
  double passing(double ratio) const { return curve_.passing(ratio) / 100.0; }

 private:
  fracture::ProgenyDistribution curve_;  // built at parent size 1, so its x is d/D
};

// The t10 progeny at breakage index t10 (%): points (1/n, t_n) of eq. P2 with (1/10, t10) and
// (1, 100 %), monotone PCHIP in ln(d/D), power-law tail below 1/75 (eq. P3).
ProgenyFractions t10_progeny(const fracture::T10Model& model, double t10);

}  // namespace comminute::pbm
