#pragma once
// How the fragments of a parent share its mass. By default each fragment keeps the mass the
// progeny draw gave it (the parent's mass shared by volume: one density). A rule (the texture
// module, whose fragments have densities of their own) may redistribute the masses before the
// fragments are placed and given velocities, so placement, momentum, energy and the fragment log
// all see the final masses. A rule must keep the sum of the masses.
#include <cstddef>
#include <vector>

#include "comminute/particles/particle_store.hpp"

namespace comminute::breakage {

class FragmentMassRule {
 public:
  virtual ~FragmentMassRule() = default;
  // Parent in slot `parent`; fragments of final radii `radii` (m), in the order their ids will be
  // given; `masses` (kg) in, redistributed out with the same sum.
  virtual void share(const ParticleStore& p, std::size_t parent, const std::vector<double>& radii,
                     std::vector<double>& masses) = 0;
};

}  // namespace comminute::breakage
