#pragma once
// Reads [coarse_graining] (particles/coarse_graining.hpp). The DEM case reader applies it to the
// material pairs; the grid statistics and the particle snapshots read it for their per-primary
// outputs. Every key is documented in docs/case-file.md.
#include "comminute/core/case_table.hpp"
#include "comminute/engine/simulation.hpp"
#include "comminute/particles/coarse_graining.hpp"

namespace comminute::io {

// The case's coarse graining (scale 1 without the table).
CoarseGraining coarse_graining_of(const CaseTable& root);
// Refuses what coarse graining does not scale: call after [contact] is read.
void check_coarse_graining(const CaseTable& root, const Simulation& sim);

}  // namespace comminute::io
