#pragma once
// Settings the breakage module hands to its collaborators (stressing events, fragment growth,
// replacement): per-material breakage settings, the module's options and the per-particle fields
// the module registers for all of them.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "comminute/breakage/criteria/breakage_criterion.hpp"
#include "comminute/breakage/placement/placement_model.hpp"
#include "comminute/breakage/progeny/progeny_sizes.hpp"
#include "comminute/breakage/progeny/t10_progeny.hpp"

namespace comminute::breakage {

// The force of a stressing event (docs/breakage.md, "Stressing events").
enum class ForceMeasure {
  largest_contact,  // the largest single elastic normal contact force (Cleary & Sinnott 2015)
  contact_sum       // the sum of the elastic normal contact forces on the particle
};

// The specific energy the progeny (t10) is sized at (docs/breakage.md, "Stressing energy").
enum class SizingEnergy {
  stressing,   // the event's stressing energy: absorbed work plus the approach energy still due
  at_fracture  // the energy absorbed up to the instant of fracture (the rule before issue 8)
};

// How fragments are kept from taking the step below the floor (docs/breakage.md, time_step_floor).
enum class FloorRule {
  fines,           // fragments whose Rayleigh time is below the floor's become fines
  density_scaling  // they stay, with their inertia scaled up to the floor's Rayleigh time
};

// Breakage settings of one material.
struct MaterialBreakage {
  std::unique_ptr<BreakageCriterion> criterion;
  std::unique_ptr<ProgenyModel> progeny = std::make_unique<T10Progeny>(T10Progeny::illustrative());
  double reference_energy = -1;      // J/kg, E50b for t10 when the criterion has no median
  double min_breakable_size = 0;     // m, smaller particles never break
  double min_fragment_size = 0;      // m, smaller fragments become fines
  double min_fragment_ratio = 0.05;  // fragments below this fraction of the parent diameter: fines
  FinesRule fines = FinesRule::particles;
  double release_fraction = 0;  // eta: fraction of the absorbed energy given as radial speed
  FragmentSpin fragment_spin = FragmentSpin::parent;  // how fragments inherit the parent's spin
  ForceMeasure force_measure = ForceMeasure::largest_contact;  // the event's peak force
  SizingEnergy sizing_energy = SizingEnergy::stressing;        // E of the t10 relation
};

// Settings of material k at [k], or empty (material k never breaks).
using BreakageMaterials = std::vector<std::optional<MaterialBreakage>>;

struct BreakageOptions {
  PlacementOptions placement;  // of the default placement model when placement_model is empty
  std::shared_ptr<const FragmentPlacement> placement_model;
  double growth_overlap_ratio = 0.001;  // largest overlap growth may create, fraction of the
                                        // smaller radius (each growth step pumps in U(eps))
  double growth_step = 0.005;  // largest radius increment per step, fraction of the final radius
  // false ("capped"): growth stops where an overlap reaches growth_overlap_ratio (a fragment
  // under a sustained load never reaches full size); true ("pushing"): growth may deepen every
  // overlap by growth_overlap_ratio per step, so a loaded fragment grows against its load
  bool growth_pushes = false;
  int event_end_steps = 20;      // steps without new loading that end a stressing event
  int replacement_interval = 1;  // replace broken parents every this many steps (batched; each
                                 // replacement makes the engine rebuild its neighbour list)
  bool log_all_events = false;   // also log events that did not break (probability plots)
  // Only particles of a generation below this break (1: only the initial set); default unlimited.
  std::uint32_t max_generations = std::numeric_limits<std::uint32_t>::max();
  double output_interval = 0;  // s between ledger rows / table rewrites (0: every 1000 steps)
  // The step never falls below this fraction of the step of the inserted sizes (docs/models.md,
  // "Time step"); 0: off, the step follows the smallest fragment.
  double time_step_floor = 0.1;
  FloorRule floor_rule = FloorRule::fines;
};

// Indices of the per-particle fields every collaborator reads.
struct BreakageFields {
  std::size_t initialized = 0;  // 1 once strength is drawn
  std::size_t generation = 0;   // 0 for particles of the initial set
  std::size_t parent_id = 0;    // id of the particle a fragment came from (0: initial set)
  std::size_t target = 0;       // m, final radius while growing (0 otherwise)
  std::size_t mass_scale = 0;   // density scaling s >= 1 (registered when time_step_floor > 0)
};

}  // namespace comminute::breakage
