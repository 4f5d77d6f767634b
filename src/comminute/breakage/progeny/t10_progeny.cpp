#include "comminute/breakage/progeny/t10_progeny.hpp"

namespace comminute::breakage {

// docs/models.md eq. P1.
double T10Progeny::t10(double specific_energy, double e50) const {
  return model_.t10(specific_energy, e50);
}

// docs/models.md eq. P2-P3.
ProgenyDistribution T10Progeny::distribution(double d, double t10) const {
  return ProgenyDistribution(d, t10, model_.tn(t10));
}

fracture::T10Parameters T10Progeny::illustrative() {
  fracture::T10Parameters p;
  p.alpha = {0.975, 1.062, 0.918, 0.942, 0.929};
  p.beta = {2.667, 1.955, 0.393, 0.249, 0.183};
  return p;
}

namespace {
// Keys A, b_prime, alpha, beta (fracture::read_t10_model), e50b (fracture::read_e50b_rule).
std::unique_ptr<ProgenyModel> make(const CaseTable& t) {
  return std::make_unique<T10Progeny>(fracture::read_t10_model(t).parameters(),
                                      fracture::read_e50b_rule(t));
}
const bool registered = ProgenyRegistry::add("t10", &make);
}  // namespace

}  // namespace comminute::breakage
