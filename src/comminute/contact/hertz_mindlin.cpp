// Hertz–Mindlin contact with Tsuji-type damping and Coulomb friction with tangential history, the
// LIGGGHTS/EDEM formulation (docs/models.md "Contact laws"): F_n = (4/3) E* sqrt(R*) δ^1.5 (Hertz,
// J. reine angew. Math. 1882), S_t = 8 G* a (Mindlin, J. Appl. Mech. 1949), dashpots
// -2 sqrt(5/6) β sqrt(S m*) v (Tsuji, Tanaka & Ishida, Powder Technol. 1992).
// Keys of [contact]: tangential_damping (bool, default true), tangential ("mindlin_rescale_force",
// the default: incremental force, rescaled on unloading, Thornton, Cummins & Cleary, Powder
// Technol. 2013 eq. 18; "mindlin": the total form F_t = -8 G* a xi, LAMMPS `mindlin`, whose
// energy ledger does not close while loaded contacts change their radius); docs/models.md T1.
#include <cmath>

#include "comminute/contact/tangential_friction.hpp"

namespace comminute {
namespace {

class HertzMindlin final : public ContactLawOf<HertzMindlin> {
 public:
  explicit HertzMindlin(const CaseTable& t)
      : tangential_damping_(t.boolean("tangential_damping", true)),
        rescale_(t.choice("tangential", {"mindlin_rescale_force", "mindlin"},
                          "mindlin_rescale_force") == "mindlin_rescale_force") {}
  std::string name() const override { return "hertz_mindlin"; }
  void declare(ContactStateStore& layout) override {
    slots_.declare(layout, dynamic_friction_, rescale_);
  }

  // always inlined into the batch loop of ContactLawOf (one call per run of contacts)
  [[gnu::always_inline]] void compute(const ContactKinematics& k, const PairParameters& p,
                                      const StateRef& s, ContactForces& out) const override {
    const double delta = k.overlap;
    const double a = std::sqrt(k.effective_radius * delta);  // contact radius sqrt(R* delta)
    const double sn = 2.0 * p.effective_modulus * a;         // S_n = 2 E* a
    const double kn = 2.0 / 3.0 * sn;                        // F = (4/3) E* sqrt(R*) delta^1.5
    const double beta = p.damping_beta;
    // F_n,d = -2 sqrt(5/6) beta sqrt(S_n m*) v_n (Tsuji-type, beta <= 0 here)
    const double gn = -2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(sn * k.effective_mass);
    // the same root for S_t = 8 G* a: sqrt(S_t m*) = sqrt(S_n m*) sqrt(4 G* / E*)
    const double fel = kn * delta;
    const double fd = gn * k.overlap_rate;
    out.elastic_normal_force = fel;
    out.normal_force = fel + fd;
    out.normal_elastic_energy = 0.4 * fel * delta;  // integral of F dδ = (2/5) k_n δ^2
    out.stored_energy = out.normal_elastic_energy;
    out.damping_dissipation = fd * k.overlap_rate * k.dt;
    const double st = 8.0 * p.effective_shear_modulus * a;  // Mindlin S_t = 8 G* a
    const double gt = tangential_damping_ ? gn * p.shear_normal_root : 0.0;
    if (rescale_)
      out.friction_dissipation +=
          follow_stiffness(s.vec3(slots_.spring), s.f64(slots_.stiffness), st);
    coulomb_tangential(k, st, gt, friction_limit(p, out.normal_force), s.vec3(slots_.spring),
                       slots_.flag(s), out);
  }

  double normal_stiffness(const PairParameters& p, double r, double, double delta) const override {
    return 2.0 * p.effective_modulus * std::sqrt(r * delta);  // dF/dδ = 2 E* sqrt(R* δ)
  }

 private:
  bool tangential_damping_;
  bool rescale_;  // tangential = "mindlin_rescale_force"
  TangentialSlots slots_;
};

const bool registered = ContactLawRegistry::add(
    "hertz_mindlin", [](const CaseTable& t) { return std::make_unique<HertzMindlin>(t); });

}  // namespace
}  // namespace comminute
