#pragma once
// One failed bond, as the failure log keeps it (plain data: checkpointed as is).
#include <cstdint>

#include "comminute/bonds/bond_law.hpp"
#include "comminute/core/vec3.hpp"

namespace comminute::bonds {

enum class FailureCause : std::uint8_t { tensile = 1, shear = 2, particle_removed = 3 };

struct BondFailure {
  double time = 0;         // s
  std::uint64_t id_i = 0;  // the two particles' ids
  std::uint64_t id_j = 0;
  Vec3 position;      // m, the bond's contact point when it failed
  double energy = 0;  // J, dissipated by the bond over its life (damage + release)
  FailureCause cause = FailureCause::tensile;
  std::uint8_t padding[7] = {};  // written to checkpoints: no undefined bytes
};

const char* cause_name(FailureCause c);

}  // namespace comminute::bonds
