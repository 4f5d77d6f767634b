#pragma once
// The loop of one step over a range of bonds, shared by the bond laws: each law's update_range
// instantiates it with its own class, whose advance() (what its update() does) is inlined into
// the loop instead of one virtual call per bond. Per bond: the motion of its two particles, the
// law's update, the force and the two torques the particles receive, added straight onto them
// (deliver); on several threads a particle already loaded by an earlier block of bonds takes this
// one's load after the threads join, in bond order (BondsModule).
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "comminute/bonds/bond_law.hpp"
#include "comminute/bonds/bond_states.hpp"

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
  const Vec3 n = length > 0 ? d * (1.0 / length) : st.state->live[b].normal;
  return bond_point(st.x[i], st.radius[i], st.radius[j], n, length);
}

// What a bond sees of its two particles over one step: the motion, and the levers x_c − x_i and
// x_c − x_j of its contact point, from the relative position d = x_j − x_i, the radii, the
// relative velocity dv = v_j − v_i and the spins. Without branches (a zero length keeps the last
// normal by selection), so that a loop over a batch of bonds vectorises; the levers are formed
// from d, not from absolute positions, which keeps their digits.
struct BondKinematics {
  BondMotion m;
  Vec3 lever_i, lever_j;  // m, x_c − x_i and x_c − x_j
};

[[gnu::always_inline]] inline BondKinematics bond_kinematics(const Vec3& d, double ri, double rj,
                                                             const Vec3& dv, const Vec3& wi,
                                                             const Vec3& wj,
                                                             const Vec3& last_normal, double dt) {
  BondKinematics k;
  const double length = std::sqrt(dot(d, d));
  const double per_length = 1.0 / length;
  const bool apart = length > 0;
  k.m.length = length;
  k.m.normal = {apart ? d.x * per_length : last_normal.x, apart ? d.y * per_length : last_normal.y,
                apart ? d.z * per_length : last_normal.z};
  const Vec3& n = k.m.normal;
  k.lever_i = (ri + 0.5 * (length - ri - rj)) * n;  // as bond_point()
  k.lever_j = k.lever_i - d;
  const Vec3 vc = dv + cross(wj, k.lever_j) - cross(wi, k.lever_i);
  k.m.slip_increment = (vc - dot(vc, n) * n) * dt;
  k.m.rotation_increment = (wj - wi) * dt;
  return k;
}

// The same from the step's particle arrays, for bond b (slots i, j).
inline BondKinematics bond_kinematics(const BondStep& st, std::uint32_t i, std::uint32_t j,
                                      const Vec3& last_normal) {
  return bond_kinematics(st.x[j] - st.x[i], st.radius[i], st.radius[j], st.v[j] - st.v[i], st.w[i],
                         st.w[j], last_normal, st.dt);
}

// Hands bond b's load to its particles: the force on j (i gets −force) and the torques, into the
// step's arrays or, when the step has them, straight onto the particles (BondStep).
inline void deliver(const BondStep& st, std::size_t b, const Vec3& force, const Vec3& torque_i,
                    const Vec3& torque_j) {
  if (st.particle_force) {
    const std::uint32_t i = st.slot_i[b], j = st.slot_j[b];
    const std::uint8_t wait = st.defer ? st.defer[b] : 0;
    if (wait) {  // added after the threads join, from its place among the waiting bonds
      const std::uint32_t* at = std::lower_bound(st.deferred, st.deferred + st.n_deferred, b);
      const auto k = static_cast<std::size_t>(at - st.deferred);
      st.force[k] = force;
      st.torque_i[k] = torque_i;
      st.torque_j[k] = torque_j;
    }
    if (!(wait & 1u)) {
      st.particle_force[i] -= force;
      st.particle_torque[i] -= torque_i;
    }
    if (!(wait & 2u)) {
      st.particle_force[j] += force;
      st.particle_torque[j] += torque_j;
    }
    return;
  }
  st.force[b] = force;
  st.torque_i[b] = torque_i;
  st.torque_j[b] = torque_j;
}

// A gone bond (flag 1: a particle of it was removed, its slots may point nowhere) carries nothing.
inline void deliver_nothing(const BondStep& st, std::size_t b) {
  if (!st.particle_force) st.force[b] = st.torque_i[b] = st.torque_j[b] = Vec3{};
}

template <class Law>
BondStepSums update_bonds(const Law& law, const BondStep& st, std::size_t begin, std::size_t end) {
  BondStepSums sums;
  for (std::size_t b = begin; b < end; ++b) {
    if (st.flag[b]) {
      deliver_nothing(st, b);
      continue;
    }
    BondState s = st.state->get(b);  // the whole record: any law's fields
    const BondKinematics k = bond_kinematics(st, st.slot_i[b], st.slot_j[b], s.normal);
    const double before = s.dissipated;
    const BondLoad load = law.advance(s, k.m);  // the law's update(), inlined
    st.state->set(b, s);
    sums.released += s.dissipated - before;
    if (s.failed != FailureMode::none) {
      st.flag[b] = 2;
      ++sums.failed;
      deliver(st, b, {}, {}, {});  // zeros, as the fold of the arrays adds them
      continue;
    }
    sums.elastic += s.strain_energy;
    deliver(st, b, load.force, cross(k.lever_i, load.force) + load.moment,
            cross(k.lever_j, load.force) + load.moment);
  }
  return sums;
}

}  // namespace comminute::bonds
