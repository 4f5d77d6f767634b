#pragma once
// Per-contact forces and branch vectors for the modules that need them (grid and bed statistics):
// the force loops fill, on the steps a module arms, each particle's Love–Weber moment
//   M_i = Σ_c sym(f_c ⊗ l_c)   (N m; f_c the force contact c exerts on i, l_c = contact point −
//   x_i)
// so that σ_i = M_i / V_i (Christoffersen, Mehrabadi & Nemat-Nasser 1981, J. Appl. Mech. 48,
// eq. 2.9), the count of its load-bearing particle contacts (normal force > threshold) and,
// when asked, a compact list of the step's contacts (force-chain export). On every step it also
// lists the contacts that began (first touch), for contact frequencies.
// A module asks for it in declare_contact_state (ContactPipeline::require_contact_stress), arms it
// in pre_force, reads it in post_force (ghosts still present; their moments are already folded
// onto their owners); the engine disarms it after post_force. Tension is positive.
#include <array>
#include <cstdint>
#include <vector>

#include "comminute/core/vec3.hpp"

namespace comminute {

using SymTensor = std::array<double, 6>;  // xx, yy, zz, xy, xz, yz

// sym(a ⊗ b) added to t, scaled by s.
inline void add_sym_outer(SymTensor& t, const Vec3& a, const Vec3& b, double s) {
  t[0] += s * a.x * b.x;
  t[1] += s * a.y * b.y;
  t[2] += s * a.z * b.z;
  t[3] += s * 0.5 * (a.x * b.y + a.y * b.x);
  t[4] += s * 0.5 * (a.x * b.z + a.z * b.x);
  t[5] += s * 0.5 * (a.y * b.z + a.z * b.y);
}

// One touching contact of a step, as the force loops saw it.
struct ContactRecord {
  std::uint32_t i = 0;  // slot of the first particle
  std::int32_t j = 0;   // slot of the second particle (>= 0), or -1 - wall index
  Vec3 xi;              // m, centre of i
  Vec3 xj;              // m, centre of j as seen across the pair (a wall: the contact point)
  Vec3 force;           // N, exerted on i
  double normal_force;  // N, the normal part (> 0 pushes apart)
};

// A contact that began this step: particle slots i and j, or j = -1 - wall index.
struct ContactStart {
  std::uint32_t i;
  std::int32_t j;
};

class ContactStress {
 public:
  // Set while the contacts are assembled. The threshold (N) of a load-bearing contact: the
  // first module to set it fixes it; a second, different one is refused (Error).
  void set_threshold(double fn);
  double threshold() const { return threshold_; }
  void want_contact_list() { list_wanted_ = true; }
  bool contact_list_wanted() const { return list_wanted_; }

  void arm() { armed_ = true; }
  void disarm() { armed_ = false; }
  bool armed() const { return armed_; }

  // For a module adding forces of its own in post_force (bonds) on an armed step: a force f on
  // slot i applied at lever l (contact point − centre).
  void add(std::size_t i, const Vec3& f, const Vec3& lever) {
    if (armed_) add_sym_outer(moment[i], f, lever, 1.0);
  }
  // By the engine before the force loops: the step's arrays sized for n slots and zeroed.
  void begin(std::size_t n);
  // By the engine after the ghosts' forces were folded: ghost g's moment and count added to its
  // owner (rotate(g, v) turns a vector from ghost g's frame to its owner's).
  template <class Rotate>
  void fold(std::size_t owned, const std::vector<std::uint32_t>& ghost_owner, Rotate rotate);

  // Filled by the force loops (armed steps; starts: every step).
  std::vector<SymTensor> moment;            // N m, per slot
  std::vector<std::uint32_t> load_bearing;  // particle–particle contacts with fn > threshold
  std::vector<ContactRecord> contacts;      // armed steps, when a module wants the list
  std::vector<ContactStart> starts;         // every step

 private:
  double threshold_ = 0;
  bool threshold_set_ = false;
  bool list_wanted_ = false;
  bool armed_ = false;
};

template <class Rotate>
void ContactStress::fold(std::size_t owned, const std::vector<std::uint32_t>& ghost_owner,
                         Rotate rotate) {
  if (!armed_) return;
  for (std::size_t g = 0; g < ghost_owner.size(); ++g) {
    const Vec3 e[3] = {rotate(g, Vec3{1, 0, 0}), rotate(g, Vec3{0, 1, 0}),
                       rotate(g, Vec3{0, 0, 1})};
    const std::size_t s = owned + g, o = ghost_owner[g];
    const SymTensor& m = moment[s];
    // Q M Qᵀ = Σ_ab M_ab (Q e_a) ⊗ (Q e_b), with the symmetric off-diagonal terms counted twice
    const double full[3][3] = {{m[0], m[3], m[4]}, {m[3], m[1], m[5]}, {m[4], m[5], m[2]}};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) add_sym_outer(moment[o], e[a], e[b], full[a][b]);
    moment[s] = {};
    load_bearing[o] += load_bearing[s];
    load_bearing[s] = 0;
  }
}

}  // namespace comminute
