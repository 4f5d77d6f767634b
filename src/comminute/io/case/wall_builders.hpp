#pragma once
// Walls from [[walls]] tables: the wall type by name from WallRegistry (each type reads the keys of
// its shape), then the keys common to all walls.
#include <memory>

#include "comminute/core/case_table.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::io {

// Creates the wall of `type` through WallRegistry, then reads the common keys (name, material,
// velocity, angular_velocity, rotation_center).
std::unique_ptr<Wall> build_wall(const CaseTable& t, std::size_t index, const Simulation& sim);

}  // namespace comminute::io
