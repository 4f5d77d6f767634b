#pragma once
// Walls from [[walls]] tables: the wall type by name from WallRegistry (each type reads the keys of
// its shape), or a generated machine of several walls from WallGroupRegistry; then the keys common
// to all walls.
#include <memory>
#include <vector>

#include "comminute/core/case_table.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::io {

// The walls of table t: one wall of `type` through WallRegistry with the common keys (name,
// material, velocity, angular_velocity, rotation_center), or the parts of a machine of `type`
// through WallGroupRegistry, each named "<name>_<part>", all of the table's material (a machine's
// parts move by themselves: velocity, angular_velocity, rotation_center and control refused).
std::vector<std::unique_ptr<Wall>> build_walls(const CaseTable& t, std::size_t index,
                                               const Simulation& sim);

}  // namespace comminute::io
