#pragma once
// Materials and per-pair interaction parameters (SI units).
#include <cstdint>
#include <string>
#include <vector>

namespace comminute {

struct Material {
  std::string name;
  double density = 0.0;         // kg/m3
  double youngs_modulus = 0.0;  // Pa
  double poisson_ratio = 0.0;   // -
  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
};

// What a user sets for a pair of materials.
struct PairInput {
  double restitution = 0.5;              // normal coefficient of restitution, (0, 1]
  double friction = 0.5;                 // static Coulomb friction coefficient mu_s
  double dynamic_friction = -1.0;        // mu_d while sliding; < 0: the same as mu_s
  double rolling_friction = 0.0;         // rolling resistance coefficient (dimensionless)
  double cohesion_energy_density = 0.0;  // J/m3, SJKR cohesion (LIGGGHTS' cohesionEnergyDensity)
  double rolling_damping = 0.0;          // viscous damping ratio of the EPSD rolling model
  double surface_energy = 0.0;           // J/m2, work of adhesion Gamma of the JKR cohesion
};

// PairInput plus the derived constants the contact laws use (dynamic_friction resolved: >= 0).
struct PairParameters : PairInput {
  double effective_modulus = 0.0;        // E*, 1/E* = (1-v1^2)/E1 + (1-v2^2)/E2  [Pa]
  double effective_shear_modulus = 0.0;  // G*, 1/G* = 2(2-v1)(1+v1)/E1 + ...      [Pa]
  double damping_beta = 0.0;             // beta = ln e / sqrt(ln^2 e + pi^2) (<= 0), linear law
  double shear_normal_root = 0.0;        // sqrt(8 G* a / (2 E* a)) = sqrt(4 G* / E*): Mindlin's
                                         // S_t / S_n under the root (a law's dashpots share a root)
};

class MaterialTable {
 public:
  // Adds a material; returns its index. Pair parameters default to PairInput{} until set.
  std::uint16_t add(const Material& m);
  void set_pair(std::uint16_t a, std::uint16_t b, const PairInput& p);
  const Material& material(std::uint16_t k) const { return materials_[k]; }
  std::size_t size() const { return materials_.size(); }
  const PairParameters& pair(std::uint16_t a, std::uint16_t b) const {
    return pairs_[static_cast<std::size_t>(a) * materials_.size() + b];
  }
  // True when some pair slides with a dynamic friction coefficient other than its static one.
  bool has_dynamic_friction() const;
  // Index of a material by name, or -1.
  int find(const std::string& name) const;

 private:
  void rebuild_pair(std::uint16_t a, std::uint16_t b, const PairInput& p);
  std::vector<Material> materials_;
  std::vector<PairInput> inputs_;  // n x n
  std::vector<PairParameters> pairs_;
};

}  // namespace comminute
