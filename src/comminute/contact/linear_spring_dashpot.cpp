// Linear spring–dashpot contact (Cundall & Strack, Géotechnique 1979): F_n = k_n δ + c_n δ̇,
// c_n = 2|β| sqrt(m* k_n) with β = ln e / sqrt(ln² e + π²); tangential spring k_t = ratio·k_n
// with Coulomb limit (docs/models.md "Contact laws").
// Keys of [contact]: normal_stiffness (N/m, required), tangential_stiffness_ratio (-, default
// 2/7), tangential_damping (bool, default true).
#include <fmt/format.h>

#include <cmath>

#include "comminute/contact/tangential_friction.hpp"
#include "comminute/core/units.hpp"

namespace comminute {
namespace {

class LinearSpringDashpot final : public ContactLawOf<LinearSpringDashpot> {
 public:
  explicit LinearSpringDashpot(const CaseTable& t)
      : kn_(t.number("normal_stiffness", Limits::positive())),
        ratio_(t.number("tangential_stiffness_ratio", Limits{0.0, 1.0, true, false}, 2.0 / 7.0)),
        tangential_damping_(t.boolean("tangential_damping", true)) {}
  std::string name() const override { return "linear_spring_dashpot"; }
  void declare(ContactStateStore& layout) override { slots_.declare(layout, dynamic_friction_); }

  void compute(const ContactKinematics& k, const PairParameters& p, const StateRef& s,
               ContactForces& out) const override {
    const double cn = -2.0 * p.damping_beta * std::sqrt(k.effective_mass * kn_);
    const double fel = kn_ * k.overlap;
    const double fd = cn * k.overlap_rate;
    out.elastic_normal_force = fel;
    out.normal_force = fel + fd;
    out.normal_elastic_energy = 0.5 * fel * k.overlap;
    out.stored_energy = out.normal_elastic_energy;
    out.damping_dissipation = fd * k.overlap_rate * k.dt;
    const double kt = ratio_ * kn_;
    const double ct =
        tangential_damping_ ? -2.0 * p.damping_beta * std::sqrt(k.effective_mass * kt) : 0.0;
    coulomb_tangential(k, kt, ct, friction_limit(p, out.normal_force), s.vec3(slots_.spring),
                       slots_.flag(s), out);
  }

  double normal_elastic_energy(const PairParameters&, double, double delta) const override {
    const double fel = kn_ * delta;  // compute()'s
    return 0.5 * fel * delta;
  }

  // The contact time pi sqrt(m*/k_n) of the lightest pair (m* = m/2) resolved with 10 steps.
  StepLimit step_limit(const PairParameters&, double, double mass) const override {
    const double tc = units::pi * std::sqrt(0.5 * mass / kn_);
    return {tc / 10,
            fmt::format("resolves the linear contact time {:.4g} s with fewer than 10 steps", tc)};
  }

 private:
  double kn_, ratio_;
  bool tangential_damping_;
  TangentialSlots slots_;
};

const bool registered = ContactLawRegistry::add("linear_spring_dashpot", [](const CaseTable& t) {
  return std::make_unique<LinearSpringDashpot>(t);
});

}  // namespace
}  // namespace comminute
