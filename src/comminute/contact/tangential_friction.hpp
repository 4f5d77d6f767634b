#pragma once
// Coulomb friction with a tangential spring–dashpot whose history is carried in the contact: the
// stored displacement is rotated into the current tangent plane (keeping its length) and
// incremented by v_t dt. When the spring force exceeds the static limit mu_s |F_n| the contact
// slides: the spring is truncated to the dynamic limit mu_d |F_n| and the dashpot is off; a
// sliding contact (its flag set) keeps sliding while the spring force exceeds mu_d |F_n|; while it
// sticks, spring + dashpot are capped at mu_s |F_n| by reducing the dashpot part (Coulomb's static
// and kinetic friction; mu_d = mu_s, the default, is the single-coefficient rule and needs no
// flag).
#include <cmath>

#include "comminute/contact/contact_law.hpp"

namespace comminute {

// The slot of the spring: the tangential displacement of i relative to j (m), which changes sign
// when i and j swap.
// The sliding flag (1 while the contact slides) is declared only when some pair of the run has
// mu_d != mu_s (ContactLaw::use_dynamic_friction()). The stiffness of the last step (N/m) is
// declared only by a law whose tangential stiffness follows the contact (Mindlin's 8 G* a with
// the rescaling of follow_stiffness()).
struct TangentialSlots {
  SlotId spring = 0;
  SlotId sliding = ContactStateStore::none;
  SlotId stiffness = ContactStateStore::none;
  void declare(ContactStateStore& layout, bool dynamic_friction, bool stiffness_history = false) {
    spring = layout.declare_vec3("tangential_spring", SwapRule::negate);
    if (dynamic_friction) sliding = layout.declare_f32("tangential_sliding", SwapRule::keep);
    if (stiffness_history) stiffness = layout.declare_f64("tangential_stiffness", SwapRule::keep);
  }
  float* flag(const StateRef& s) const {
    return sliding == ContactStateStore::none ? nullptr : &s.f32(sliding);
  }
};

// Carries a loaded spring from the stiffness of the last step, `kt_before` (N/m; 0: a new
// contact), to this step's `kt`, and returns the elastic energy the change releases (J, >= 0).
// The tangential force is incremental in Mindlin's stiffness and scaled with the contact radius
// on unloading (Thornton, Cummins & Cleary, Powder Technol. 233 (2013) 30, eq. 18 and the
// unloading rule after it; LAMMPS `mindlin_rescale/force`): with F_s = -k_t xi,
//   k_t grows (loading):    F_s kept,               xi <- xi k_t,before / k_t
//   k_t shrinks (unloading): F_s <- F_s a / a_before, xi kept.
// Either way the spring energy F_s^2 / (2 k_t) can only fall; the fall is booked as friction
// (the micro-slip of Mindlin's annulus), so the ledger closes. The total form F_s = -k_t(a) xi
// instead gains 1/2 xi^2 dk_t from nothing while the contact is loaded.
inline double follow_stiffness(Vec3& xi, double& kt_before, double kt) {
  double released = 0;
  if (kt_before > 0.0) {
    const double energy = 0.5 * kt_before * norm2(xi);
    if (kt > kt_before) {
      xi *= kt_before / kt;
      released = energy * (1.0 - kt_before / kt);
    } else {
      released = energy * (1.0 - kt / kt_before);
    }
  }
  kt_before = kt;
  return released;
}

// The Coulomb limits of a contact (N): mu_s |F_n| to start sliding, mu_d |F_n| while sliding.
struct FrictionLimit {
  double stick = 0;
  double slide = 0;
};

inline FrictionLimit friction_limit(const PairParameters& p, double normal_force) {
  return {p.friction * std::abs(normal_force), p.dynamic_friction * std::abs(normal_force)};
}

// The stored spring carried into the current tangent plane keeping its length, in two halves so
// that a batch of contacts can take its divisions and square roots in one loop (ContactBatch):
// project_spring() removes the part along the normal and keeps the squared lengths before and
// after; restore_length() is the factor sqrt(before / after) that gives the length back (1 when
// the spring is zero or lies along the normal: nothing to restore).
struct ProjectedSpring {
  Vec3 xi;            // the stored spring less its part along the normal (m)
  double before = 1;  // |xi|^2 before the projection (m^2)
  double after = 1;   // |xi|^2 after it (m^2)
};

inline ProjectedSpring project_spring(const Vec3& stored, const Vec3& normal) {
  ProjectedSpring s{stored, 1.0, 1.0};
  const double len2 = norm2(stored);
  if (len2 > 0.0) {
    s.xi -= dot(s.xi, normal) * normal;
    const double l2 = norm2(s.xi);
    if (l2 > 0.0) {
      s.before = len2;
      s.after = l2;
    }
  }
  return s;
}

inline double restore_length(double before, double after) {
  return std::sqrt(before / after);
}

// kt: tangential stiffness (N/m), ct: tangential damping (N s/m), `lim`: the limits (N),
// `xi`: the contact's stored displacement already rotated into the current tangent plane (m),
// written back to `stored`, `sliding`: its flag (null: mu_d = mu_s everywhere). Sets
// out.tangential_force, adds to out.stored_energy, out.damping_dissipation,
// out.friction_dissipation.
inline void coulomb_rotated(const ContactKinematics& k, double kt, double ct, FrictionLimit lim,
                            Vec3 xi, Vec3& stored, float* sliding, ContactForces& out) {
  const double limit = lim.stick;
  const bool was_sliding = sliding != nullptr && *sliding != 0.0f;
  const Vec3 trial = xi + k.tangential_velocity * k.dt;
  xi = trial;
  // the spring force |k_t xi| against the limits, compared squared (its root only when it slides)
  const double spring2 = kt * kt * norm2(xi);
  Vec3 ft;
  const bool slides = spring2 > limit * limit || (was_sliding && spring2 > lim.slide * lim.slide);
  if (sliding != nullptr) *sliding = slides ? 1.0f : 0.0f;
  if (slides) {
    const double spring = kt * std::sqrt(norm2(xi));
    // sliding: the spring is cut back to |k_t xi| = mu_d |F_n| and the dashpot is off; the
    // friction force does work |F_t| |slip|, slip being the part of the motion the spring did not
    // take
    xi *= lim.slide / spring;
    ft = -kt * xi;
    out.friction_dissipation += lim.slide * norm(trial - xi);
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

// coulomb_rotated() of the stored spring rotated into the current tangent plane, keeping its
// magnitude (`stored`: the contact's stored displacement, m).
inline void coulomb_tangential(const ContactKinematics& k, double kt, double ct, FrictionLimit lim,
                               Vec3& stored, float* sliding, ContactForces& out) {
  const ProjectedSpring s = project_spring(stored, k.normal);
  coulomb_rotated(k, kt, ct, lim, s.xi * restore_length(s.before, s.after), stored, sliding, out);
}

}  // namespace comminute
