#pragma once
// One particle as an observation module logged it at an event: taken out by an outlet (the
// product stream of a mill) or counted crossing a sampling plane (the flow through a section).
// Both logs hold the same record, filled by one ParticleRecorder, so they agree on what a
// particle's mass, size and generation are. Trivially copyable: checkpointed as an array (its
// layout is part of the checkpoint format, io/output/checkpoint.hpp).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "comminute/particles/particle_store.hpp"

namespace comminute {

struct ParticleRecord {
  double time = 0;               // s
  std::uint64_t step = 0;        // the step of the event
  std::uint64_t id = 0;          // particle id
  double mass = 0;               // kg (physical mass)
  double diameter = 0;           // m (the final size of a growing fragment)
  std::uint32_t site = 0;        // index of the outlet, or of the sampling plane, that logged it
  std::int32_t direction = 0;    // a crossing: +1 along the plane's normal, -1 against; removal: 0
  std::uint32_t generation = 0;  // breakage generation (0: initial particle, or no breakage)
  std::uint16_t material = 0;
  std::uint16_t pad = 0;
};

// Fills records from a particle store. The breakage fields (target radius, generation) are looked
// up once, when it is made: make one per pass over the particles.
class ParticleRecorder {
 public:
  explicit ParticleRecorder(const ParticleStore& p);
  ParticleRecord operator()(std::size_t i, double time, std::uint64_t step, std::uint32_t site,
                            std::int32_t direction = 0) const;

 private:
  const ParticleStore& p_;
  const std::vector<double>* target_ = nullptr;      // "breakage.target_radius", when present
  const std::vector<double>* generation_ = nullptr;  // "breakage.generation", when present
};

}  // namespace comminute
