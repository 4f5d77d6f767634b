#pragma once
// Builds the breakage module from a case file: [materials.<name>.breakage] per material (the
// criterion by name and its parameters, progeny, fines, minimum sizes) and the optional
// [breakage] table (placement, growth, events, outputs). Every key: docs/breakage.md.
#include "comminute/breakage/breakage_module.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/engine/simulation.hpp"
#include "comminute/io/case/dem_case.hpp"

namespace comminute::io {

// When at least one material has a breakage table, appends a BreakageModule (and a size
// distribution observer; both offer their tables to the output module) to sim.modules and
// returns the module; otherwise returns nullptr. Call after build_dem_case and before
// decide_time_step() (the module announces its smallest fragment to the time-step policy) and
// CaseFile::reject_unknown().
breakage::BreakageModule* add_breakage(const CaseTable& root, DemCase& dem);

}  // namespace comminute::io
