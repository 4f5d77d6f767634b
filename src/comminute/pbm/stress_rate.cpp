#include "comminute/pbm/stress_rate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "comminute/core/csv_columns.hpp"
#include "comminute/core/error.hpp"

namespace comminute::pbm {

ContactFrequencySpectrum::ContactFrequencySpectrum(std::vector<double> stress,
                                                   std::vector<double> frequency)
    : s_(std::move(stress)), n_(std::move(frequency)), tail_(s_.size(), 0.0) {
  if (s_.size() < 2 || s_.size() != n_.size())
    throw Error("contact frequency spectrum: need at least two (stress, frequency) rows");
  for (std::size_t i = 1; i < s_.size(); ++i)
    if (!(s_[i] > s_[i - 1])) throw Error("contact frequency spectrum: stresses must increase");
  for (std::size_t i = s_.size() - 1; i > 0; --i)
    tail_[i - 1] = tail_[i] + 0.5 * (n_[i] + n_[i - 1]) * (s_[i] - s_[i - 1]);
}

double ContactFrequencySpectrum::integral_above(double sigma) const {
  if (sigma <= s_.front()) return tail_.front();
  if (sigma >= s_.back()) return 0.0;
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(s_.begin(), s_.end(), sigma) -
                                                 s_.begin());  // s_[i-1] <= σ < s_[i]
  const double w = (sigma - s_[i - 1]) / (s_[i] - s_[i - 1]);
  const double n_sigma = n_[i - 1] + w * (n_[i] - n_[i - 1]);
  return tail_[i] + 0.5 * (n_sigma + n_[i]) * (s_[i] - sigma);
}

// docs/models.md eq. S2: b(x) = λ ∫_{σcrit(x)}^{σmax} ṅ(σ) dσ.
double StressRate::rate(double size, double /*volume*/) const {
  const double sc = strength_->of_size(size);
  if (!std::isfinite(sc)) return 0.0;
  return lambda_ * spectrum_.integral_above(sc);
}

namespace {
// Keys lambda, frequency_file (CSV stress_Pa, frequency_per_s_Pa, or the grid statistics'
// spectrum: stress [Pa], primary_frequency or frequency [1/(s Pa)]) and strength = "<name>" with
// the strength model's keys (CriticalStressRegistry).
std::unique_ptr<SelectionFunction> make(const CaseTable& t, const ModelContext&) {
  const double lambda = t.number("lambda", Limits::non_negative());
  const auto path = t.input_file("frequency_file");
  const auto csv = CsvColumns::read(path, t.key_path("frequency_file"));
  // the headers of a hand-made table, or those of the DEM's grid_statistics_spectrum.csv
  const bool dem = csv.has("stress [Pa]");
  const auto s = csv.column(dem ? "stress [Pa]" : "stress_Pa");
  // the DEM's frequency per primary particle (= per particle without coarse graining)
  const char* dem_column = csv.has("primary_frequency [1/(s Pa)]") ? "primary_frequency [1/(s Pa)]"
                                                                   : "frequency [1/(s Pa)]";
  const auto n = csv.column(dem ? dem_column : "frequency_per_s_Pa");
  for (std::size_t r = 0; r < s.size(); ++r) {
    if (n[r] < 0)
      throw InputError(path.string(), t.key_path("frequency_file"), csv.line_of_row(r),
                       fmt::format("negative contact frequency {}", n[r]));
    if (s[r] < 0)
      throw InputError(path.string(), t.key_path("frequency_file"), csv.line_of_row(r),
                       fmt::format("negative stress {} Pa (a contact stress is >= 0)", s[r]));
    if (r > 0 && !(s[r] > s[r - 1]))
      throw InputError(path.string(), t.key_path("frequency_file"), csv.line_of_row(r),
                       "stress_Pa must increase");
  }
  if (s.size() < 2)
    throw InputError(path.string(), t.key_path("frequency_file"), 0, "need at least two rows");
  const std::string name = t.choice("strength", CriticalStressRegistry::names());
  return std::make_unique<StressRate>(lambda, ContactFrequencySpectrum(s, n),
                                      CriticalStressRegistry::create(name, t));
}
const bool registered = SelectionFunctionRegistry::add("stress", &make);
}  // namespace

}  // namespace comminute::pbm
