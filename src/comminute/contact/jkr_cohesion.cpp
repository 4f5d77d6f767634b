// JKR adhesion (Johnson, Kendall & Roberts, Proc. R. Soc. Lond. A 324 (1971) 301): completes the
// Hertz normal force of the law to the JKR force-overlap curve (contact/jkr_curve.hpp),
//   F_adh(delta) = F_JKR(delta) - (4/3) E* sqrt(R*) delta^1.5,
// Gamma (`surface_energy`, J/m^2) the work of adhesion of the material pair, so that the
// pull-off force is 1.5 pi Gamma R*. Only with model = "hertz_mindlin". The engine evaluates
// touching contacts (delta > 0), so a run reaches at most -4/3 pi Gamma R* (at delta -> 0) before
// the contact separates; the neck at negative overlap is not followed.
#include <cmath>

#include "comminute/contact/cohesion.hpp"
#include "comminute/contact/jkr_curve.hpp"

namespace comminute {
namespace {

class JkrCohesion final : public Cohesion {
 public:
  std::string name() const override { return "jkr"; }
  void compute(const ContactKinematics& k, const PairParameters& p,
               ContactForces& out) const override {
    const double work = p.surface_energy;
    if (!(work > 0)) return;
    const double r = k.effective_radius, e = p.effective_modulus, d = k.overlap;
    const double hertz = 4.0 / 3.0 * e * std::sqrt(r) * std::pow(d, 1.5);
    out.normal_force += jkr_point(d, r, e, work).force - hertz;
    out.stored_energy += jkr_energy(d, r, e, work) - 0.4 * hertz * d;
  }
};

std::unique_ptr<Cohesion> make(const CaseTable& t) {
  if (t.has("model") && t.string("model") != "hertz_mindlin")
    t.fail("cohesion",
           "jkr adhesion completes the Hertz normal force: use model = \"hertz_mindlin\"");
  return std::make_unique<JkrCohesion>();
}
const bool registered = CohesionRegistry::add("jkr", &make);

}  // namespace
}  // namespace comminute
