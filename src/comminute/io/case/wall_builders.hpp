#pragma once
// Walls from [[walls]] tables, by `type` (plane, box, cylinder): one builder per type.
#include <memory>

#include "comminute/core/case_table.hpp"
#include "comminute/core/registry.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute::io {

using WallBuilderRegistry = Registry<Wall, const CaseTable&>;

// Reads the shape through the registry, then the common keys (name, material, motion).
std::unique_ptr<Wall> build_wall(const CaseTable& t, std::size_t index, const Simulation& sim);

}  // namespace comminute::io
