#pragma once
// Contact laws: one interface for particle–particle and particle–wall contacts, chosen by name in
// the case file ([contact] model = "hertz_mindlin" | "linear_spring_dashpot"). A law is built
// from the [contact] table and reads its own keys; it declares the per-contact state it keeps
// (contact_state.hpp) and answers for its own time-step limit. Rolling resistance and adhesion are
// separate small interfaces composed with the law (rolling_resistance.hpp, cohesion.hpp).
#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <string>

#include "comminute/contact/contact_state.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/core/registry.hpp"
#include "comminute/core/vec3.hpp"
#include "comminute/particles/material.hpp"

namespace comminute {

// Geometry and relative motion of one contact, computed by the engine.
struct ContactKinematics {
  Vec3 normal;               // unit normal pointing from the other body to particle i
  double overlap = 0;        // m, > 0
  double overlap_rate = 0;   // m/s, d(overlap)/dt = -(v_i - v_j).normal at the contact point
  Vec3 tangential_velocity;  // m/s, tangential relative velocity of i w.r.t. j at the contact point
  Vec3 relative_angular_velocity;  // rad/s, w_i - w_j (rolling)
  double effective_radius = 0;     // m, R* (wall: R_i)
  double effective_mass = 0;       // kg, m* (wall: m_i)
  double effective_inertia = 0;    // kg m2, I_i I_j / (I_i + I_j) (wall: I_i), for rolling models
  double dt = 0;                   // s
};

// What a law returns for one contact (forces act on i; j receives the opposite).
struct ContactForces {
  double normal_force = 0;           // N, signed along normal (> 0 repulsive), damping included
  double elastic_normal_force = 0;   // N, elastic part (adhesion excluded)
  Vec3 tangential_force;             // N
  Vec3 rolling_torque;               // N m on i (j gets the opposite)
  double stored_energy = 0;          // J, elastic energy stored in the contact now
  double normal_elastic_energy = 0;  // J, integral of the elastic normal force from 0 to overlap
  double damping_dissipation = 0;    // J, dissipated by dashpots during this step
  double friction_dissipation = 0;   // J, dissipated by sliding (and rolling slip) this step
};

// A batch's contacts in columns (structure of arrays, one array per component), so that a law's
// vector loops read its inputs and write its results in place: contact c of a batch has the
// kinematics kinematics.<field>[c] and its forces go to forces.<field>[c]. At most kBatchSize
// contacts per batch (the force loops' runs, engine/contact_run.hpp).
inline constexpr std::size_t kBatchSize = 64;
using BatchColumn = std::array<double, kBatchSize>;

struct KinematicsColumns {  // ContactKinematics' fields by component; one dt for the batch
  BatchColumn nx{}, ny{}, nz{}, overlap{}, overlap_rate{}, vx{}, vy{}, vz{}, wx{}, wy{}, wz{};
  BatchColumn effective_radius{}, effective_mass{}, effective_inertia{};
  double dt = 0;
  ContactKinematics at(std::size_t c) const {
    return {{nx[c], ny[c], nz[c]},
            overlap[c],
            overlap_rate[c],
            {vx[c], vy[c], vz[c]},
            {wx[c], wy[c], wz[c]},
            effective_radius[c],
            effective_mass[c],
            effective_inertia[c],
            dt};
  }
  void set(std::size_t c, const ContactKinematics& k) {  // (dt is the batch's)
    nx[c] = k.normal.x, ny[c] = k.normal.y, nz[c] = k.normal.z;
    overlap[c] = k.overlap, overlap_rate[c] = k.overlap_rate;
    vx[c] = k.tangential_velocity.x, vy[c] = k.tangential_velocity.y;
    vz[c] = k.tangential_velocity.z;
    wx[c] = k.relative_angular_velocity.x, wy[c] = k.relative_angular_velocity.y;
    wz[c] = k.relative_angular_velocity.z;
    effective_radius[c] = k.effective_radius, effective_mass[c] = k.effective_mass;
    effective_inertia[c] = k.effective_inertia;
  }
};

struct ForceColumns {  // ContactForces' fields by component
  BatchColumn normal_force{}, elastic_normal_force{}, fx{}, fy{}, fz{}, tx{}, ty{}, tz{};
  BatchColumn stored_energy{}, normal_elastic_energy{}, damping_dissipation{},
      friction_dissipation{};
  ContactForces at(std::size_t c) const {
    return {normal_force[c],        elastic_normal_force[c], {fx[c], fy[c], fz[c]},
            {tx[c], ty[c], tz[c]},  stored_energy[c],        normal_elastic_energy[c],
            damping_dissipation[c], friction_dissipation[c]};
  }
  void set(std::size_t c, const ContactForces& f) {
    normal_force[c] = f.normal_force, elastic_normal_force[c] = f.elastic_normal_force;
    fx[c] = f.tangential_force.x, fy[c] = f.tangential_force.y, fz[c] = f.tangential_force.z;
    tx[c] = f.rolling_torque.x, ty[c] = f.rolling_torque.y, tz[c] = f.rolling_torque.z;
    stored_energy[c] = f.stored_energy, normal_elastic_energy[c] = f.normal_elastic_energy;
    damping_dissipation[c] = f.damping_dissipation;
    friction_dissipation[c] = f.friction_dissipation;
  }
  // Zeroes contacts [0, n) (a batch adds to its forces).
  void clear(std::size_t n) {
    for (BatchColumn* col :
         {&normal_force, &elastic_normal_force, &fx, &fy, &fz, &tx, &ty, &tz, &stored_energy,
          &normal_elastic_energy, &damping_dissipation, &friction_dissipation})
      std::fill_n(col->begin(), n, 0.0);
  }
};

// Contacts evaluated in one call (the force loops hand them over in runs): contact c < size
// (at most kBatchSize) has the kinematics kinematics->at(c), the parameters *parameters[c] and the
// slots of contact index[c] of the store `slots`; its forces go to forces->at(c) (zeroed by the
// caller).
struct ContactBatch {
  std::size_t size = 0;
  const KinematicsColumns* kinematics = nullptr;
  const PairParameters* const* parameters = nullptr;
  const std::size_t* index = nullptr;
  const Slots* slots = nullptr;
  ForceColumns* forces = nullptr;
  template <class F>  // f(kinematics, parameters, state, forces) for every contact, in order
  void for_each(F f) const {
    for (std::size_t c = 0; c < size; ++c) {
      const ContactKinematics k = kinematics->at(c);
      ContactForces out = forces->at(c);
      f(k, *parameters[c], StateRef{slots, index[c]}, out);
      forces->set(c, out);
    }
  }
};

// The largest time step a law resolves, and why (s; infinity: no limit of its own, the Rayleigh
// time of the time-step policy governs).
struct StepLimit {
  double dt = std::numeric_limits<double>::infinity();
  std::string reason;
};

class ContactLaw {
 public:
  virtual ~ContactLaw() = default;
  virtual std::string name() const = 0;
  // Declares the law's per-contact slots (called once, before any contact list exists).
  virtual void declare(ContactStateStore& layout) = 0;
  // Some pair has a dynamic friction coefficient other than its static one: the law keeps a
  // sliding flag per contact (call before declare()).
  void use_dynamic_friction() { dynamic_friction_ = true; }
  // Normal and tangential force for one contact; updates the contact's slots in `s`.
  virtual void compute(const ContactKinematics& k, const PairParameters& p, const StateRef& s,
                       ContactForces& out) const = 0;
  // compute() for every contact of a batch, in order: one virtual call per batch. A law derived
  // from ContactLawOf<itself> gets this loop with its compute() inlined.
  virtual void compute_batch(const ContactBatch& b) const {
    b.for_each([this](const ContactKinematics& k, const PairParameters& p, const StateRef& s,
                      ContactForces& out) { compute(k, p, s, out); });
  }
  // The normal elastic energy compute() reports (out.normal_elastic_energy) at overlap `delta` (m)
  // for this effective radius (m), J: the same operations, so the same bits, without the friction
  // and the contact's state (breakage's energy bookkeeping asks it for every growing contact).
  virtual double normal_elastic_energy(const PairParameters& p, double effective_radius,
                                       double delta) const = 0;
  // Time-step limit for a contact between two particles of this radius (m) and mass (kg).
  virtual StepLimit step_limit(const PairParameters&, double /*radius*/, double /*mass*/) const {
    return {};
  }

 protected:
  bool dynamic_friction_ = false;
};

// The base of a law class `Law` (declared final): compute_batch() calls Law::compute directly, so
// the compiler inlines the law into the batch loop (no virtual call per contact).
template <class Law>
class ContactLawOf : public ContactLaw {
 public:
  void compute_batch(const ContactBatch& b) const final {
    const Law& law = static_cast<const Law&>(*this);
    b.for_each([&law](const ContactKinematics& k, const PairParameters& p, const StateRef& s,
                      ContactForces& out) { law.Law::compute(k, p, s, out); });
  }
};

// A law's factory reads the law's keys from the [contact] table.
using ContactLawRegistry = Registry<ContactLaw, const CaseTable&>;

}  // namespace comminute
