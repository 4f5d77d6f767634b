#pragma once
// Vogel & Peukert (2003) breakage probability, incremental form (Morrison, Shi & Whyte 2007;
// docs/models.md eq. C3): P = 1 - exp[-f_mat x sum_k max(0, W_k - W_min(x))], with
// W_min(x) = (x W_min)/x. Each particle draws a uniform "breakability" u once; it breaks when P of
// its accumulated energy (past events plus the current one) reaches u, so a fresh particle breaks
// in one event of energy W with probability P(W) (LIGGGHTS-PFM fix_break_particle).
#include "comminute/breakage/criteria/breakage_criterion.hpp"
#include "comminute/fracture/vogel_peukert.hpp"

namespace comminute::breakage {

using VogelPeukertParameters = fracture::VogelPeukertModel;  // f_mat, threshold_product

class VogelPeukert final : public BreakageCriterion {
 public:
  explicit VogelPeukert(const VogelPeukertParameters& p) : p_(p) {}
  std::string name() const override { return "vogel_peukert"; }
  void attach(ParticleStore& p) override;
  void initialize(ParticleStore& p, std::size_t i, double d, Rng& rng) const override;
  bool breaks(const ParticleStore& p, std::size_t i, double d,
              const StressingEvent& e) const override;
  void survive(ParticleStore& p, std::size_t i, double d, const StressingEvent& e) const override;
  double strength(const ParticleStore& p, std::size_t i, double d) const override;
  std::string strength_unit() const override { return "J/kg"; }
  double probability(double d, const StressingEvent& e) const override;
  bool energy_based() const override { return true; }
  // P for an accumulated excess energy (J/kg) at diameter d.
  double probability_of_excess(double d, double excess) const;
  double threshold(double d) const { return p_.threshold(d); }  // W_min(x), J/kg

 private:
  VogelPeukertParameters p_;
  std::size_t accumulated_ = 0, breakability_ = 0;
};

}  // namespace comminute::breakage
