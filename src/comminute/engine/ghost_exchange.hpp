#pragma once
// Periodic boundaries as ghost particles. At each neighbour-list rebuild the owned particles are
// wrapped into the domain and every owned particle within its reach (its radius + the largest
// radius + skin) of a periodic face gets a ghost: its copy under one of the map's images,
// appended after the owned range of the store. Every step the ghosts are made again from their
// owners (same plan until the next rebuild, so the pair list's slots stay valid), the force loops
// see them as ordinary particles, and the forces and torques they received are folded back onto
// their owners (rotated back in a sector). The engine drops the ghosts after the modules'
// post_force; the rest of the step, outputs and checkpoints see the owned particles only.
//
// The exchange (owner slot, image) is what a domain decomposition over MPI would send to the
// neighbouring rank; here the neighbour is the domain itself.
#include <cstdint>
#include <vector>

#include "comminute/contact/contact_state.hpp"
#include "comminute/core/archive.hpp"
#include "comminute/geometry/periodic_map.hpp"
#include "comminute/neighbor/neighbor_list.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

class GhostExchange {
 public:
  PeriodicMap map;

  bool active() const { return map.active(); }
  // Registers the per-particle image labels (fields "periodic.image_x|y|z": how many periods or
  // turns the particle has been wrapped; they move and checkpoint with the particles).
  void attach(ParticleStore& p);
  // At a rebuild, with no ghosts in the store: wraps the owned particles into the domain (a
  // sector turns velocity and angular velocity with the position; momentum magnitude is kept),
  // then plans one ghost per (owned particle, image) within reach of a face.
  void wrap(ParticleStore& p);
  // The particles the last wrap moved (by id) and the image each was moved by.
  struct Wrapped {
    std::uint64_t id;
    PeriodicMap::Shift shift;
  };
  const std::vector<Wrapped>& wrapped() const { return wrapped_; }
  void plan(const ParticleStore& p, double skin);
  // Appends the planned ghosts from their owners' current state.
  void append(ParticleStore& p) const;
  // The image label of every slot (owned and ghosts), for the neighbour list's carry.
  const std::vector<std::uint64_t>& labels(const ParticleStore& p);
  // After a rebuild: turns the springs of the pairs carried to another turn of a sector.
  void turn_carried(const NeighborList::Carry& carried, ContactStateStore& state) const;
  // Adds each ghost's force and torque to its owner (rotated back) and zeroes the ghost's.
  void fold(ParticleStore& p) const;

  std::size_t size() const { return owner_.size(); }
  // Ghost g (slot owned + g while present): its owner slot and its image.
  std::uint32_t owner(std::size_t g) const { return owner_[g]; }
  const PeriodicMap::Shift& image(std::size_t g) const { return map.images()[image_[g]]; }
  // Where slot s is, and a point given in slot s's frame brought into its owner's frame: for the
  // ghosts of the last plan even while they are not in the store (n_owned: the owned count).
  Vec3 position(const ParticleStore& p, std::size_t slot, std::size_t n_owned) const;
  Vec3 to_owner_frame(std::size_t slot, std::size_t n_owned, const Vec3& x) const;
  Vec3 from_owner_frame(std::size_t slot, std::size_t n_owned, const Vec3& x) const;

  void save(Archive& a) const;
  // Reads the plan; checks it against the owned particles.
  void load(const Archive& a, std::size_t n_owned);

 private:
  std::vector<std::uint32_t> owner_;  // per planned ghost
  std::vector<std::uint8_t> image_;   // index into map.images()
  std::size_t f_label_[3] = {0, 0, 0};
  std::vector<std::uint64_t> labels_;  // scratch
  std::vector<Wrapped> wrapped_;       // by the last wrap, sorted by id
  PeriodicMap::Shift label_of(const ParticleStore& p, std::size_t owned_slot) const;
};

}  // namespace comminute
