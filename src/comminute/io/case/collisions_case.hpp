#pragma once
// Reads [collisions] (the collision log, analysis/collision_log.hpp) and adds its module. Every
// key is documented in docs/case-file.md.
#include "comminute/core/case_table.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::io {

// Call after the materials and walls are read (their names name the contact types).
void add_collision_log(const CaseTable& root, Simulation& sim);

}  // namespace comminute::io
