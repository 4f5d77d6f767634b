#pragma once
// The phase weighting of a composition-dependent criterion: w(C) = sum_k C_k f_rel,k, C_k the
// particle's volume fraction of phase k (per-particle fields "composition.0", "composition.1",
// ..., written by the texture module; phase 0 defaults to 1, the others to 0) and f_rel,k the
// phase's relative strength. Shared by composition_peak_force (Cleary & Sinnott, Minerals Eng. 74
// (2015) 178, docs/models.md eq. C2) and the phase-weighted option of tavares (eq. C2b).
#include <cstddef>
#include <vector>

#include "comminute/core/case_table.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute::breakage {

class PhaseWeights {
 public:
  PhaseWeights() = default;
  explicit PhaseWeights(std::vector<double> relative_strength)
      : relative_strength_(std::move(relative_strength)) {}
  // Registers the composition fields (idempotent).
  void attach(ParticleStore& p);
  // w = sum_k C_k f_rel,k of particle i (1 when there are no phases).
  double weight(const ParticleStore& p, std::size_t i) const;
  // w of the default composition (all phase 0): f_rel,0 (1 when there are no phases).
  double nominal() const { return relative_strength_.empty() ? 1.0 : relative_strength_[0]; }
  bool empty() const { return relative_strength_.empty(); }
  const std::vector<double>& relative_strength() const { return relative_strength_; }

 private:
  std::vector<double> relative_strength_;  // f_rel,k per phase
  std::vector<std::size_t> composition_;   // field indices
};

// Reads the list `relative_strength` (non-negative, one per phase); `required` refuses a missing
// or empty list, otherwise a missing key gives no phases.
PhaseWeights read_phase_weights(const CaseTable& t, bool required);

}  // namespace comminute::breakage
