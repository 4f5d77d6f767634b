#pragma once
// Builds a DEM simulation from a case file: [simulation], [contact], [materials.*],
// [interaction] (+ [[interaction.pairs]]), [[walls]], [[insert]]. Every key is documented in
// docs/case-file.md. Other readers ([output], breakage) read their own tables from the same
// CaseFile; the caller rejects unknown keys once all have read.
#include <memory>
#include <string>
#include <vector>

#include "comminute/core/case_table.hpp"
#include "comminute/engine/simulation.hpp"
#include "comminute/engine/time_step_policy.hpp"
#include "comminute/geometry/region.hpp"

namespace comminute::io {

struct DemCase {
  std::unique_ptr<Simulation> sim;
  double end_time = 0;                        // s
  std::unique_ptr<TimeStepPolicy> time_step;  // knows the inserted sizes
  std::string time_step_note;                 // how the step was chosen, for the log
  std::vector<std::string> warnings;
};

// An [[insert]] or outlet region table: shape "box" (lo, hi) or "cylinder" (center, axis, radius,
// length).
Region read_region(const CaseTable& t);

// Builds everything but the time step: modules (breakage) may still be added.
DemCase build_dem_case(const CaseTable& root);
// Sets the time step once, when every module is in (TimeStepPolicy).
void decide_time_step(DemCase& c);

// Loads a case file that holds only DEM tables (benchmarks, tools): builds it and rejects unknown
// keys. `comminute run` reads more tables ([output], breakage) and does its own loading.
DemCase load_plain_dem_case(const std::filesystem::path& path);

}  // namespace comminute::io
