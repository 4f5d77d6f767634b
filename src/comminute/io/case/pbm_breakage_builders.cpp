// Case-file builders of the breakage functions ([breakage] function = "...").
#include <fmt/format.h>

#include <cmath>

#include "comminute/core/csv_columns.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/pbm_case.hpp"
#include "comminute/pbm/austin_breakage_function.hpp"
#include "comminute/pbm/product_function.hpp"
#include "comminute/pbm/t10_breakage_function.hpp"
#include "comminute/pbm/tabulated_breakage_function.hpp"

namespace comminute::io {

namespace {

std::unique_ptr<pbm::BreakageFunction> diemer_olson(const CaseTable& t, const PbmContext&) {
  const double q = t.number("q", Limits::positive());
  const double nu = t.number("nu", Limits::at_least(2.0));  // at least binary breakage
  return std::make_unique<pbm::ProductFunction>(q, nu);
}

std::unique_ptr<pbm::BreakageFunction> austin(const CaseTable& t, const PbmContext& ctx) {
  pbm::AustinBreakageFunction::Parameters p;
  p.phi = t.number("phi", Limits::unit_interval());
  p.gamma = t.number("gamma", Limits::positive());
  p.beta = t.number("beta", Limits::positive());
  p.delta = t.number("delta", Limits::any(), 0.0);
  p.reference_size = t.number("reference_size", Limits::positive(), 1e-3);
  return std::make_unique<pbm::AustinBreakageFunction>(p, ctx.grid.shape_factor());
}

std::unique_ptr<pbm::BreakageFunction> tabulated(const CaseTable& t, const PbmContext&) {
  std::vector<double> ratio, passing;
  std::string key = "ratio";
  if (t.has("file")) {
    key = "file";
    const auto csv = CsvColumns::read(t.file_path("file"), t.key_path("file"));
    ratio = csv.column("size_ratio");
    passing = csv.column("cumulative_passing");
  } else {
    ratio = t.numbers("ratio", Limits::positive());
    passing = t.numbers("passing", Limits::unit_interval());
  }
  try {  // CumulativeTable's message says what is wrong with the table
    return std::make_unique<pbm::TabulatedBreakageFunction>(pbm::CumulativeTable(ratio, passing));
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    t.fail(key, e.what());
  }
}

std::array<double, 5> five(const CaseTable& t, const std::string& key) {
  const auto v = t.numbers(key, Limits::positive());
  if (v.size() != 5)
    t.fail(key, fmt::format("give 5 values (n = 2, 4, 25, 50, 75), got {}", v.size()));
  return {v[0], v[1], v[2], v[3], v[4]};
}

std::unique_ptr<pbm::BreakageFunction> t10(const CaseTable& t, const PbmContext& ctx) {
  pbm::T10BreakageFunction::Parameters p;
  p.A = t.number("A", {0, 100, true, false});
  p.b_prime = t.number("b", Limits::positive());
  p.specific_energy = t.number("energy", Limits::non_negative());
  p.family.alpha = five(t, "alpha");
  p.family.beta = five(t, "beta");
  std::function<double(double)> e50;
  if (t.has("e50")) {
    const double e = t.number("e50", Limits::positive());
    e50 = [e](double) { return e; };
  } else {  // Tavares: E50(d) = E∞ [1 + (d0/d)^φ]
    const double inf = t.number("e50_inf", Limits::positive());
    const double d0 = t.number("d0", Limits::positive());
    const double phi = t.number("phi", Limits::positive());
    e50 = [=](double d) { return inf * (1 + std::pow(d0 / d, phi)); };
  }
  return std::make_unique<pbm::T10BreakageFunction>(p, e50, ctx.grid.shape_factor());
}

const bool registered = BreakageFunctionBuilders::add("diemer_olson", &diemer_olson) &&
                        BreakageFunctionBuilders::add("austin", &austin) &&
                        BreakageFunctionBuilders::add("tabulated", &tabulated) &&
                        BreakageFunctionBuilders::add("t10", &t10);

}  // namespace

}  // namespace comminute::io
