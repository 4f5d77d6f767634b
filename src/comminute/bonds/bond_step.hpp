#pragma once
// The loop of one step over a range of bonds, shared by the bond laws: each law's update_range
// instantiates it with its own class, whose advance() (what its update() does) is inlined into
// the loop instead of one virtual call per bond. Per bond: the motion of its two particles, the
// law's update, the force and the two torques the particles receive (added to them afterwards, per
// particle in bond order, by BondsModule).
#include <cstddef>

#include "comminute/bonds/bond_law.hpp"

namespace comminute::bonds {

// The bond's contact point: the middle of the gap (or overlap) between the two surfaces, on the
// line of centres (n: unit normal i -> j, length: centre distance).
inline Vec3 bond_point(const Vec3& xi, double ri, double rj, const Vec3& n, double length) {
  return xi + (ri + 0.5 * (length - ri - rj)) * n;
}

// The same for bond b of a step (failure positions and stress levers after the step).
inline Vec3 bond_point(const BondStep& st, std::size_t b) {
  const std::uint32_t i = st.slot_i[b], j = st.slot_j[b];
  const Vec3 d = st.x[j] - st.x[i];
  const double length = norm(d);
  const Vec3 n = length > 0 ? d * (1.0 / length) : st.state[b].normal;
  return bond_point(st.x[i], st.radius[i], st.radius[j], n, length);
}

template <class Law>
BondStepSums update_bonds(const Law& law, const BondStep& st, std::size_t begin, std::size_t end) {
  BondStepSums sums;
  for (std::size_t b = begin; b < end; ++b) {
    if (st.flag[b]) {
      st.force[b] = st.torque_i[b] = st.torque_j[b] = Vec3{};
      continue;
    }
    const std::uint32_t i = st.slot_i[b], j = st.slot_j[b];
    BondState& s = st.state[b];
    const Vec3 xi = st.x[i], xj = st.x[j];
    const Vec3 d = xj - xi;
    BondMotion m;
    m.length = norm(d);
    m.normal = m.length > 0 ? d * (1.0 / m.length) : s.normal;
    const Vec3 xc = bond_point(xi, st.radius[i], st.radius[j], m.normal, m.length);
    const Vec3 wi = st.w[i], wj = st.w[j];
    const Vec3 vc = st.v[j] + cross(wj, xc - xj) - st.v[i] - cross(wi, xc - xi);
    m.slip_increment = (vc - dot(vc, m.normal) * m.normal) * st.dt;
    m.rotation_increment = (wj - wi) * st.dt;
    const double before = s.dissipated;
    const BondLoad load = law.advance(s, m);  // the law's update(), inlined
    sums.released += s.dissipated - before;
    if (s.failed != FailureMode::none) {
      st.flag[b] = 2;
      ++sums.failed;
      st.force[b] = st.torque_i[b] = st.torque_j[b] = Vec3{};
      continue;
    }
    sums.elastic += s.strain_energy;
    st.force[b] = load.force;
    st.torque_j[b] = cross(xc - xj, load.force) + load.moment;
    st.torque_i[b] = cross(xc - xi, load.force) + load.moment;
  }
  return sums;
}

}  // namespace comminute::bonds
