// The "datta_rajamani" breakage rate: the energy-spectrum skeleton (docs/models.md eq. S5) with
// P = F_i(e), the fracture-energy distribution of the class (docs/models.md eq. F1-F3), standing
// for the drop-weight data of Datta & Rajamani, Int. J. Miner. Process. 64 (2002) 181 (eq. S8).
#include "comminute/pbm/energy_spectrum_rate.hpp"

namespace comminute::pbm {

namespace {
std::unique_ptr<SelectionFunction> make(const CaseTable& t, const ModelContext&) {
  return read_energy_spectrum_rate(
      t, std::make_unique<FractureEnergyProbability>(fracture::read_fracture_energy_model(t)));
}
const bool registered = SelectionFunctionRegistry::add("datta_rajamani", &make);
}  // namespace

}  // namespace comminute::pbm
