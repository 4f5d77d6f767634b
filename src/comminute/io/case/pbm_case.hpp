#pragma once
// Builds a population-balance run (pbm::Problem) from a case file. Model families are picked by
// name through registries that the model builder files fill:
//   [breakage] function = "diemer_olson" | "austin" | "t10" | "tabulated"   (pbm_breakage_builders)
//   [rate]     model = "power_law" | "stress" | "capece" | ...             (pbm_rate_builders)
// Every key, its unit and default: docs/pbm.md.
#include <filesystem>
#include <memory>

#include "comminute/core/case_table.hpp"
#include "comminute/core/registry.hpp"
#include "comminute/pbm/breakage_function.hpp"
#include "comminute/pbm/collision_spectrum.hpp"
#include "comminute/pbm/critical_stress.hpp"
#include "comminute/pbm/fracture_energy.hpp"
#include "comminute/pbm/problem.hpp"
#include "comminute/pbm/selection_function.hpp"

namespace comminute::io {

// What a model builder may need besides its own table.
struct PbmContext {
  const pbm::SizeGrid& grid;
  double density;  // kg/m³
};

using BreakageFunctionBuilders =
    Registry<pbm::BreakageFunction, const CaseTable&, const PbmContext&>;
using SelectionFunctionBuilders =
    Registry<pbm::SelectionFunction, const CaseTable&, const PbmContext&>;
using CriticalStressBuilders = Registry<pbm::CriticalStress, const CaseTable&>;

// Creates by name from the table's `key`, failing with the list of known names.
template <class R>
auto build_named(const CaseTable& t, const std::string& key, const PbmContext& ctx) {
  const std::string name = t.choice(key, R::names());
  return R::create(name, t, ctx);
}

struct PbmOutput {
  std::filesystem::path directory;
  bool plots = true;
};

pbm::SizeGrid read_size_grid(const CaseTable& grid);
// CSV named by `key` with columns energy_J, frequency_per_s.
pbm::CollisionSpectrum read_collision_spectrum(const CaseTable& t, const std::string& key);
// e50_inf (J/kg), d0 (m), phi, sigma, max_ratio.
pbm::FractureEnergyModel read_fracture_energy(const CaseTable& t);
// [breakage]: one function, or [[breakage.population]] tables split by parent size.
std::unique_ptr<pbm::BreakageFunction> read_breakage(const CaseTable& breakage,
                                                     const PbmContext& ctx);
// Reads [material], [grid], [initial], [rate], [breakage], [solver]. Leaves unknown-key
// rejection to the caller (a calibration case has more tables).
pbm::Problem read_pbm_problem(const CaseTable& root);
PbmOutput read_pbm_output(const CaseTable& root, const std::filesystem::path& case_path);

}  // namespace comminute::io
