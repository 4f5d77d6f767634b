#pragma once
// Bond laws: what holds two bonded particles together until the bond fails. One interface, one
// registry keyed by the case file's [bonds] law name; a law reads its own keys from [bonds].
// A bond acts at its contact point (middle of the gap between the two spheres) in parallel with
// the contact law (Potyondy & Cundall 2004: the linear contact acts beside the parallel bond).
// Sign convention: `normal` points from particle i to particle j; the law returns the force and
// moment the bond exerts on j; i receives the opposite force and moment.
#include <cstdint>
#include <memory>
#include <string>

#include "comminute/bonds/bond_states.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/core/registry.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/core/vec3.hpp"

namespace comminute::bonds {

enum class FailureMode : std::uint8_t { none = 0, tensile = 1, shear = 2 };

// What a bond remembers between steps (plain data: checkpointed as is). A list of bonds keeps
// these fields split by use (BondStates, bond_states.hpp); this is one bond's whole record.
struct BondState {
  Vec3 normal;                  // unit normal i -> j at the last update
  Vec3 shear_force;             // N, stored shear force on j (parallel bond)
  Vec3 moment;                  // N m, stored moment on j: twist along normal + bending (parallel)
  Vec3 slip;                    // m, shear displacement of j relative to i (cohesive bond)
  double length0 = 0;           // m, centre distance when the bond was made
  double radius = 0;            // m, bond radius R̄ = λ̄ min(R_i, R_j)
  double tensile_strength = 0;  // Pa, this bond's (drawn when strengths scatter)
  double shear_strength = 0;    // Pa
  double damage = 0;            // 0 (intact) ... 1 (failed), never decreases
  double dissipated = 0;        // J, dissipated by this bond so far (damage, release at failure)
  double strain_energy = 0;     // J, held now
  FailureMode failed = FailureMode::none;
  std::uint8_t padding[7] = {};  // written to checkpoints: no undefined bytes
};

// The motion of the two particles over one step, as the bond sees it.
struct BondMotion {
  Vec3 normal;              // unit normal i -> j now
  double length = 0;        // m, centre distance now
  Vec3 slip_increment;      // m, shear displacement of j relative to i at the contact point
  Vec3 rotation_increment;  // rad, rotation of j relative to i over the step
};

struct BondLoad {
  Vec3 force;   // N, on j (i gets -force)
  Vec3 moment;  // N m, on j besides the moment of the force (i gets -moment)
};

// One step of a range of bonds at once (bond_step.hpp runs it): what the bonds read of the
// particles and of themselves, and per bond what the step gives back. Plain arrays, indexed by
// bond (slots, states, flags, results) or by particle slot (x, v, w, radius).
struct BondStep {
  const Vec3* x = nullptr;
  const Vec3* v = nullptr;  // at the half step: v dt is this step's displacement
  const Vec3* w = nullptr;
  const double* radius = nullptr;
  const std::uint32_t* slot_i = nullptr;
  const std::uint32_t* slot_j = nullptr;
  BondStates* state = nullptr;   // by bond (live and shape arrays, rest records)
  std::uint8_t* flag = nullptr;  // in: 1 = gone (its particle was removed; skipped), else 0;
                                 // out: 2 = failed in this step
  double dt = 0;
  Vec3* force = nullptr;     // N, on j (i gets -force); zero for a skipped or failed bond
  Vec3* torque_i = nullptr;  // N m, i gets -torque_i (moment of the force about x_i + moment)
  Vec3* torque_j = nullptr;  // N m, j gets +torque_j
  // When set (one thread), the loads go straight onto the particles' force and torque (by slot)
  // instead of into force/torque_i/torque_j: bond by bond in bond order, which is the order in
  // which the per-particle fold of the arrays adds them, so the sums are the same bit for bit.
  Vec3* particle_force = nullptr;
  Vec3* particle_torque = nullptr;
  // With particle_force on several threads: per bond, which ends' loads wait (bit 0: i's, bit 1:
  // j's) because an earlier block of bonds, run by another thread, also loads that particle. A
  // bond with a waiting end puts its loads into force/torque_i/torque_j as well, at its place k
  // in `deferred` (the n_deferred bonds with a waiting end, in bond order: deferred[k] = b); they
  // are added after the threads join, in bond order (BondsModule), so each particle still
  // receives its loads in bond order.
  const std::uint8_t* defer = nullptr;
  const std::uint32_t* deferred = nullptr;
  std::size_t n_deferred = 0;
};

// What a range of bonds adds up to in one step (summed in bond order within the range).
struct BondStepSums {
  double released = 0;     // J, dissipated in this step
  double elastic = 0;      // J, strain energy held by the bonds still intact
  std::size_t failed = 0;  // bonds that failed in this step
};

class BondLaw {
 public:
  virtual ~BondLaw() = default;
  virtual std::string name() const = 0;
  // A new bond between spheres of radii ri, rj at centre distance length along normal.
  virtual BondState create(double ri, double rj, double length, const Vec3& normal,
                           Rng& rng) const = 0;
  // Advances the bond by one step: updates its state (damage, stored force and moment, strain
  // energy, dissipated energy, failure) and returns the load on j. A failed bond carries nothing.
  virtual BondLoad update(BondState& s, const BondMotion& m) const = 0;
  // update() for bonds [begin, end) of a step, with their motion from the particles (one call
  // per range: the law's own update is inlined in the loop, bond_step.hpp).
  virtual BondStepSums update_range(const BondStep& step, std::size_t begin,
                                    std::size_t end) const = 0;
  // Largest stiffness of the bond (N/m), for the time-step check.
  virtual double stiffness(const BondState& s) const = 0;
};

using BondLawRegistry = Registry<BondLaw, const CaseTable&>;

// The rotation that takes unit vector a onto unit vector b (about a x b), made once and applied
// to each vector a bond stores (inline: it runs for every bond in every step). Without branches,
// so that a loop over bonds vectorises: the reciprocal is formed always and a half turn (no
// rotation defined) selects v unturned.
class BondTurn {
 public:
  BondTurn(const Vec3& a, const Vec3& b)
      : k_(cross(a, b)), c_(dot(a, b)), per_1c_(1.0 / (1.0 + c_)), defined_(c_ > -1.0 + 1e-12) {}
  // Rodrigues' formula with k = a x b (|k| = sin θ), c = a·b = cos θ:
  // R v = c v + k x v + k (k·v) / (1 + c)
  Vec3 operator()(const Vec3& v) const {
    const Vec3 r = c_ * v + cross(k_, v) + k_ * (dot(k_, v) * per_1c_);
    return {defined_ ? r.x : v.x, defined_ ? r.y : v.y, defined_ ? r.z : v.z};
  }

 private:
  Vec3 k_;
  double c_;
  double per_1c_;  // 1 / (1 + c), once for every vector turned
  bool defined_;   // not a half turn
};

// Rotates v by the rotation that takes unit vector a onto unit vector b (about a x b).
inline Vec3 rotate_with(const Vec3& v, const Vec3& a, const Vec3& b) {
  return BondTurn(a, b)(v);
}

}  // namespace comminute::bonds
