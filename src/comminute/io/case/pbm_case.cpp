#include "comminute/io/case/pbm_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <limits>

#include "comminute/core/csv_columns.hpp"
#include "comminute/core/error.hpp"
#include "comminute/core/memory.hpp"
#include "comminute/pbm/population_split.hpp"

namespace comminute::io {

namespace {

constexpr double pi = 3.14159265358979323846;

pbm::GridCoordinate coordinate(const CaseTable& t) {
  return t.choice("coordinate", {"size", "volume"}, "size") == "size" ? pbm::GridCoordinate::size
                                                                      : pbm::GridCoordinate::volume;
}

std::size_t classes(const CaseTable& t) {
  const auto n = static_cast<std::size_t>(t.integer("classes", 1, 100000));
  // the solvers hold a few n x n matrices of doubles (breakage, its transform, work arrays)
  const double bytes = 4.0 * 8.0 * static_cast<double>(n) * static_cast<double>(n);
  if (exceeds_memory(bytes))
    t.fail("classes", fmt::format("{} classes need about {:.3g} GB ({} x {} matrices), more than "
                                  "this machine's {:.3g} GB",
                                  n, bytes / 1e9, n, n, physical_memory_bytes() / 1e9));
  return n;
}

// Fractions (in the initial table's basis) per class from a cumulative passing curve: linear in
// ln d between measured sizes; below the first, the power law through the first two points
// (Schuhmann tail) when both pass something, else nothing.
std::vector<double> from_cumulative(const pbm::SizeGrid& g, const std::vector<double>& sizes,
                                    const std::vector<double>& passing) {
  auto at = [&](double d) {
    if (d <= sizes.front()) {
      if (sizes.size() < 2 || !(passing[0] > 0) || !(passing[1] > passing[0])) return 0.0;
      const double slope = std::log(passing[1] / passing[0]) / std::log(sizes[1] / sizes[0]);
      return passing[0] * std::pow(d / sizes[0], slope);
    }
    if (d >= sizes.back()) return passing.back();
    const auto i = static_cast<std::size_t>(std::upper_bound(sizes.begin(), sizes.end(), d) -
                                            sizes.begin() - 1);
    const double w = std::log(d / sizes[i]) / std::log(sizes[i + 1] / sizes[i]);
    return passing[i] + w * (passing[i + 1] - passing[i]);
  };
  std::vector<double> f(g.classes());
  double prev = 0;
  for (std::size_t i = 0; i < g.classes(); ++i) {
    const double c = i + 1 == g.classes() ? 1.0 : at(g.size_edge(i + 1));
    f[i] = c - prev;
    prev = c;
  }
  return f;
}

std::vector<double> initial_fractions(const CaseTable& t, const pbm::SizeGrid& g) {
  const std::string kind = t.choice("kind", {"fractions", "monodisperse", "lognormal", "table"});
  const std::size_t n = g.classes();
  std::vector<double> f(n, 0.0);
  if (kind == "fractions") {
    f = t.numbers("fractions", Limits::non_negative());
    if (f.size() != n)
      t.fail("fractions",
             fmt::format("{} values given for {} classes (fine to coarse)", f.size(), n));
    double sum = 0;
    for (double x : f) sum += x;
    // 1e−6: six decimals is what measured distributions are typed with.
    if (std::abs(sum - 1) > 1e-6)
      t.fail("fractions", fmt::format("fractions sum to {:.9g}, not 1 (tolerance 1e-6)", sum));
  } else if (kind == "monodisperse") {
    const double d = t.number("size", Limits::positive());
    std::size_t k = n;
    for (std::size_t i = 0; i < n; ++i)
      if (d >= g.size_edge(i) && d <= g.size_edge(i + 1)) k = i;
    if (k == n)
      t.fail("size", fmt::format("{} m lies outside the grid [{}, {}] m", d, g.size_edge(0),
                                 g.size_edge(n)));
    f[k] = 1;
  } else if (kind == "lognormal") {
    const double median = t.number("median", Limits::positive());
    const double sigma = t.number("sigma", Limits::positive());
    auto cdf = [&](double d) {
      return d <= 0 ? 0.0
                    : 0.5 * boost::math::erfc(-std::log(d / median) / (sigma * std::sqrt(2.0)));
    };
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += f[i] = cdf(g.size_edge(i + 1)) - cdf(g.size_edge(i));
    if (!(sum > 1e-9)) t.fail("median", "the lognormal distribution lies outside the grid");
    for (double& x : f) x /= sum;
  } else {
    const auto csv = CsvColumns::read(t.input_file("file"), t.key_path("file"));
    const auto sizes = csv.column("size_m"), passing = csv.column("cumulative_passing");
    for (std::size_t r = 0; r < sizes.size(); ++r) {
      if (!(sizes[r] > 0) || (r > 0 && !(sizes[r] > sizes[r - 1])))
        throw InputError(t.input_file("file").string(), t.key_path("file"), csv.line_of_row(r),
                         "size_m must be positive and increasing");
      if (passing[r] < 0 || passing[r] > 1 + 1e-6 || (r > 0 && passing[r] < passing[r - 1]))
        throw InputError(t.input_file("file").string(), t.key_path("file"), csv.line_of_row(r),
                         "cumulative_passing must be non-decreasing within [0, 1]");
    }
    if (std::abs(passing.back() - 1) > 1e-6)
      throw InputError(t.input_file("file").string(), t.key_path("file"),
                       csv.line_of_row(passing.size() - 1),
                       fmt::format("cumulative_passing ends at {}, not 1", passing.back()));
    f = from_cumulative(g, sizes, passing);
  }
  return f;
}

}  // namespace

pbm::SizeGrid read_size_grid(const CaseTable& t) {
  const std::string spacing = t.choice("spacing", {"logarithmic", "geometric", "edges"});
  const auto coord = coordinate(t);
  const double k_v = t.number("shape_factor", Limits::positive(), pi / 6);
  if (spacing == "logarithmic") {
    const double lo = t.number("min", Limits::positive());
    const double hi = t.number("max", Limits::positive());
    if (!(hi > lo)) t.fail("max", fmt::format("max ({}) must exceed min ({})", hi, lo));
    return pbm::SizeGrid::logarithmic(lo, hi, classes(t), coord, k_v);
  }
  if (spacing == "geometric") {
    const double top = t.number("top", Limits::positive());
    const double ratio = t.number("ratio", {1.0, 1e6, true, false}, std::sqrt(2.0));
    return pbm::SizeGrid::geometric(top, ratio, classes(t), coord, k_v);
  }
  const auto e = t.numbers("edges", Limits::non_negative());
  if (e.size() < 2) t.fail("edges", "at least two edges (one class) are needed");
  for (std::size_t i = 1; i < e.size(); ++i)
    if (!(e[i] > e[i - 1]))
      t.fail("edges", fmt::format("edges must increase strictly: edges[{}] = {} is not above "
                                  "edges[{}] = {}",
                                  i, e[i], i - 1, e[i - 1]));
  return pbm::SizeGrid(e, coord, k_v);
}

std::unique_ptr<pbm::BreakageFunction> read_breakage(const CaseTable& b,
                                                     const pbm::ModelContext& ctx) {
  const auto pops = b.tables("population");
  if (pops.empty()) return build_named<pbm::BreakageFunctionRegistry>(b, "function", ctx);
  std::vector<pbm::PopulationSplit::Population> out;
  double last = 0;
  for (std::size_t i = 0; i < pops.size(); ++i) {
    const bool final_pop = i + 1 == pops.size();
    double upper = 0;
    if (!final_pop) {
      const double d = pops[i].number("below", Limits::positive());
      if (!(d > last))
        pops[i].fail("below", "population size limits must increase from one to the next");
      last = d;
      upper = ctx.grid.volume_of_size(d);
    } else if (pops[i].has("below")) {
      pops[i].fail("below", "the last population takes every larger parent: no 'below' here");
    }
    out.push_back({upper, build_named<pbm::BreakageFunctionRegistry>(pops[i], "function", ctx)});
  }
  return std::make_unique<pbm::PopulationSplit>(std::move(out));
}

namespace {
// RK4 takes fixed steps: one larger than an output interval would be shortened silently, and a
// count beyond the adaptive integrator's cap would run for hours.
void check_rk4_step(const CaseTable& s, const pbm::Problem& p) {
  const double h = p.integration.time_step;
  double smallest = std::numeric_limits<double>::infinity(), previous = 0;
  for (double t : p.times) {
    if (t > previous) smallest = std::min(smallest, t - previous);
    previous = t;
  }
  if (h > smallest)
    s.fail("time_step",
           fmt::format("the RK4 step {} s exceeds the smallest output interval {} s", h, smallest));
  const double steps = p.times.back() / h;
  const auto cap = static_cast<double>(p.integration.adaptive.max_steps);
  if (steps > cap)
    s.fail("time_step", fmt::format("{} s / {} s = {:.3g} RK4 steps, more than the cap of {} "
                                    "steps (the adaptive integrator's)",
                                    p.times.back(), h, steps, cap));
}
}  // namespace

pbm::Problem read_pbm_problem(const CaseTable& root) {
  const auto material = root.optional_table("material");
  const double density =
      material ? material->number("density", Limits::positive(), 1000.0) : 1000.0;
  pbm::Problem p(read_size_grid(root.table("grid")));
  p.density = density;
  const pbm::ModelContext ctx{p.grid, density};

  const CaseTable init = root.table("initial");
  const auto basis = init.choice("basis", {"mass", "volume", "number"}, "mass");
  const double total = init.number("total", Limits::positive(), 1.0);
  const auto f = initial_fractions(init, p.grid);
  p.initial_number.resize(static_cast<Eigen::Index>(f.size()));
  for (std::size_t i = 0; i < f.size(); ++i) {
    double per_particle = 1;  // amount carried by one particle in the basis
    if (basis != "number") per_particle = p.grid.pivot_volume(i) * (basis == "mass" ? density : 1);
    p.initial_number[static_cast<Eigen::Index>(i)] = total * f[i] / per_particle;
  }

  const CaseTable s = root.table("solver");
  std::vector<std::string> methods = {"classes", "batch_grinding"};
  for (const auto& m : pbm::MillRegistry::names()) methods.push_back(m);
  const std::string method = s.choice("method", methods, "classes");
  p.method = method == "classes"          ? pbm::Method::classes
             : method == "batch_grinding" ? pbm::Method::batch_grinding
                                          : pbm::Method::mill;
  if (p.method == pbm::Method::mill) {
    p.mill = pbm::MillRegistry::create(method, root.table("mill"), ctx);
    p.mill_spectrum = p.mill->spectrum();
  } else {
    p.rate = build_named<pbm::SelectionFunctionRegistry>(root.table("rate"), "model", ctx);
    p.function = read_breakage(root.table("breakage"), ctx);
  }
  p.kumar_correction = s.boolean("kumar_correction", true);
  if (!p.kumar_correction && p.method != pbm::Method::classes)
    s.fail("kumar_correction", "applies to method = \"classes\" only");
  p.integration.scheme = s.choice("integrator", {"adaptive", "rk4"}, "adaptive") == "rk4"
                             ? pbm::Scheme::rk4
                             : pbm::Scheme::adaptive;
  p.integration.time_step = s.number("time_step", Limits::positive(), 0.1);
  p.integration.adaptive.relative_tolerance =
      s.number("relative_tolerance", {0, 1, true, true}, 1e-6);
  p.integration.adaptive.absolute_tolerance =
      s.number("absolute_tolerance", {0, 1, true, true}, 1e-12);
  p.times = s.numbers("times", Limits::non_negative());
  if (p.times.empty()) s.fail("times", "give at least one output time (s)");
  for (std::size_t i = 1; i < p.times.size(); ++i)
    if (!(p.times[i] > p.times[i - 1]))
      s.fail("times", fmt::format("times must increase: times[{}] = {} s", i, p.times[i]));
  if (p.integration.scheme == pbm::Scheme::rk4) check_rk4_step(s, p);
  return p;
}

PbmOutput read_pbm_output(const CaseTable& root, const std::filesystem::path& case_path) {
  PbmOutput o;
  o.directory = case_path.parent_path() / (case_path.stem().string() + "_out");
  if (const auto t = root.optional_table("output")) {
    if (t->has("directory")) o.directory = t->file_path("directory");
    o.plots = t->boolean("plots", true);
  }
  return o;
}

}  // namespace comminute::io
