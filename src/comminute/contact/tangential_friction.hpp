#pragma once
// Coulomb friction with a tangential spring–dashpot whose history is carried in the contact: the
// stored displacement is rotated into the current tangent plane (keeping its length) and
// incremented by v_t dt. When the spring force exceeds mu |F_n| the contact slides: the spring is
// truncated to the limit and the dashpot is off; while it sticks, spring + dashpot are capped at
// the limit by reducing the dashpot part.
#include <cmath>

#include "comminute/contact/contact_law.hpp"

namespace comminute {

// The slot of the spring: the tangential displacement of i relative to j (m), which changes sign
// when i and j swap.
inline SlotId declare_tangential_spring(ContactStateStore& layout) {
  return layout.declare_vec3("tangential_spring", SwapRule::negate);
}

// kt: tangential stiffness (N/m), ct: tangential damping (N s/m), limit: mu |F_n| (N),
// `stored`: the contact's stored displacement (m). Sets out.tangential_force, adds to
// out.stored_energy, out.damping_dissipation, out.friction_dissipation.
inline void coulomb_tangential(const ContactKinematics& k, double kt, double ct, double limit,
                               Vec3& stored, ContactForces& out) {
  Vec3 xi = stored;
  // rotate into the current tangent plane, preserving the magnitude
  const double len2 = norm2(xi);
  if (len2 > 0.0) {
    xi -= dot(xi, k.normal) * k.normal;
    const double l2 = norm2(xi);
    if (l2 > 0.0) xi *= std::sqrt(len2 / l2);
  }
  const Vec3 trial = xi + k.tangential_velocity * k.dt;
  xi = trial;
  const double spring = kt * std::sqrt(norm2(xi));
  Vec3 ft;
  if (spring > limit) {
    // sliding: the spring is cut back to |k_t xi| = mu |F_n| and the dashpot is off; the friction
    // force does work |F_t| |slip|, slip being the part of the motion the spring did not take
    xi *= limit / spring;
    ft = -kt * xi;
    out.friction_dissipation += limit * norm(trial - xi);
  } else {
    // sticking: spring + dashpot, the total capped at mu |F_n| by reducing the dashpot part
    const Vec3 fs = -kt * xi;
    ft = fs - ct * k.tangential_velocity;
    const double ft2 = norm2(ft);
    if (ft2 > limit * limit) ft *= limit / std::sqrt(ft2);
    out.damping_dissipation += -dot(ft - fs, k.tangential_velocity) * k.dt;
  }
  stored = xi;
  out.tangential_force = ft;
  out.stored_energy += 0.5 * kt * norm2(xi);
}

}  // namespace comminute
