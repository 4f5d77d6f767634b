#pragma once
// A contact that ended in a force computation (its bodies separated), as the collision record
// left it: the force loops list them, when the contact model keeps that record, before the
// contact's state is cleared; Simulation::ended_contacts() holds those of the last force
// computation, in contact-list order (pairs, then walls), the same for any thread count.
#include <cstdint>

#include "comminute/contact/collision_record.hpp"

namespace comminute {

struct EndedContact {
  std::uint32_t i = 0;  // slot of the particle (pairs: the first of the pair)
  std::uint32_t j = 0;  // pairs: slot of the other particle (may be a ghost); walls: wall index
  bool wall = false;
  CollisionTotals totals;
};

}  // namespace comminute
