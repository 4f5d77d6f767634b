#pragma once
// The "t10" progeny model: t10 = A [1 - exp(-b' E/E50)] and the incomplete-beta t_n family
// (fracture::T10Model, docs/models.md eq. P1-P2) through the progeny curve of eq. P3.
#include "comminute/breakage/progeny/progeny_model.hpp"
#include "comminute/fracture/t10_model.hpp"

namespace comminute::breakage {

class T10Progeny final : public ProgenyModel {
 public:
  explicit T10Progeny(const fracture::T10Parameters& p,
                      fracture::E50bRule rule = fracture::E50bRule::breaking)
      : model_(p), rule_(rule) {}
  std::string name() const override { return "t10"; }
  double t10(double specific_energy, double e50) const override;
  fracture::E50bRule e50b_rule() const override { return rule_; }
  ProgenyDistribution distribution(double d, double t10) const override;
  const fracture::T10Model& model() const { return model_; }
  // Illustrative t_n family (a fit to a typical t-family chart; not published values), A = 50 %,
  // b' = 1: the progeny of a material without a progeny table.
  static fracture::T10Parameters illustrative();

 private:
  fracture::T10Model model_;
  fracture::E50bRule rule_;
};

}  // namespace comminute::breakage
