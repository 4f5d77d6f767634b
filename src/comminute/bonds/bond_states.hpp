#pragma once
// The states of many bonds, split by how a step uses them (hot/cold), so that the step streams
// only what it needs: BondState (bond_law.hpp) is one bond's whole record as the laws see it; here
// it is kept in three arrays of plain records, by bond:
// - live: what every step of the parallel bond reads and writes (the frame and what it carries);
// - shape: what a step reads but never writes, unless the bond fails (geometry, strengths, mode);
// - rest: what only some laws or failures touch (the cohesive slip, damage, dissipated energy).
// Read-only fields sit apart from written ones, so that their cache lines are not written back.
// Checkpoints still hold whole BondState records (BondList::save), so the split is not part of
// the file format.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "comminute/core/vec3.hpp"

namespace comminute::bonds {

struct BondState;
enum class FailureMode : std::uint8_t;

struct BondLive {
  Vec3 normal;               // BondState::normal
  Vec3 shear_force;          // BondState::shear_force
  Vec3 moment;               // BondState::moment
  double strain_energy = 0;  // BondState::strain_energy
};

struct BondShape {
  double length0 = 0, radius = 0, tensile_strength = 0, shear_strength = 0;
  FailureMode failed{};
};

struct BondRest {
  Vec3 slip;
  double damage = 0, dissipated = 0;
};

class BondStates {
 public:
  std::vector<BondLive> live;
  std::vector<BondShape> shape;
  std::vector<BondRest> rest;

  std::size_t size() const { return live.size(); }
  bool empty() const { return live.empty(); }
  void reserve(std::size_t n);
  void resize(std::size_t n);
  void push_back(const BondState& s);
  // Bond b's whole record, and back.
  BondState get(std::size_t b) const;
  void set(std::size_t b, const BondState& s);
  // Moves bond `from` to place `to` (compaction).
  void move(std::size_t from, std::size_t to);
  // Bytes held at the arrays' capacities.
  std::size_t capacity_bytes() const;
  // All records in bond order (checkpoints), and from them.
  std::vector<BondState> records() const;
  void assign(const std::vector<BondState>& records);
};

}  // namespace comminute::bonds
