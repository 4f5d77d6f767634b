#include "comminute/pbm/t10_breakage_function.hpp"

#include <cmath>
#include <memory>

#include "comminute/fracture/size_effect.hpp"

namespace comminute::pbm {

T10BreakageFunction::T10BreakageFunction(fracture::T10Model model, double specific_energy,
                                         std::function<double(double)> e50, double shape_factor)
    : model_(std::move(model)),
      specific_energy_(specific_energy),
      e50_(std::move(e50)),
      shape_factor_(shape_factor) {}

// docs/models.md eq. P1 at the parent's size.
double T10BreakageFunction::t10(double parent_size) const {
  return model_.t10(specific_energy_, e50_(parent_size));
}

double T10BreakageFunction::cumulative_mass(double v, double y) const {
  const double t = t10(std::cbrt(y / shape_factor_));
  return t10_progeny(model_, t).passing(std::cbrt(v / y));
}

namespace {
// Keys: the t10 model's (fracture::read_t10_model), `energy` (J/kg), and E50 either constant
// (`e50`, J/kg) or by the size effect (fracture::read_size_effect: e_inf, d0, phi).
std::unique_ptr<BreakageFunction> make(const CaseTable& t, const ModelContext& ctx) {
  fracture::T10Model model = fracture::read_t10_model(t);
  const double energy = t.number("energy", Limits::non_negative());
  std::function<double(double)> e50;
  if (t.has("e50")) {
    const double e = t.number("e50", Limits::positive());
    e50 = [e](double) { return e; };
  } else {
    const fracture::SizeEffect s = fracture::read_size_effect(t);
    e50 = [s](double d) { return s.e50(d); };
  }
  return std::make_unique<T10BreakageFunction>(std::move(model), energy, std::move(e50),
                                               ctx.grid.shape_factor());
}
const bool registered = BreakageFunctionRegistry::add("t10", &make);
}  // namespace

}  // namespace comminute::pbm
