// The "tuzcu_rajamani_variant" breakage rate: this code's variant, not the equations of Tuzcu &
// Rajamani, Minerals Eng. 24 (2011) 252. The energy-spectrum skeleton (docs/models.md eq. S5) with
// the Vogel–Peukert probability for one impact (eq. S7) stands for the paper's bed-impact (UFLC)
// breakage data; the paper's weighting of the energy classes E_k could not be established from
// the sources available here and is not implemented.
#include "comminute/pbm/energy_spectrum_rate.hpp"

namespace comminute::pbm {

namespace {
std::unique_ptr<SelectionFunction> make(const CaseTable& t, const ModelContext&) {
  return read_vogel_peukert_rate(t);
}
const bool registered = SelectionFunctionRegistry::add("tuzcu_rajamani_variant", &make);
}  // namespace

}  // namespace comminute::pbm
