#pragma once
// The floating roll of a generated roll press (`hpgr` walls with a `floating` table): roll 2
// translates along the line of centres towards roll 1, pushed by a constant force (a hydraulic
// cylinder), as a free body with mass and damping, its gap limited below by `min_gap` (the
// zero-gap stop). Read here into a force control (engine/wall_control.hpp, mode floating); keys
// in docs/case-file.md ("Floating roll").
#include <optional>

#include "comminute/core/case_table.hpp"
#include "comminute/engine/wall_control.hpp"
#include "comminute/geometry/wall.hpp"

namespace comminute::io {

// The control of wall `index` (w, built from [[walls]] table t) when it is the floating roll of a
// roll press; none for every other wall.
std::optional<WallControlSpec> floating_roll_control(const CaseTable& t, std::size_t index,
                                                     const Wall& w);

}  // namespace comminute::io
