#include "comminute/breakage/criteria/vogel_peukert.hpp"

#include <algorithm>
#include <cmath>

namespace comminute::breakage {

void VogelPeukert::attach(ParticleStore& p) {
  accumulated_ = p.add_field("vogel_peukert.accumulated", 0.0);    // J/kg, sum of excess energies
  breakability_ = p.add_field("vogel_peukert.breakability", 1.0);  // uniform draw u
}

void VogelPeukert::initialize(ParticleStore& p, std::size_t i, double, Rng& rng) const {
  p.field(accumulated_)[i] = 0.0;
  p.field(breakability_)[i] = rng.uniform();
}

double VogelPeukert::probability_of_excess(double d, double excess) const {
  return p_.probability(d, excess);  // Vogel & Peukert 2003, incremental form
}

bool VogelPeukert::breaks(const ParticleStore& p, std::size_t i, double d,
                          const StressingEvent& e) const {
  const double excess = p.field(accumulated_)[i] + std::max(0.0, e.specific_energy - threshold(d));
  return probability_of_excess(d, excess) >= p.field(breakability_)[i];
}

void VogelPeukert::survive(ParticleStore& p, std::size_t i, double d,
                           const StressingEvent& e) const {
  p.field(accumulated_)[i] += std::max(0.0, e.specific_energy - threshold(d));
}

double VogelPeukert::strength(const ParticleStore& p, std::size_t i, double d) const {
  // Remaining specific energy (above threshold) this particle can take in one event.
  const double u = p.field(breakability_)[i];
  const double total = -std::log1p(-u) / (p_.f_mat * d);
  return threshold(d) + std::max(0.0, total - p.field(accumulated_)[i]);
}

double VogelPeukert::probability(double d, const StressingEvent& e) const {
  return probability_of_excess(d, std::max(0.0, e.specific_energy - threshold(d)));
}

namespace {
std::unique_ptr<BreakageCriterion> make(const CaseTable& t, const Material&) {
  return std::make_unique<VogelPeukert>(fracture::read_vogel_peukert(t));
}
const bool registered = CriterionRegistry::add("vogel_peukert", &make);
}  // namespace

}  // namespace comminute::breakage
