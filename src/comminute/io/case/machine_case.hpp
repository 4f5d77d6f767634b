#pragma once
// Reads the machine parts of a DEM case that act on the run rather than on the particles' law:
// [[outlets]] (remove and log), [[sampling_planes]] (count crossings), the `control` table of a
// [[walls]] entry (servo or dead-weight wall) and [[stop]] (end the run when a wall force or
// stress reaches a value). Each adds one engine module when its tables are present. Every key is
// documented in docs/case-file.md.
#include <vector>

#include "comminute/core/case_table.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::io {

// `walls` are the [[walls]] tables, in the order of sim.walls.
void add_machines(const CaseTable& root, const std::vector<CaseTable>& walls, Simulation& sim);

}  // namespace comminute::io
