#include "comminute/io/case/grain_compression_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "comminute/core/csv_columns.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/bonds_case.hpp"
#include "comminute/io/case/calibration_keys.hpp"
#include "comminute/io/case/dem_case.hpp"

namespace comminute::io {

namespace {

constexpr const char* kPlatenKey = "calibration.compression.platen";

ForceDisplacement read_curve(const CaseTable& t) {
  const auto path = t.input_file("file");
  const auto csv = CsvColumns::read(path, t.key_path("file"));
  ForceDisplacement c{csv.column("displacement [m]"), csv.column("force [N]")};
  if (c.displacement.size() < 2)
    t.fail("file", "the measured curve needs at least two rows (displacement [m], force [N])");
  for (std::size_t r = 0; r < c.displacement.size(); ++r)
    if (c.displacement[r] < 0 || (r > 0 && !(c.displacement[r] > c.displacement[r - 1])))
      throw InputError(path.string(), t.key_path("file"), csv.line_of_row(r),
                       "displacement [m] must be non-negative and increasing");
  if (!(*std::max_element(c.force.begin(), c.force.end()) > 0))
    t.fail("file", "the measured force never exceeds 0 N: nothing to fit");
  return c;
}

// J of the header: force misfit at the measured displacements plus the peak-force misfit.
double misfit(const ForceDisplacement& measured, const ForceDisplacement& sim, double peak_weight) {
  const double peak = *std::max_element(measured.force.begin(), measured.force.end());
  double sum = 0;
  for (std::size_t i = 0; i < measured.displacement.size(); ++i) {
    const double f = force_at(sim, measured.displacement[i]);
    if (!std::isfinite(f)) return std::numeric_limits<double>::infinity();
    sum += std::pow((f - measured.force[i]) / peak, 2);
  }
  double sim_peak = 0;
  for (std::size_t k = 0; k < sim.force.size(); ++k)
    if (sim.displacement[k] <= measured.displacement.back())
      sim_peak = std::max(sim_peak, sim.force[k]);
  return sum / static_cast<double>(measured.displacement.size()) +
         peak_weight * std::pow((sim_peak - peak) / peak, 2);
}

}  // namespace

double force_at(const ForceDisplacement& c, double x) {
  const auto& d = c.displacement;
  if (d.empty() || x < d.front() || x > d.back()) return std::numeric_limits<double>::quiet_NaN();
  const auto k = static_cast<std::size_t>(std::upper_bound(d.begin(), d.end(), x) - d.begin());
  if (k == d.size()) return c.force.back();
  const double w = (x - d[k - 1]) / (d[k] - d[k - 1]);
  return (1 - w) * c.force[k - 1] + w * c.force[k];
}

ForceDisplacement compress_grain(const CaseFile& file, const CompressionSpec& spec,
                                 double displacement) {
  DemCase dem = build_dem_case(file.root());
  add_bonds(file.root(), dem);
  decide_time_step(dem);
  Simulation& sim = *dem.sim;
  const Wall* platen = nullptr;
  for (const auto& w : sim.walls)
    if (w->name == spec.platen) platen = w.get();
  if (!platen)
    throw InputError(file.path().string(), kPlatenKey, 0,
                     fmt::format("no wall is named '{}'", spec.platen));
  const Vec3 v = platen->kinematics.velocity;
  if (!(norm(v) > 0) || norm2(platen->kinematics.angular_velocity) > 0)
    throw InputError(file.path().string(), kPlatenKey, 0,
                     fmt::format("wall '{}' must move at a constant velocity (its 'velocity' key), "
                                 "without rotation and without a control",
                                 spec.platen));
  const Vec3 dir = v / norm(v);
  sim.setup();
  ForceDisplacement out;
  double travel = 0, start = -1;
  while (sim.time < dem.end_time - 0.5 * sim.dt) {
    sim.step();
    // the platen moved |v| dt in this step; the particles push it back along −dir
    travel += norm(v) * sim.dt;
    const double f = -dot(platen->force, dir);
    if (start < 0 && f > spec.contact_force) start = travel;
    if (start < 0) continue;
    out.displacement.push_back(travel - start);
    out.force.push_back(f);
    if (travel - start >= displacement) break;
  }
  return out;
}

bool is_grain_calibration(const CaseTable& root) {
  const auto c = root.optional_table("calibration");
  return c && c->has("compression");
}

GrainCalibrationCase read_grain_calibration(const CaseFile& file) {
  const CaseTable root = file.root();
  const CaseTable c = root.table("calibration");
  const calibrate::MultiStartOptions options =
      read_calibration_options(c, c.tables("parameter").size());
  const FreeKeys free = read_free_parameters(c);
  const CaseTable t = c.table("compression");
  CompressionSpec spec;
  spec.platen = t.string("platen");
  spec.contact_force = t.number("contact_force", Limits::non_negative(), 0.0);
  spec.peak_weight = t.number("peak_weight", Limits::non_negative(), 1.0);
  const ForceDisplacement measured = read_curve(t);
  const double reach = measured.displacement.back();
  if (!root.has("bonds")) root.fail("", "a grain compression calibration needs a [bonds] table");

  const toml::table doc = parse_case_toml(file.path());
  const std::filesystem::path path = file.path();
  for (std::size_t k = 0; k < free.keys.size(); ++k) {
    auto n = toml::at_path(doc, free.keys[k]);
    if (!n || !(n.is_floating_point() || n.is_integer()))
      free.tables[k].fail("key",
                          fmt::format("'{}' is not a numeric key of the case", free.keys[k]));
  }
  // the case as given: reads (and so marks) its DEM and [bonds] keys and must reach the end of
  // the measured curve
  const ForceDisplacement first = compress_grain(file, spec, reach);
  if (first.displacement.empty() || first.displacement.back() < reach)
    root.table("simulation")
        .fail("end_time",
              fmt::format("the platen pressed {:.4g} m into the grain by the end time, less than "
                          "the last measured displacement {:.4g} m: raise end_time",
                          first.displacement.empty() ? 0.0 : first.displacement.back(), reach));

  GrainCalibrationCase out{calibrate::ParameterSpace(free.params),
                           options,
                           spec,
                           measured,
                           numbers_at(doc, free.keys),
                           {},
                           {},
                           {}};
  const std::vector<std::string> keys = free.keys;
  out.case_with = [doc, path, keys](const std::vector<double>& v) {
    return case_with_numbers(doc, path, keys, v);
  };
  out.simulate = [case_with = out.case_with, spec, reach](const std::vector<double>& v) {
    return compress_grain(case_with(v), spec, reach);
  };
  out.objective = [simulate = out.simulate, measured, spec](const std::vector<double>& v) {
    try {
      return misfit(measured, simulate(v), spec.peak_weight);
    } catch (const Error&) {  // a trial value the model or the time step refuses
      return std::numeric_limits<double>::infinity();
    }
  };
  return out;
}

}  // namespace comminute::io
