#pragma once
// The bonds of a run as plain arrays: the two particles of bond b by id (id_i[b], id_j[b]: the
// particle store's identity, never reused), their slots as last seen (slot_i, slot_j) and the
// bond's state, split into hot and cold records (BondStates, bond_states.hpp). Bonds outlive the
// neighbour list (a stretched bond may leave it), so they are not kept in the contact-state store;
// like the contact history across list rebuilds, they follow the particles by id. locate() checks
// each cached slot against the store's id array and re-resolves all slots by id only when one no
// longer matches (after a cell sort, an insertion or a compaction).
#include <cstdint>
#include <vector>

#include "comminute/bonds/bond_law.hpp"
#include "comminute/bonds/bond_states.hpp"
#include "comminute/core/archive.hpp"
#include "comminute/particles/particle_store.hpp"

namespace comminute::bonds {

class BondList {
 public:
  std::vector<std::uint64_t> id_i, id_j;
  std::vector<std::uint32_t> slot_i, slot_j;
  BondStates state;

  std::size_t size() const { return id_i.size(); }
  void reserve(std::size_t n);
  void add(std::uint64_t a, std::uint32_t sa, std::uint64_t b, std::uint32_t sb,
           const BondState& s);
  // Whether every cached slot still holds its particle (checked on all threads).
  bool current(const ParticleStore& p) const;
  // Brings the slots up to date; returns the bonds one of whose particles is gone (in order).
  std::vector<std::size_t> locate(const ParticleStore& p);
  // Removes the bonds flagged in `gone` (one flag per bond), keeping the order of the others.
  void remove(const std::vector<std::uint8_t>& gone);

  void save(Archive& a, const std::string& prefix) const;
  // Reads what save() wrote; slots are re-resolved by the next locate().
  void load(const Archive& a, const std::string& prefix);

  static constexpr std::uint32_t none = 0xFFFFFFFFu;
};

}  // namespace comminute::bonds
