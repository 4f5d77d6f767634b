// Hertz–Mindlin contact with Tsuji-type damping and Coulomb friction with tangential history
// (MODELS.md "Contact mechanics"; the LIGGGHTS/EDEM formulation).
#include <cmath>

#include "comminute/contact/tangential_friction.hpp"

namespace comminute {
namespace {

class HertzMindlin final : public ContactLaw {
 public:
  explicit HertzMindlin(const ContactOptions& o) : opt_(o) {}
  std::string name() const override { return "hertz_mindlin"; }

  void compute(const ContactKinematics& k, const PairParameters& p, ContactHistory& h,
               ContactForces& out) const override {
    const double delta = k.overlap;
    const double a = std::sqrt(k.effective_radius * delta);  // contact radius sqrt(R* delta)
    const double sn = 2.0 * p.effective_modulus * a;         // S_n = 2 E* a
    const double kn = 2.0 / 3.0 * sn;                        // F = (4/3) E* sqrt(R*) delta^1.5
    const double beta = p.damping_beta;
    // F_n,d = -2 sqrt(5/6) beta sqrt(S_n m*) v_n (Tsuji-type, beta <= 0 here)
    const double gn = -2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(sn * k.effective_mass);
    const double fel = kn * delta;
    const double fd = gn * k.overlap_rate;
    out.elastic_normal_force = fel;
    out.normal_force = fel + fd;
    out.normal_elastic_energy = 0.4 * fel * delta;  // integral of F dδ = (2/5) k_n δ^2
    out.stored_energy = out.normal_elastic_energy;
    out.damping_dissipation = fd * k.overlap_rate * k.dt;
    const double st = 8.0 * p.effective_shear_modulus * a;  // Mindlin S_t = 8 G* a
    const double gt = opt_.tangential_damping
                          ? -2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(st * k.effective_mass)
                          : 0.0;
    coulomb_tangential(k, st, gt, p.friction * std::abs(out.normal_force), h, out);
  }

  double normal_stiffness(const PairParameters& p, double r, double, double delta) const override {
    return 2.0 * p.effective_modulus * std::sqrt(r * delta);  // dF/dδ = 2 E* sqrt(R* δ)
  }

 private:
  ContactOptions opt_;
};

const bool registered = ContactLawRegistry::add(
    "hertz_mindlin", [](const ContactOptions& o) { return std::make_unique<HertzMindlin>(o); });

}  // namespace
}  // namespace comminute
