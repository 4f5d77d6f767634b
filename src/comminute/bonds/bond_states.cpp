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
  const BondLive& l = live[b];
  const BondShape& h = shape[b];
  const BondRest& r = rest[b];
  return {.normal = l.normal,
          .shear_force = l.shear_force,
          .moment = l.moment,
          .slip = r.slip,
          .length0 = h.length0,
          .radius = h.radius,
          .tensile_strength = h.tensile_strength,
          .shear_strength = h.shear_strength,
          .damage = r.damage,
          .dissipated = r.dissipated,
          .strain_energy = l.strain_energy,
          .failed = h.failed,
          .padding = {}};
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
