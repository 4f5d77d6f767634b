#pragma once
// Builds a population-balance run (pbm::Problem) from a case file. Each model family is a registry
// that the models' own files fill; this reader only picks a model by name and passes its table:
//   [breakage] function = "<name>"   pbm::BreakageFunctionRegistry
//   [rate]     model = "<name>"      pbm::SelectionFunctionRegistry
//   [solver]   method = "<mill>"     pbm::MillRegistry (keys in [mill]); or "classes",
//                                    "batch_grinding" with [rate] and [breakage]
// Every key, its unit and default: docs/pbm.md.
#include <filesystem>
#include <memory>

#include "comminute/core/case_table.hpp"
#include "comminute/pbm/breakage_function.hpp"
#include "comminute/pbm/model_context.hpp"
#include "comminute/pbm/problem.hpp"
#include "comminute/pbm/selection_function.hpp"

namespace comminute::io {

// Creates by name from the table's `key`, failing with the list of known names.
template <class R>
auto build_named(const CaseTable& t, const std::string& key, const pbm::ModelContext& ctx) {
  const std::string name = t.choice(key, R::names());
  return R::create(name, t, ctx);
}

struct PbmOutput {
  std::filesystem::path directory;
  bool plots = true;
};

pbm::SizeGrid read_size_grid(const CaseTable& grid);
// [breakage]: one function, or [[breakage.population]] tables split by parent size.
std::unique_ptr<pbm::BreakageFunction> read_breakage(const CaseTable& breakage,
                                                     const pbm::ModelContext& ctx);
// Reads [material], [grid], [initial], [rate], [breakage], [solver]. Leaves unknown-key
// rejection to the caller (a calibration case has more tables).
pbm::Problem read_pbm_problem(const CaseTable& root);
PbmOutput read_pbm_output(const CaseTable& root, const std::filesystem::path& case_path);

}  // namespace comminute::io
