#include "comminute/bonds/bond_states.hpp"

#include <algorithm>

#include "comminute/bonds/bond_law.hpp"

namespace comminute::bonds {

std::array<std::vector<double>*, 14> BondStates::columns() {
  return {&nx,
          &ny,
          &nz,
          &fx,
          &fy,
          &fz,
          &mx,
          &my,
          &mz,
          &strain_energy,
          &length0,
          &radius,
          &tensile_strength,
          &shear_strength};
}

std::array<const std::vector<double>*, 14> BondStates::columns() const {
  // the same columns as the writable list, read-only
  const auto writable = const_cast<BondStates*>(this)->columns();
  std::array<const std::vector<double>*, 14> out{};
  std::copy(writable.begin(), writable.end(), out.begin());
  return out;
}

void BondStates::reserve(std::size_t n) {
  for (std::vector<double>* c : columns()) c->reserve(n);
  failed.reserve(n);
  rest.reserve(n);
}

void BondStates::resize(std::size_t n) {
  for (std::vector<double>* c : columns()) c->resize(n);
  failed.resize(n);
  rest.resize(n);
}

void BondStates::push_back(const BondState& s) {
  resize(size() + 1);
  set(size() - 1, s);
}

BondState BondStates::get(std::size_t b) const {
  const BondRest& r = rest[b];
  return {.normal = normal(b),
          .shear_force = shear_force(b),
          .moment = moment(b),
          .slip = r.slip,
          .length0 = length0[b],
          .radius = radius[b],
          .tensile_strength = tensile_strength[b],
          .shear_strength = shear_strength[b],
          .damage = r.damage,
          .dissipated = r.dissipated,
          .strain_energy = strain_energy[b],
          .failed = failed[b],
          .padding = {}};
}

void BondStates::set(std::size_t b, const BondState& s) {
  nx[b] = s.normal.x, ny[b] = s.normal.y, nz[b] = s.normal.z;
  fx[b] = s.shear_force.x, fy[b] = s.shear_force.y, fz[b] = s.shear_force.z;
  mx[b] = s.moment.x, my[b] = s.moment.y, mz[b] = s.moment.z;
  strain_energy[b] = s.strain_energy;
  length0[b] = s.length0, radius[b] = s.radius;
  tensile_strength[b] = s.tensile_strength, shear_strength[b] = s.shear_strength;
  failed[b] = s.failed;
  rest[b] = {s.slip, s.damage, s.dissipated};
}

void BondStates::move(std::size_t from, std::size_t to) {
  for (std::vector<double>* c : columns()) (*c)[to] = (*c)[from];
  failed[to] = failed[from];
  rest[to] = rest[from];
}

std::size_t BondStates::capacity_bytes() const {
  std::size_t bytes = failed.capacity() * sizeof(FailureMode) + rest.capacity() * sizeof(BondRest);
  for (const std::vector<double>* c : columns()) bytes += c->capacity() * sizeof(double);
  return bytes;
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
