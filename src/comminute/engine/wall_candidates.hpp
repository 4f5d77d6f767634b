#pragma once
// Which particle–wall contacts the force loop must check: one candidate per particle, wall and
// feature (face, edge, vertex) within the skin of the particle's reach sphere at the last search,
// with each mesh wall's element lists (WallElementLists), how far each wall has travelled since
// (the search is due again past skin/2) and which walls are checked every step (their surface
// moves: Wall::full_scan). The wall-contact state store (ContactStateStore) runs parallel to the
// candidates: a search carries the state of each touching contact to its new index by (particle
// id, wall, feature). PairTracker owns one and searches it at each rebuild and in-place update.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "comminute/contact/contact_state.hpp"
#include "comminute/core/archive.hpp"
#include "comminute/engine/wall_contact.hpp"
#include "comminute/engine/wall_element_lists.hpp"
#include "comminute/geometry/wall.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute {

class WallCandidates {
 public:
  using Walls = std::vector<std::unique_ptr<Wall>>;

  const std::vector<WallContactRecord>& records() const { return records_; }
  // Per wall and particle, the elements within the skin at the last search.
  const WallElementLists& elements() const { return elements_; }
  // Wall k moved `distance` (m) this step; the largest travel of a wall since the search (m).
  void moved(std::size_t k, double distance) { travel_[k] += distance; }
  double largest_travel() const;
  // Before a search: calls f(record, index) on each touching contact, which may change its
  // feature key (periodic wraps); the search then carries the contact under its new key.
  template <class F>
  void rekey(const ContactStateStore& state, F f) {
    for (std::size_t q = 0; q < records_.size(); ++q)
      if (state.active[q]) f(records_[q], q);
  }

  // Searches the owned particles' candidates at their current spheres, on all threads; the state
  // of the touching contacts follows. The travel restarts from 0.
  void build(const ParticleStore& p, const Walls& walls, double skin, ContactStateStore& state);
  // After parents were removed and fragments appended: the kept candidates move to their new slots
  // (to_new: old slot -> new slot or NeighborList::none when removed, n_kept slots kept) with
  // their state, and each appended fragment's are searched at its reach sphere (x_reach, r_reach:
  // per slot).
  void remap(const ParticleStore& p, const Walls& walls, double skin,
             std::span<const std::uint32_t> to_new, std::size_t n_kept,
             std::span<const Vec3> x_reach, std::span<const double> r_reach,
             ContactStateStore& state);
  // After new particles took the slots flagged in `renewed` (of the n_old slots searched) and
  // fragments were appended from n_old on: the renewed slots' candidates become the new
  // particles', afresh, and the appended fragments' are searched at their reach spheres.
  void renew(const ParticleStore& p, const Walls& walls, double skin,
             const std::vector<std::uint8_t>& renewed, std::size_t n_old,
             std::span<const Vec3> x_reach, std::span<const double> r_reach,
             ContactStateStore& state);

  void save(Archive& a) const;
  // Checks every entry against the n_build particles the lists were built with. The element
  // lists are not checkpointed: the force loop searches until the next build.
  void load(const Archive& a, std::size_t n_build);

 private:
  // Appends particle i's candidates on wall w found at the sphere (x, r); true when the wall
  // listed its elements within the skin in `elements`.
  bool add(const ParticleStore& p, const Walls& walls, std::uint32_t i, std::uint32_t w,
           const Vec3& x, double r, double skin, std::vector<std::uint32_t>& elements,
           std::vector<WallContact>& found, std::vector<WallContactRecord>& into) const;
  // Candidates (and element lists) of the fragments appended from slot n_kept on.
  void add_appended(const ParticleStore& p, const Walls& walls, double skin, std::size_t n_kept,
                    std::span<const Vec3> x_reach, std::span<const double> r_reach,
                    WallElementLists& lists, std::vector<WallContactRecord>& into) const;

  std::vector<WallContactRecord> records_;  // by particle, then wall and feature
  WallElementLists elements_;
  std::vector<std::uint8_t> full_scan_;  // per wall: surface moves, check every step
  std::vector<double> travel_;           // per wall: distance moved since the search (m)
};

}  // namespace comminute
