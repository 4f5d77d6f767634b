#pragma once
// The particle store: structure of arrays, one contiguous vector per quantity, so hot loops run
// over plain arrays and the store can be sorted by cell. Index i is a particle's current slot and
// changes when particles are sorted, inserted or removed; id[i] is its identity, unique and never
// reused within a run (64-bit counter). Modules that need more per-particle data (damage,
// fracture energy, composition...) register named scalar fields, which move with the particles.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/core/vec3.hpp"

namespace comminute {

// Particle flags (bit mask).
namespace pflag {
inline constexpr std::uint32_t fixed = 1u << 0;        // not integrated (e.g. anvil particles)
inline constexpr std::uint32_t unbreakable = 1u << 1;  // fines / dummy particles
inline constexpr std::uint32_t growing = 1u << 2;      // fragment still growing to full size
inline constexpr std::uint32_t remove = 1u << 3;       // marked for removal at the next compact()
inline constexpr std::uint32_t ghost = 1u << 4;        // a periodic image of an owned particle
}  // namespace pflag

struct ParticleInit {
  Vec3 x, v, w;
  double radius = 0.0;   // m
  double density = 0.0;  // kg/m3 (mass and inertia follow for a solid sphere)
  std::uint16_t material = 0;
  std::uint32_t flags = 0;
};

class ParticleStore {
 public:
  // Kinematics (SI): position m, velocity m/s, angular velocity rad/s, force N, torque N m.
  std::vector<Vec3> x, v, w, f, t;
  std::vector<double> radius;     // m
  std::vector<double> mass;       // kg
  std::vector<double> inertia;    // kg m2 (solid sphere 2/5 m r^2 unless set otherwise)
  std::vector<std::uint64_t> id;  // unique, never reused
  std::vector<std::uint16_t> material;
  std::vector<std::uint32_t> flags;

  std::size_t size() const { return id.size(); }
  bool empty() const { return id.empty(); }

  // Owned range and ghost range: slots [0, owned()) are the particles of the run; while the engine
  // computes forces (from its force loops to the modules' post_force) slots [owned(), size()) are
  // ghosts, periodic images of owned particles (docs/ARCHITECTURE.md). ghost_owner[g] is the owned
  // slot of ghost owned() + g. Everything outside the force stage sees no ghosts.
  std::vector<std::uint32_t> ghost_owner;
  std::size_t owned() const { return size() - ghost_owner.size(); }
  std::size_t owner_of(std::size_t slot) const {
    return slot < owned() ? slot : ghost_owner[slot - owned()];
  }
  // Appends a ghost of owned slot `owner` at x with velocity v and angular velocity w (every
  // other quantity and field copied; force and torque zero).
  void add_ghost(std::size_t owner, const Vec3& x, const Vec3& v, const Vec3& w);
  // Drops every ghost.
  void drop_ghosts();

  // Adds a particle (mass and inertia of a solid sphere from radius and density); returns id.
  std::uint64_t add(const ParticleInit& p);
  // Adds with an explicit mass (fragments carry their final mass while still growing).
  std::uint64_t add_with_mass(const ParticleInit& p, double mass);
  // Puts a new particle (fresh id, fields at their defaults, zero force and torque) in slot i in
  // place of the one there: breakage writes a fragment into its parent's slot, so that nothing
  // after it moves. Returns the id.
  std::uint64_t renew(std::size_t i, const ParticleInit& p, double mass);
  // Appends n blank slots [size(), size() + n) (zero kinematics, radius, mass, id and flags;
  // fields at their defaults), one array per job on all threads, for put() to fill: breakage
  // writes the fragments of many parents at once, each parent's into slots known beforehand.
  void extend(std::size_t n);
  // n fresh ids: [returned, returned + n), never handed out again.
  std::uint64_t take_ids(std::size_t n);
  // Writes a particle with id `id` into slot i as renew() does (fields at their defaults, zero
  // force and torque). Slots of different calls may be written on different threads.
  void put(std::size_t i, const ParticleInit& p, double mass, std::uint64_t id);
  // Removes all particles whose flags have pflag::remove; keeps the order of the others.
  // Returns the number removed. Neither this nor permute() may run while ghosts are present.
  std::size_t compact();
  // Reorders so that new slot k holds old slot order[k] (order is a permutation).
  void permute(const std::vector<std::size_t>& order);
  void clear_forces();

  // Named per-particle scalar fields owned by modules. Registering twice returns the same index.
  std::size_t add_field(const std::string& name, double initial_value);
  std::size_t field_index(const std::string& name) const;  // throws Error if unknown
  bool has_field(const std::string& name) const;
  std::vector<double>& field(std::size_t k) { return fields_[k]; }
  const std::vector<double>& field(std::size_t k) const { return fields_[k]; }
  const std::vector<std::string>& field_names() const { return field_names_; }
  const std::vector<double>& field_defaults() const { return field_defaults_; }

  std::uint64_t next_id() const { return next_id_; }
  void set_next_id(std::uint64_t n) { next_id_ = n; }  // checkpoints only

  // Density scaling (docs/models.md, "Time step"): a module that gives small particles a heavier
  // inertia registers the field `mass_scale` (s >= 1). mass[i] and inertia[i] are then the
  // inertial values the dynamics use (s times those of the solid sphere); physical_mass(i) is the
  // particle's real mass, mass[i] / s, which size distributions, outlets and mass balances count.
  static constexpr const char* mass_scale_field = "mass_scale";
  double mass_scale(std::size_t i) const { return scale_ == npos_ ? 1.0 : fields_[scale_][i]; }
  double physical_mass(std::size_t i) const { return mass[i] / mass_scale(i); }

  // Total physical mass (kg) and linear momentum of the inertial masses (kg m/s, the quantity
  // the contact forces conserve) — conservation checks and outputs.
  double total_mass() const;
  Vec3 total_momentum() const;

 private:
  static constexpr std::size_t npos_ = static_cast<std::size_t>(-1);
  std::uint64_t next_id_ = 1;
  std::size_t scale_ = npos_;  // index of the mass_scale field, if registered
  std::vector<std::vector<double>> fields_;
  std::vector<std::string> field_names_;
  std::vector<double> field_defaults_;
  // op(array, value of a fresh element) applied to every per-particle array, one job per array on
  // all threads when `threaded` (the arrays are independent)
  template <class Op>
  void each_array(Op&& op, bool threaded);
};

}  // namespace comminute
