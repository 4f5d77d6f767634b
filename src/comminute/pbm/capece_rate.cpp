// The "capece" breakage rate: the energy-spectrum skeleton (docs/models.md eq. S5) with the
// Vogel–Peukert probability linearised for one impact (Capece, Bilgili & Davé,
// AIChE J. 60 (2014) 2404; docs/models.md eq. S6).
#include "comminute/pbm/energy_spectrum_rate.hpp"

namespace comminute::pbm {

namespace {
std::unique_ptr<SelectionFunction> make(const CaseTable& t, const ModelContext&) {
  return read_vogel_peukert_rate(t, /*linearised=*/true);
}
const bool registered = SelectionFunctionRegistry::add("capece", &make);
}  // namespace

}  // namespace comminute::pbm
