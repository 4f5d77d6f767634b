// Linear spring–dashpot contact: F_n = k_n δ + c_n δ̇, c_n = 2|β| sqrt(m* k_n) with β(e)
// (MODELS.md "Contact mechanics"); tangential spring k_t = ratio·k_n with Coulomb limit.
#include <cmath>

#include "comminute/contact/tangential_friction.hpp"

namespace comminute {
namespace {

class LinearSpringDashpot final : public ContactLaw {
 public:
  explicit LinearSpringDashpot(const ContactOptions& o) : opt_(o) {}
  std::string name() const override { return "linear_spring_dashpot"; }

  void compute(const ContactKinematics& k, const PairParameters& p, ContactHistory& h,
               ContactForces& out) const override {
    const double kn = opt_.linear_normal_stiffness;
    const double cn = -2.0 * p.damping_beta * std::sqrt(k.effective_mass * kn);
    const double fel = kn * k.overlap;
    const double fd = cn * k.overlap_rate;
    out.elastic_normal_force = fel;
    out.normal_force = fel + fd;
    out.normal_elastic_energy = 0.5 * fel * k.overlap;
    out.stored_energy = out.normal_elastic_energy;
    out.damping_dissipation = fd * k.overlap_rate * k.dt;
    const double kt = opt_.linear_tangential_ratio * kn;
    const double ct =
        opt_.tangential_damping ? -2.0 * p.damping_beta * std::sqrt(k.effective_mass * kt) : 0.0;
    coulomb_tangential(k, kt, ct, p.friction * std::abs(out.normal_force), h, out);
  }

  double normal_stiffness(const PairParameters&, double, double, double) const override {
    return opt_.linear_normal_stiffness;
  }

 private:
  ContactOptions opt_;
};

const bool registered = ContactLawRegistry::add(
    "linear_spring_dashpot",
    [](const ContactOptions& o) { return std::make_unique<LinearSpringDashpot>(o); });

}  // namespace
}  // namespace comminute
