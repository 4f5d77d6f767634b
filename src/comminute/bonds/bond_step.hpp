#pragma once
// The loop of one step over a range of bonds, shared by the bond laws: each law's update_range
// instantiates it with its own class, whose advance() (what its update() does) is inlined into
// the loop instead of one virtual call per bond. Per bond: the motion of its two particles, the
// law's update, the force and the two torques the particles receive, added straight onto them
// (BondLoadDelivery); on several threads a particle already loaded by an earlier block of bonds
// takes this one's load after the threads join, in bond order (BondsModule).
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
  const Vec3 n = length > 0 ? d * (1.0 / length) : st.state->normal(b);
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

// Hands the loads of a range of bonds, bond by bond in bond order, to their particles: the force
// on j (i gets −force) and the torques, into the step's arrays or, when the step has them, straight
// onto the particles (BondStep). Particle i's force and torque stay in registers over consecutive
// bonds of the same i (bonds made from the pairs in id order come grouped by i), as the pair loop
// keeps them over a particle's contacts: the same sums in the same order as adding to the
// particle bond by bond. They are written back when another particle's turn comes, before the
// held particle is loaded as a bond's j or as a waiting i, and at the end (destructor).
class BondLoadDelivery {
 public:
  explicit BondLoadDelivery(const BondStep& st) : st_(st) {}
  BondLoadDelivery(const BondLoadDelivery&) = delete;
  BondLoadDelivery& operator=(const BondLoadDelivery&) = delete;
  ~BondLoadDelivery() { release(); }

  void operator()(std::size_t b, const Vec3& force, const Vec3& torque_i, const Vec3& torque_j) {
    if (!st_.particle_force) {
      st_.force[b] = force;
      st_.torque_i[b] = torque_i;
      st_.torque_j[b] = torque_j;
      return;
    }
    const std::uint32_t i = st_.slot_i[b], j = st_.slot_j[b];
    const std::uint8_t wait = st_.defer ? st_.defer[b] : 0;
    if (wait) {  // added after the threads join, from its place among the waiting bonds
      const std::uint32_t* at = std::lower_bound(st_.deferred, st_.deferred + st_.n_deferred, b);
      const auto k = static_cast<std::size_t>(at - st_.deferred);
      st_.force[k] = force;
      st_.torque_i[k] = torque_i;
      st_.torque_j[k] = torque_j;
    }
    if (j == held_) release();
    if (!(wait & 1u)) {
      if (i != held_) {
        release();
        held_ = i;
        fi_ = st_.particle_force[i];
        ti_ = st_.particle_torque[i];
      }
      fi_ -= force;
      ti_ -= torque_i;
    }
    if (!(wait & 2u)) {
      st_.particle_force[j] += force;
      st_.particle_torque[j] += torque_j;
    }
  }

  // A gone bond (flag 1: a particle of it was removed, its slots may point nowhere) carries
  // nothing.
  void nothing(std::size_t b) {
    if (!st_.particle_force) st_.force[b] = st_.torque_i[b] = st_.torque_j[b] = Vec3{};
  }

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  void release() {
    if (held_ == kNone) return;
    st_.particle_force[held_] = fi_;
    st_.particle_torque[held_] = ti_;
    held_ = kNone;
  }

  const BondStep& st_;
  std::uint32_t held_ = kNone;  // the particle whose force and torque are held
  Vec3 fi_, ti_;
};

template <class Law>
BondStepSums update_bonds(const Law& law, const BondStep& st, std::size_t begin, std::size_t end) {
  BondStepSums sums;
  BondLoadDelivery deliver(st);
  for (std::size_t b = begin; b < end; ++b) {
    if (st.flag[b]) {
      deliver.nothing(b);
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
      deliver(b, {}, {}, {});  // zeros, as the fold of the arrays adds them
      continue;
    }
    sums.elastic += s.strain_energy;
    deliver(b, load.force, cross(k.lever_i, load.force) + load.moment,
            cross(k.lever_j, load.force) + load.moment);
  }
  return sums;
}

}  // namespace comminute::bonds
