#include "comminute/engine/particle_record.hpp"

#include <algorithm>

namespace comminute {

namespace {
// A per-particle field the breakage module may have registered (the engine does not need it).
const std::vector<double>* optional_field(const ParticleStore& p, const char* name) {
  return p.has_field(name) ? &p.field(p.field_index(name)) : nullptr;
}
}  // namespace

ParticleRecorder::ParticleRecorder(const ParticleStore& p)
    : p_(p),
      target_(optional_field(p, "breakage.target_radius")),
      generation_(optional_field(p, "breakage.generation")) {}

ParticleRecord ParticleRecorder::operator()(std::size_t i, double time, std::uint64_t step,
                                            std::uint32_t site, std::int32_t direction) const {
  ParticleRecord r;
  r.time = time;
  r.step = step;
  r.id = p_.id[i];
  r.mass = p_.physical_mass(i);
  r.diameter = 2 * std::max(p_.radius[i], target_ ? (*target_)[i] : 0.0);
  r.site = site;
  r.direction = direction;
  r.generation = generation_ ? static_cast<std::uint32_t>((*generation_)[i]) : 0;
  r.material = p_.material[i];
  return r;
}

}  // namespace comminute
