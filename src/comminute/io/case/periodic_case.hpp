#pragma once
// The [periodic] table: periodic bounds along coordinate axes, or a rotationally periodic sector
// (docs/case-file.md, [periodic]). Refuses input the ghost exchange cannot honour: bounds shorter
// than 2 × (largest diameter + skin), a wall that is not the same on both sides of a periodic
// face, a sector with gravity or wall motion that the rotation does not map onto itself.
#include <limits>

#include "comminute/core/case_table.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::io {

// What the insertions can create: the largest diameter (m) and the box the particles start in.
struct ParticleReach {
  double largest_diameter = 0;
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
};

// Reads [periodic] when present and sets it on the simulation (walls and insertions read).
void read_periodic(const CaseTable& root, Simulation& sim, const ParticleReach& reach);

}  // namespace comminute::io
