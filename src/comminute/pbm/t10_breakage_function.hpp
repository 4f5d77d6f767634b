#pragma once
// The t10 breakage function (JKMRC t10 with the UFRJ incomplete-beta t_n family; docs/models.md
// eq. B5): every parent is stressed at one mass-specific energy e, its progeny has
//   t10 = A [1 - exp(-b' e / E50(D))]   and   t_n = 100 I_{t10/100}(alpha_n, beta_n)
// (fracture::T10Model) and passes t_n % at d = D/n (t_1 = 100 %), interpolated as the DEM
// progeny is (t10_progeny, docs/models.md eq. P3).
#include <functional>

#include "comminute/fracture/t10_model.hpp"
#include "comminute/pbm/breakage_function.hpp"
#include "comminute/pbm/progeny_fractions.hpp"

namespace comminute::pbm {

class T10BreakageFunction : public BreakageFunction {
 public:
  // specific_energy: e (J/kg); e50(d): median fracture energy (J/kg) of a parent of size d (m).
  T10BreakageFunction(fracture::T10Model model, double specific_energy,
                      std::function<double(double)> e50, double shape_factor);

  double t10(double parent_size) const;
  double cumulative_mass(double v, double y) const override;

 private:
  fracture::T10Model model_;
  double specific_energy_;
  std::function<double(double)> e50_;
  double shape_factor_;
};

}  // namespace comminute::pbm
