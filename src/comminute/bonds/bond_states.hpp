#pragma once
// The states of many bonds, split by how a step uses them (hot/cold), so that the step streams
// only what it needs: BondState (bond_law.hpp) is one bond's whole record as the laws see it; here
// its fields are kept as arrays by bond (structure of arrays), so that the step's vector loop
// reads and writes them in place, a whole vector of bonds at once:
// - live: what every step of the parallel bond reads and writes (the frame and what it carries),
//   one array per component;
// - shape: what a step reads but never writes, unless the bond fails (geometry, strengths, mode);
// - rest: what only some laws or failures touch (the cohesive slip, damage, dissipated energy),
//   as plain records.
// Read-only fields sit apart from written ones, so that their cache lines are not written back.
// Checkpoints still hold whole BondState records (BondList::save), so the split is not part of
// the file format.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "comminute/core/vec3.hpp"

namespace comminute::bonds {

struct BondState;
enum class FailureMode : std::uint8_t;

struct BondRest {
  Vec3 slip;
  double damage = 0, dissipated = 0;
};

class BondStates {
 public:
  // live, by component: BondState::normal, shear_force, moment, strain_energy
  std::vector<double> nx, ny, nz, fx, fy, fz, mx, my, mz, strain_energy;
  // shape: BondState::length0, radius, tensile_strength, shear_strength, failed
  std::vector<double> length0, radius, tensile_strength, shear_strength;
  std::vector<FailureMode> failed;
  std::vector<BondRest> rest;

  std::size_t size() const { return nx.size(); }
  bool empty() const { return nx.empty(); }
  Vec3 normal(std::size_t b) const { return {nx[b], ny[b], nz[b]}; }
  Vec3 shear_force(std::size_t b) const { return {fx[b], fy[b], fz[b]}; }
  Vec3 moment(std::size_t b) const { return {mx[b], my[b], mz[b]}; }
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
  // The arrays of doubles (live and shape), for what is done to each alike.
  std::array<std::vector<double>*, 14> columns();
  std::array<const std::vector<double>*, 14> columns() const;
};

}  // namespace comminute::bonds
