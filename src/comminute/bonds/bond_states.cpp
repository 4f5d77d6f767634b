#include "comminute/bonds/bond_states.hpp"

#include "comminute/bonds/bond_law.hpp"

namespace comminute::bonds {

void BondStates::reserve(std::size_t n) {
  live.reserve(n);
  shape.reserve(n);
  rest.reserve(n);
}

void BondStates::resize(std::size_t n) {
  live.resize(n);
  shape.resize(n);
  rest.resize(n);
}

void BondStates::push_back(const BondState& s) {
  live.emplace_back();
  shape.emplace_back();
  rest.emplace_back();
  set(size() - 1, s);
}

BondState BondStates::get(std::size_t b) const {
  BondState s;
  const BondLive& l = live[b];
  const BondShape& h = shape[b];
  const BondRest& r = rest[b];
  s.normal = l.normal;
  s.shear_force = l.shear_force;
  s.moment = l.moment;
  s.strain_energy = l.strain_energy;
  s.length0 = h.length0;
  s.radius = h.radius;
  s.tensile_strength = h.tensile_strength;
  s.shear_strength = h.shear_strength;
  s.failed = h.failed;
  s.slip = r.slip;
  s.damage = r.damage;
  s.dissipated = r.dissipated;
  return s;
}

void BondStates::set(std::size_t b, const BondState& s) {
  live[b] = {s.normal, s.shear_force, s.moment, s.strain_energy};
  shape[b] = {s.length0, s.radius, s.tensile_strength, s.shear_strength, s.failed};
  rest[b] = {s.slip, s.damage, s.dissipated};
}

void BondStates::move(std::size_t from, std::size_t to) {
  live[to] = live[from];
  shape[to] = shape[from];
  rest[to] = rest[from];
}

std::size_t BondStates::capacity_bytes() const {
  return live.capacity() * sizeof(BondLive) + shape.capacity() * sizeof(BondShape) +
         rest.capacity() * sizeof(BondRest);
}

std::vector<BondState> BondStates::records() const {
  std::vector<BondState> all(size());
  for (std::size_t b = 0; b < size(); ++b) all[b] = get(b);
  return all;
}

void BondStates::assign(const std::vector<BondState>& records) {
  resize(records.size());
  for (std::size_t b = 0; b < records.size(); ++b) set(b, records[b]);
}

}  // namespace comminute::bonds
