// Simplified JKR cohesion (as LIGGGHTS' cohesion sjkr): an attractive normal force
// F_c = -k_c A over the contact area A; A = 2 pi R* δ is the small-overlap area of the
// intersection circle of two spheres (a^2 = R δ for equal spheres R, = 2 R* δ) and of a sphere
// with a plane (a^2 = 2 R δ). k_c is the cohesion energy density (J/m3) of the material pair.
#include "comminute/contact/cohesion.hpp"
#include "comminute/core/units.hpp"

namespace comminute {
namespace {

class SjkrCohesion final : public Cohesion {
 public:
  std::string name() const override { return "sjkr"; }
  void compute(const ContactKinematics& k, const PairParameters& p,
               ContactForces& out) const override {
    const double area = 2.0 * units::pi * k.effective_radius * k.overlap;
    const double f = p.cohesion_energy_density * area;
    out.normal_force -= f;
    out.stored_energy -= 0.5 * f * k.overlap;  // integral of k_c 2 pi R* δ dδ, attractive
  }
};

const bool registered = CohesionRegistry::add(
    "sjkr", [](const CaseTable&) { return std::make_unique<SjkrCohesion>(); });

}  // namespace
}  // namespace comminute
