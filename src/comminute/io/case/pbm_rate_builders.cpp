// Case-file builders of the breakage rates ([rate] model = "...") and of the strength models of
// the stress-based rate ([rate] strength = "...").
#include <fmt/format.h>

#include "comminute/core/csv_columns.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/pbm_case.hpp"
#include "comminute/pbm/energy_spectrum_rate.hpp"
#include "comminute/pbm/power_law_rate.hpp"
#include "comminute/pbm/stress_rate.hpp"

namespace comminute::io {

namespace {

std::unique_ptr<pbm::SelectionFunction> power_law(const CaseTable& t, const PbmContext&) {
  pbm::PowerLawRate::Parameters p;
  p.k = t.number("k", Limits::non_negative());
  p.alpha = t.number("alpha");
  p.variable = t.choice("variable", {"size", "volume"}) == "size" ? pbm::GridCoordinate::size
                                                                  : pbm::GridCoordinate::volume;
  p.reference = t.number("reference", Limits::positive(), 1.0);
  if (t.has("mu")) p.mu = t.number("mu", Limits::positive());
  p.lambda = t.number("lambda", Limits::positive(), 2.0);
  return std::make_unique<pbm::PowerLawRate>(p);
}

std::unique_ptr<pbm::CriticalStress> power_law_strength(const CaseTable& t) {
  return std::make_unique<pbm::PowerLawStrength>(
      t.number("sigma0", Limits::positive()), t.number("m", Limits::positive()),
      t.number("reference_size", Limits::positive(), 1.0));
}

std::unique_ptr<pbm::CriticalStress> sigma50_strength(const CaseTable& t) {
  return std::make_unique<pbm::Sigma50Strength>(
      t.number("sigma_inf", Limits::positive()), t.number("x0", Limits::non_negative()),
      t.number("phi", Limits::any()), t.number("x_p", Limits::non_negative(), 0.0));
}

std::unique_ptr<pbm::SelectionFunction> stress(const CaseTable& t, const PbmContext&) {
  const double lambda = t.number("lambda", Limits::non_negative());
  const auto path = t.input_file("frequency_file");
  const auto csv = CsvColumns::read(path, t.key_path("frequency_file"));
  const auto s = csv.column("stress_Pa"), n = csv.column("frequency_per_s_Pa");
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
  const std::string name = t.choice("strength", CriticalStressBuilders::names());
  return std::make_unique<pbm::StressRate>(lambda, pbm::ContactFrequencySpectrum(s, n),
                                           CriticalStressBuilders::create(name, t));
}

// The skeleton S_i = (1/H) Σ λ_k m* P_i(η E_k/m*) with the model's probability.
std::unique_ptr<pbm::SelectionFunction> energy_spectrum(
    const CaseTable& t, std::unique_ptr<pbm::BreakageProbability> probability) {
  return std::make_unique<pbm::EnergySpectrumRate>(
      read_collision_spectrum(t, "spectrum_file"), t.number("holdup", Limits::positive()),
      t.number("captured_mass", Limits::positive()),
      t.number("energy_share", {0, 1, true, false}, 1.0), std::move(probability));
}

std::unique_ptr<pbm::BreakageProbability> vogel_peukert(const CaseTable& t, bool linearised) {
  return std::make_unique<pbm::VogelPeukertProbability>(t.number("f_mat", Limits::positive()),
                                                        t.number("x_e_min", Limits::non_negative()),
                                                        linearised);
}

std::unique_ptr<pbm::SelectionFunction> capece(const CaseTable& t, const PbmContext&) {
  return energy_spectrum(t, vogel_peukert(t, true));
}
std::unique_ptr<pbm::SelectionFunction> tuzcu_rajamani(const CaseTable& t, const PbmContext&) {
  return energy_spectrum(t, vogel_peukert(t, false));
}
std::unique_ptr<pbm::SelectionFunction> datta_rajamani(const CaseTable& t, const PbmContext&) {
  return energy_spectrum(t,
                         std::make_unique<pbm::FractureEnergyProbability>(read_fracture_energy(t)));
}

const bool registered = SelectionFunctionBuilders::add("power_law", &power_law) &&
                        SelectionFunctionBuilders::add("stress", &stress) &&
                        SelectionFunctionBuilders::add("capece", &capece) &&
                        SelectionFunctionBuilders::add("tuzcu_rajamani", &tuzcu_rajamani) &&
                        SelectionFunctionBuilders::add("datta_rajamani", &datta_rajamani) &&
                        CriticalStressBuilders::add("power_law", &power_law_strength) &&
                        CriticalStressBuilders::add("sigma50", &sigma50_strength);

}  // namespace

}  // namespace comminute::io
