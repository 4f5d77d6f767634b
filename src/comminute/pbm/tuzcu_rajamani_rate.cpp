// The "tuzcu_rajamani" breakage rate: the energy-spectrum skeleton (docs/models.md eq. S5) with the
// Vogel–Peukert probability for one impact standing for the bed-impact data of
// Tuzcu & Rajamani, Minerals Eng. 24 (2011) 252 (docs/models.md eq. S7).
#include "comminute/pbm/energy_spectrum_rate.hpp"

namespace comminute::pbm {

namespace {
std::unique_ptr<SelectionFunction> make(const CaseTable& t, const ModelContext&) {
  return read_vogel_peukert_rate(t, /*linearised=*/false);
}
const bool registered = SelectionFunctionRegistry::add("tuzcu_rajamani", &make);
}  // namespace

}  // namespace comminute::pbm
