#pragma once
// Progeny models: what a breaking particle turns into. One interface, chosen per material by name
// in the case file ([materials.<m>.breakage.progeny] model = "t10", the default); the model's
// factory reads its own keys from that table.
#include <memory>
#include <string>

#include "comminute/core/case_table.hpp"
#include "comminute/core/registry.hpp"
#include "comminute/fracture/breaking_median.hpp"
#include "comminute/fracture/progeny_distribution.hpp"

namespace comminute::breakage {

using fracture::ProgenyDistribution;  // the progeny curve of docs/models.md eq. P3

class ProgenyModel {
 public:
  virtual ~ProgenyModel() = default;
  virtual std::string name() const = 0;
  // Breakage index t10 (%) of an event of specific energy `specific_energy` (J/kg) on a parent
  // whose median fracture energy is `e50` (J/kg).
  virtual double t10(double specific_energy, double e50) const = 0;
  // Which E50 t10() wants (key e50b): the median of the particles that break at the event's
  // energy (default) or the class median; the caller asks the criterion for it
  // (BreakageCriterion::t10_median_energy).
  virtual fracture::E50bRule e50b_rule() const { return fracture::E50bRule::class_median; }
  // Cumulative progeny size distribution of a parent of diameter d (m) at breakage index t10.
  virtual ProgenyDistribution distribution(double d, double t10) const = 0;
};

using ProgenyRegistry = Registry<ProgenyModel, const CaseTable&>;

}  // namespace comminute::breakage
