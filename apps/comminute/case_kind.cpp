#include "case_kind.hpp"

#include <algorithm>

#include "comminute/core/case_table.hpp"

namespace comminute::app {

namespace {
CaseKind kind_of(const CaseTable& root) {
  if (root.has("couple")) return CaseKind::chain;
  const auto calibration = root.optional_table("calibration");
  if (root.has("simulation"))
    return calibration && calibration->has("compression") ? CaseKind::grain_fit : CaseKind::dem;
  if (!root.has("grid")) return CaseKind::dem;  // its reader names what is missing
  return calibration ? CaseKind::population_balance_fit : CaseKind::population_balance;
}
}  // namespace

CaseKind case_kind(const std::filesystem::path& file) {
  return kind_of(CaseFile::load(file).root());
}

void require_case_kind(const std::filesystem::path& file,
                       std::initializer_list<CaseKind> accepted) {
  const CaseFile copy = CaseFile::load(file);
  const CaseTable root = copy.root();
  const CaseKind kind = kind_of(root);
  if (std::find(accepted.begin(), accepted.end(), kind) != accepted.end()) return;
  switch (kind) {
    case CaseKind::chain:
      root.fail("couple",
                "this table makes the case a DEM-to-population-balance chain: "
                "run it with `comminute couple`");
    case CaseKind::grain_fit:
      root.fail("calibration",
                "with [calibration.compression] the case is a fit of bond parameters "
                "to a grain's compression: run it with `comminute calibrate` "
                "(without [calibration], `comminute run` runs the DEM case)");
    case CaseKind::population_balance:
      root.fail("grid",
                "a [grid] and no [simulation] make the case a population balance: "
                "run it with `comminute pbm`");
    case CaseKind::population_balance_fit:
      root.fail("calibration",
                "a population balance with [calibration] is a fit: "
                "run it with `comminute calibrate` "
                "(without [calibration], `comminute pbm` solves it)");
    case CaseKind::dem:
      break;
  }
  root.fail("simulation",
            "this table makes the case a DEM case: run it with `comminute run` "
            "(with [calibration.compression] it is a grain compression fit, "
            "for `comminute calibrate`)");
}

}  // namespace comminute::app
