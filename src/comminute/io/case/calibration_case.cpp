#include "comminute/io/case/calibration_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "comminute/analysis/size_distribution.hpp"
#include "comminute/core/csv_columns.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/calibration_keys.hpp"
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

CaseFile with_values(const DataSet& d, const std::vector<std::string>& keys,
                     const std::vector<double>& v) {
  return case_with_numbers(d.doc, d.path, keys, v);
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
  const calibrate::MultiStartOptions o = read_calibration_options(c, c.tables("parameter").size());
  const FreeKeys free = read_free_parameters(c);
  const std::vector<std::string>& keys = free.keys;
  const std::vector<calibrate::FreeParameter>& params = free.params;
  const std::vector<CaseTable>& ptabs = free.tables;

  // Data sets grouped by the case they are compared with.
  std::vector<DataSet> sets;
  std::map<std::string, std::size_t> by_case;
  const auto dtabs = c.tables("data");
  if (dtabs.empty()) c.fail("data", "give at least one [[calibration.data]]");
  for (std::size_t i = 0; i < dtabs.size(); ++i) {
    const auto path = dtabs[i].has("case") ? dtabs[i].file_path("case") : file.path();
    if (!by_case.count(path.string())) {
      by_case[path.string()] = sets.size();
      sets.push_back({path, parse_case_toml(path), {}});
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
      const std::vector<double> base = numbers_at(d.doc, keys);
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
  const DataSet main{file.path(), parse_case_toml(file.path()), {}};
  cc.case_with = [main, keys](const std::vector<double>& v) { return with_values(main, keys, v); };
  return cc;
}

}  // namespace comminute::io
