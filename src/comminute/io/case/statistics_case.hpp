#pragma once
// Reads [grid_statistics] and [bed_statistics] (docs/case-file.md) into their observer modules
// (analysis/grid_statistics.hpp, analysis/bed_statistics.hpp). Call after the walls are built.
#include "comminute/core/case_table.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::io {

void add_statistics(const CaseTable& root, Simulation& sim);

}  // namespace comminute::io
