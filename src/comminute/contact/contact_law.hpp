#pragma once
// Contact laws: one interface for particle–particle and particle–wall contacts, chosen by name in
// the case file ([contact] model = "hertz_mindlin" | "linear_spring_dashpot"). Rolling resistance
// and adhesion are separate small interfaces composed with the law (see rolling.hpp, cohesion.hpp).
#include <memory>
#include <string>

#include "comminute/core/registry.hpp"
#include "comminute/core/vec3.hpp"
#include "comminute/particles/material.hpp"

namespace comminute {

// Per-contact state that survives from step to step (and across neighbour-list rebuilds and
// particle reordering: it is keyed by the two particle ids). Modules read it (breakage uses the
// loading work and peak force).
struct ContactHistory {
  Vec3 tangential_spring;  // m, accumulated tangential displacement (in the current tangent plane)
  Vec3 rolling_spring;     // N m, elastic rolling torque (EPSD model)
  // Loading record for breakage models, in single precision (a dense bed holds several hundred
  // thousand histories: 64 bytes each keeps a 100k-particle bed under 1 kB per particle).
  float max_overlap = 0;   // m, largest overlap in this contact
  float loading_work = 0;  // J, elastic work of the normal force up to max_overlap
  float normal_force = 0;  // N, elastic normal force of the last step (0 when apart)
  float unused = 0;        // explicit padding: checkpoints copy the bytes of this struct
};
static_assert(sizeof(ContactHistory) == 64);

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

class ContactLaw {
 public:
  virtual ~ContactLaw() = default;
  virtual std::string name() const = 0;
  // Normal and tangential force for one contact; updates the history.
  virtual void compute(const ContactKinematics& k, const PairParameters& p, ContactHistory& h,
                       ContactForces& out) const = 0;
  // Normal stiffness at overlap `delta` (N/m), for the time-step check and energy partition.
  virtual double normal_stiffness(const PairParameters& p, double effective_radius,
                                  double effective_mass, double delta) const = 0;
};

// Options common to all laws, from [contact] in the case file.
struct ContactOptions {
  double linear_normal_stiffness = 0;          // N/m, linear spring–dashpot k_n
  double linear_tangential_ratio = 2.0 / 7.0;  // k_t / k_n for the linear law
  bool tangential_damping = true;              // dashpot in the tangential direction
};

using ContactLawRegistry = Registry<ContactLaw, const ContactOptions&>;

}  // namespace comminute
