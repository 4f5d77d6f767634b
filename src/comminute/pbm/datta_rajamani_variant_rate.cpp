// The "datta_rajamani_variant" breakage rate: this code's variant, not the equations of Datta &
// Rajamani, Int. J. Miner. Process. 64 (2002) 181. The energy-spectrum skeleton (docs/models.md
// eq. S5) with P = F_i(e), the fracture-energy distribution of the class (eq. F1–F3, S8), stands
// for the paper's drop-weight data; the paper's broken-mass function and its energy-dependent
// breakage function b_ij(E_k) could not be established from the sources available here: the
// breakage function is the energy-independent one of [breakage].
#include "comminute/pbm/energy_spectrum_rate.hpp"

namespace comminute::pbm {

namespace {
std::unique_ptr<SelectionFunction> make(const CaseTable& t, const ModelContext&) {
  return read_energy_spectrum_rate(
      t, std::make_unique<FractureEnergyProbability>(fracture::read_fracture_energy_model(t)));
}
const bool registered = SelectionFunctionRegistry::add("datta_rajamani_variant", &make);
}  // namespace

}  // namespace comminute::pbm
