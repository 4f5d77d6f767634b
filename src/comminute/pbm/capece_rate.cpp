#include "comminute/pbm/capece_rate.hpp"

#include <algorithm>
#include <cmath>

#include "comminute/core/csv_columns.hpp"
#include "comminute/core/error.hpp"

namespace comminute::pbm {

// Capece et al., AIChE J. 60 (2014) 2404, eq. 13: S_i = f_mat x_i ω Σ p_k (E_m,k − E_min,i)⁺
double CapeceRate::rate(double size, double /*volume*/) const {
  const double threshold = material_.threshold(size);  // E_m,min,i = (x E_m,min)/x_i
  double excess = 0;
  for (std::size_t k = 0; k < impacts_.energy.size(); ++k)
    excess += impacts_.probability[k] * std::max(0.0, impacts_.energy[k] - threshold);
  return material_.f_mat * size * omega_ * excess;
}

SpecificEnergyDistribution read_specific_energy_distribution(const CaseTable& t,
                                                             const std::string& key) {
  const auto path = t.input_file(key);
  const auto csv = CsvColumns::read(path, t.key_path(key));
  SpecificEnergyDistribution d{csv.column("specific_energy_J_per_kg"), csv.column("probability")};
  if (d.energy.empty()) throw InputError(path.string(), t.key_path(key), t.line(key), "no rows");
  double sum = 0;
  for (std::size_t r = 0; r < d.energy.size(); ++r) {
    if (d.energy[r] < 0 || d.probability[r] < 0)
      throw InputError(path.string(), t.key_path(key), csv.line_of_row(r),
                       "specific_energy_J_per_kg and probability must not be negative");
    sum += d.probability[r];
  }
  if (std::abs(sum - 1.0) > 1e-6)
    throw InputError(path.string(), t.key_path(key), csv.line_of_row(d.energy.size() - 1),
                     "the probabilities sum to " + std::to_string(sum) + ", not 1 (±1e-6)");
  return d;
}

namespace {
std::unique_ptr<SelectionFunction> make(const CaseTable& t, const ModelContext&) {
  // The energy-spectrum skeleton's keys belong to tuzcu_rajamani_variant / datta_rajamani_variant.
  for (const char* old : {"spectrum_file", "holdup", "captured_mass", "energy_share"})
    if (t.has(old))
      t.fail(old, std::string("capece takes Capece et al.'s parameters (impact_frequency, "
                              "specific_energy_file, f_mat, threshold_product), not '") +
                      old + "' (docs/pbm.md)");
  const auto material = fracture::read_vogel_peukert(t);
  const double omega = t.number("impact_frequency", Limits::positive());
  return std::make_unique<CapeceRate>(material, omega,
                                      read_specific_energy_distribution(t, "specific_energy_file"));
}
const bool registered = SelectionFunctionRegistry::add("capece", &make);
}  // namespace

}  // namespace comminute::pbm
