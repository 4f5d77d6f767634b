#pragma once
// Breakage criteria: when does a stressed particle break? One interface, chosen per material by
// name in the case file ([materials.X.breakage] criterion = "tavares" | "peak_force" |
// "composition_peak_force" | "vogel_peukert"). A criterion keeps its per-particle state (fracture
// energy, damage, random strength factor, accumulated energy) in named fields of the particle
// store, so the state moves with the particles and is checkpointed with them.
//
// The breakage module builds one StressingEvent per particle (see docs/breakage.md for when an
// event starts and ends), asks breaks() every step while the event lasts (breakage is decided
// during loading) and calls survive() once when an event ends without breakage.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "comminute/core/case_table.hpp"
#include "comminute/core/registry.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/fracture/breaking_median.hpp"
#include "comminute/particles/material.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute::breakage {

// The loading a particle has received in the current stressing event.
struct StressingEvent {
  double specific_energy =
      0;                  // J/kg, energy absorbed by the particle (its share e of the contact work)
  double peak_force = 0;  // N, peak of the largest single elastic normal contact force on the
                          // particle (or of their sum: the material's force_measure)
};

class BreakageCriterion {
 public:
  virtual ~BreakageCriterion() = default;
  virtual std::string name() const = 0;
  // Registers the per-particle fields this criterion keeps (idempotent).
  virtual void attach(ParticleStore& p) = 0;
  // Gives particle i (diameter d, m) its own strength: called once for every particle, fragments
  // included, so every generation draws afresh for its own size.
  virtual void initialize(ParticleStore& p, std::size_t i, double d, Rng& rng) const = 0;
  // True when the event so far breaks particle i (diameter d).
  virtual bool breaks(const ParticleStore& p, std::size_t i, double d,
                      const StressingEvent& e) const = 0;
  // The event ended without breakage: damage / accumulation.
  virtual void survive(ParticleStore& /*p*/, std::size_t /*i*/, double /*d*/,
                       const StressingEvent& /*e*/) const {}
  // Current strength for the event log: specific fracture energy (J/kg) for energy criteria,
  // critical force (N) for force criteria; see strength_unit().
  virtual double strength(const ParticleStore& p, std::size_t i, double d) const = 0;
  virtual std::string strength_unit() const = 0;
  // Accumulated damage D in [0, 1) (0 for criteria without damage).
  virtual double damage(const ParticleStore&, std::size_t) const { return 0.0; }
  // Model probability that a fresh particle of diameter d breaks in one event with absorbed
  // specific energy `energy` (J/kg) or peak force `force` (N); the plotted model curve.
  virtual double probability(double d, const StressingEvent& e) const = 0;
  // True when probability() depends on the absorbed specific energy (the model curve of
  // breakage_model.csv is then plotted against it); false for force criteria.
  virtual bool energy_based() const = 0;
  // Median specific fracture energy of size d (J/kg) used by the t10 model (E50b), or a negative
  // number when the criterion has none (the progeny table then needs reference_energy).
  virtual double median_fracture_energy(double /*d*/) const { return -1.0; }
  // E50b of the t10 relation for an event of stressing energy `specific_energy` (J/kg) on a
  // particle of size d (docs/models.md eq. P1b) under `rule` (ProgenyModel::e50b_rule()); criteria
  // without a fracture-energy distribution answer median_fracture_energy(d).
  virtual double t10_median_energy(double d, double /*specific_energy*/,
                                   fracture::E50bRule /*rule*/) const {
    return median_fracture_energy(d);
  }
  // The relative strengths f_rel,k of the phases the criterion weighs by the particle's
  // composition (composition_peak_force, tavares with relative_strength), or nullptr.
  virtual const std::vector<double>* relative_strength() const { return nullptr; }
};

// A criterion's factory reads its own keys from the material's [materials.<m>.breakage] table;
// the material gives the elastic constants of the energy partition.
using CriterionRegistry = Registry<BreakageCriterion, const CaseTable&, const Material&>;

}  // namespace comminute::breakage
