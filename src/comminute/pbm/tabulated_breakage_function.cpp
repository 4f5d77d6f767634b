#include "comminute/pbm/tabulated_breakage_function.hpp"

#include <cmath>
#include <memory>

#include "comminute/core/csv_columns.hpp"
#include "comminute/core/error.hpp"

namespace comminute::pbm {

double TabulatedBreakageFunction::cumulative_mass(double v, double y) const {
  return table_.passing(std::cbrt(v / y));
}

namespace {
// `ratio` and `passing` lists, or `file` (CSV size_ratio, cumulative_passing).
std::unique_ptr<BreakageFunction> make(const CaseTable& t, const ModelContext&) {
  std::vector<double> ratio, passing;
  std::string key = "ratio";
  if (t.has("file")) {
    key = "file";
    const auto csv = CsvColumns::read(t.input_file("file"), t.key_path("file"));
    ratio = csv.column("size_ratio");
    passing = csv.column("cumulative_passing");
  } else {
    ratio = t.numbers("ratio", Limits::positive());
    passing = t.numbers("passing", Limits::unit_interval());
  }
  try {  // CumulativeTable's message says what is wrong with the table
    return std::make_unique<TabulatedBreakageFunction>(CumulativeTable(ratio, passing));
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    t.fail(key, e.what());
  }
}
const bool registered = BreakageFunctionRegistry::add("tabulated", &make);
}  // namespace

}  // namespace comminute::pbm
