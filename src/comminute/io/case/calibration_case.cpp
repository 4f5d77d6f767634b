#include "comminute/io/case/calibration_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "comminute/analysis/size_distribution.hpp"
#include "comminute/core/csv_columns.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/pbm_case.hpp"
#include "comminute/pbm/problem.hpp"

namespace comminute::io {

namespace {

struct Measurement {
  std::size_t index;
  double time, weight;
  analysis::Basis basis;
  std::vector<double> sizes, passing;
};

// One pbm case (the calibration case itself or another) and the data compared with it.
struct DataSet {
  std::filesystem::path path;
  toml::table doc;
  std::vector<Measurement> data;
};

toml::table parse_toml(const std::filesystem::path& path) {
  (void)CaseFile::load(path);  // the text checks (UTF-8, keys) before toml++ parses it directly
  try {
    return toml::parse_file(path.string());
  } catch (const toml::parse_error& e) {
    throw InputError(path.string(), "", static_cast<long>(e.source().begin.line),
                     fmt::format("TOML syntax error: {}", e.description()));
  }
}

// Sets a number at a dotted key path ("a.b", "a.b[2]", "a.list[0].c") of a parsed document.
void set_number(toml::table& doc, const std::string& key, double value) {
  toml::node_view<toml::node> n = toml::at_path(doc, key);
  if (auto* f = n.as_floating_point()) {
    *f = value;
    return;
  }
  const auto dot = key.find_last_of('.');
  const auto bracket = key.find_last_of('[');
  if (bracket != std::string::npos && (dot == std::string::npos || bracket > dot)) {
    auto* arr = toml::at_path(doc, key.substr(0, bracket)).as_array();
    const auto i = std::stoul(key.substr(bracket + 1));
    arr->replace(arr->cbegin() + static_cast<long>(i), value);
    return;
  }
  toml::table* parent =
      dot == std::string::npos ? &doc : toml::at_path(doc, key.substr(0, dot)).as_table();
  parent->insert_or_assign(key.substr(dot == std::string::npos ? 0 : dot + 1), value);
}

CaseFile with_values(const DataSet& d, const std::vector<std::string>& keys,
                     const std::vector<double>& v) {
  toml::table doc = d.doc;
  for (std::size_t i = 0; i < keys.size(); ++i) set_number(doc, keys[i], v[i]);
  std::ostringstream s;
  s << doc;
  return CaseFile::parse(s.str(), d.path.string());
}

// Simulated cumulative passing at each measurement's sizes.
std::vector<std::vector<double>> simulate(const DataSet& d, const std::vector<std::string>& keys,
                                          const std::vector<double>& v) {
  const CaseFile cf = with_values(d, keys, v);
  pbm::Problem p = read_pbm_problem(cf.root());
  std::vector<double> times;
  for (const auto& m : d.data) times.push_back(m.time);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  p.times = times;
  const pbm::Solution s = pbm::solve(p);
  std::vector<double> edges, vol;
  for (std::size_t i = 0; i <= p.grid.classes(); ++i) edges.push_back(p.grid.size_edge(i));
  for (std::size_t i = 0; i < p.grid.classes(); ++i) vol.push_back(p.grid.pivot_volume(i));
  std::vector<std::vector<double>> out;
  for (const auto& m : d.data) {
    const auto k =
        static_cast<std::size_t>(std::find(times.begin(), times.end(), m.time) - times.begin());
    const Eigen::VectorXd& n = s.number[k];
    const analysis::SizeDistribution dist(
        edges, vol, std::vector<double>(n.data(), n.data() + n.size()), p.density);
    std::vector<double> c;
    for (double x : m.sizes) c.push_back(dist.cumulative_at(x, m.basis));
    out.push_back(std::move(c));
  }
  return out;
}

Measurement read_measurement(const CaseTable& t, std::size_t index) {
  Measurement m;
  m.index = index;
  m.time = t.number("time", Limits::non_negative());
  m.weight = t.number("weight", Limits::positive(), 1.0);
  m.basis = analysis::basis_from_name(t.choice("basis", {"mass", "volume", "number"}, "mass"));
  const auto path = t.input_file("file");
  const auto csv = CsvColumns::read(path, t.key_path("file"));
  m.sizes = csv.column("size_m");
  m.passing = csv.column("cumulative_passing");
  for (std::size_t r = 0; r < m.sizes.size(); ++r) {
    if (!(m.sizes[r] > 0) || (r > 0 && !(m.sizes[r] > m.sizes[r - 1])))
      throw InputError(path.string(), t.key_path("file"), csv.line_of_row(r),
                       "size_m must be positive and increasing");
    if (m.passing[r] < 0 || m.passing[r] > 1)
      throw InputError(
          path.string(), t.key_path("file"), csv.line_of_row(r),
          fmt::format("cumulative_passing {} is not a fraction in [0, 1]", m.passing[r]));
    // A cumulative passing never decreases with size; measured ones dip by their noise (the
    // examples' by up to 0.0023). More than measured_passing_noise is a mistake (columns
    // swapped, sizes in the wrong order, retained instead of passing): docs/pbm.md.
    constexpr double measured_passing_noise = 0.01;
    if (r > 0 && m.passing[r] < m.passing[r - 1] - measured_passing_noise)
      throw InputError(path.string(), t.key_path("file"), csv.line_of_row(r),
                       fmt::format("cumulative_passing {} at size {} is below {} at the smaller "
                                   "size {} by more than the {} allowed for measurement noise: a "
                                   "cumulative passing does not decrease with size",
                                   m.passing[r], m.sizes[r], m.passing[r - 1], m.sizes[r - 1],
                                   measured_passing_noise));
  }
  return m;
}

}  // namespace

CalibrationCase read_calibration(const CaseFile& file) {
  const CaseTable root = file.root();
  const CaseTable c = root.table("calibration");
  calibrate::MultiStartOptions o;
  o.starts = static_cast<std::size_t>(c.integer("starts", 1, 100000, 15));
  o.seed =
      static_cast<std::uint64_t>(c.integer("seed", 0, std::numeric_limits<std::int64_t>::max(), 1));
  o.threads = static_cast<int>(c.integer("threads", 0, 1024, 0));
  o.simplex_step = c.number("simplex_step", {0, 1, true, false}, 0.1);
  if (c.boolean("adaptive", false))  // Gao & Han coefficients, for many parameters
    o.nelder_mead = calibrate::NelderMeadOptions::adaptive(
        static_cast<std::size_t>(c.tables("parameter").size()));
  o.nelder_mead.x_tolerance = c.number("x_tolerance", Limits::positive(), 1e-4);
  o.nelder_mead.f_tolerance = c.number("f_tolerance", Limits::non_negative(), 1e-12);
  o.nelder_mead.f_relative_tolerance =
      c.number("f_relative_tolerance", Limits::non_negative(), 1e-6);
  o.nelder_mead.max_evaluations =
      static_cast<std::size_t>(c.integer("max_evaluations", 10, 10000000, 2000));

  std::vector<std::string> keys;
  std::vector<calibrate::FreeParameter> params;
  const auto ptabs = c.tables("parameter");
  if (ptabs.empty()) c.fail("parameter", "give at least one [[calibration.parameter]]");
  for (const auto& t : ptabs) {
    calibrate::FreeParameter p;
    p.name = t.string("key");
    p.lower = t.number("min");
    p.upper = t.number("max");
    if (!(p.upper > p.lower))
      t.fail("max", fmt::format("max ({}) must exceed min ({})", p.upper, p.lower));
    const std::string scale = t.choice("scale", {"auto", "log", "linear"}, "auto");
    p.scale = scale == "log"      ? calibrate::Scale::log
              : scale == "linear" ? calibrate::Scale::linear
                                  : calibrate::auto_scale(p.lower, p.upper);
    if (p.scale == calibrate::Scale::log && !(p.lower > 0))
      t.fail("min", "log scale needs a positive lower bound");
    // one key, one parameter: a second [[calibration.parameter]] of the same key would silently
    // override the first (the later value wins in every evaluation)
    if (std::find(keys.begin(), keys.end(), p.name) != keys.end())
      t.fail("key", fmt::format("'{}' is already a free parameter", p.name));
    keys.push_back(p.name);
    params.push_back(p);
  }

  // Data sets grouped by the case they are compared with.
  std::vector<DataSet> sets;
  std::map<std::string, std::size_t> by_case;
  const auto dtabs = c.tables("data");
  if (dtabs.empty()) c.fail("data", "give at least one [[calibration.data]]");
  for (std::size_t i = 0; i < dtabs.size(); ++i) {
    const auto path = dtabs[i].has("case") ? dtabs[i].file_path("case") : file.path();
    if (!by_case.count(path.string())) {
      by_case[path.string()] = sets.size();
      sets.push_back({path, parse_toml(path), {}});
      if (path != file.path()) {  // another pbm case: validate it whole
        const auto other = CaseFile::load(path);
        read_pbm_problem(other.root());
        read_pbm_output(other.root(), path);  // allowed there, unused here
        other.reject_unknown();
      }
    }
    sets[by_case[path.string()]].data.push_back(read_measurement(dtabs[i], i));
  }

  // Every free key must be a number in every case it is set in, and both bounds must give a
  // valid model (otherwise every start would fail in the same, confusing way).
  for (std::size_t k = 0; k < params.size(); ++k) {
    for (const auto& d : sets) {
      auto n = toml::at_path(d.doc, keys[k]);
      if (!n || !(n.is_floating_point() || n.is_integer()))
        ptabs[k].fail("key",
                      fmt::format("'{}' is not a numeric key of {}", keys[k], d.path.string()));
      std::vector<double> base(params.size());
      for (std::size_t j = 0; j < params.size(); ++j)
        base[j] = toml::at_path(d.doc, keys[j]).value<double>().value_or(0.0);
      for (const char* bound : {"min", "max"}) {
        auto v = base;
        v[k] = bound[1] == 'i' ? params[k].lower : params[k].upper;
        try {
          read_pbm_problem(with_values(d, keys, v).root());
        } catch (const InputError& e) {
          ptabs[k].fail(bound, fmt::format("the model rejects this bound: {}", e.what()));
        }
      }
    }
  }

  CalibrationCase cc{calibrate::ParameterSpace(params), o, {}, {}, {}};
  cc.objective = [sets, keys](const std::vector<double>& v) {
    double sum = 0;
    for (const auto& d : sets) {
      std::vector<std::vector<double>> sim;
      try {
        sim = simulate(d, keys, v);
      } catch (const Error&) {
        return std::numeric_limits<double>::infinity();
      }
      for (std::size_t m = 0; m < d.data.size(); ++m)
        for (std::size_t j = 0; j < sim[m].size(); ++j) {
          const double e = sim[m][j] - d.data[m].passing[j];
          sum += d.data[m].weight * e * e;
        }
    }
    return sum;
  };
  cc.fit = [sets, keys](const std::vector<double>& v) {
    std::vector<FitPoint> out;
    for (const auto& d : sets) {
      const auto sim = simulate(d, keys, v);
      for (std::size_t m = 0; m < d.data.size(); ++m)
        for (std::size_t j = 0; j < sim[m].size(); ++j)
          out.push_back({d.data[m].index, d.data[m].time, d.data[m].sizes[j], d.data[m].passing[j],
                         sim[m][j]});
    }
    return out;
  };
  const DataSet main{file.path(), parse_toml(file.path()), {}};
  cc.case_with = [main, keys](const std::vector<double>& v) { return with_values(main, keys, v); };
  return cc;
}

}  // namespace comminute::io
