#include "comminute/pbm/progeny_fractions.hpp"

namespace comminute::pbm {

// docs/models.md eq. P2-P3, at parent size 1 so that the curve's x is d/D.
ProgenyFractions t10_progeny(const fracture::T10Model& model, double t10) {
  return ProgenyFractions(fracture::ProgenyDistribution(1.0, t10, model.tn(t10)));
}

}  // namespace comminute::pbm
