#include "comminute/io/case/statistics_case.hpp"

#include <fmt/format.h>

#include <numbers>

#include "comminute/analysis/bed_statistics.hpp"
#include "comminute/analysis/grid_statistics.hpp"
#include "comminute/io/case/coarse_graining_case.hpp"

namespace comminute::io {

namespace {

std::size_t count(const CaseTable& t, const char* key, std::int64_t fallback) {
  return static_cast<std::size_t>(t.has(key) ? t.integer(key, 1, 100000) : fallback);
}

// A table's grid: `shape` = "box" (lo, hi, cells = [nx, ny, nz]) or "cylinder" (origin, axis,
// radius, inner_radius, z_min, z_max, cells = [n_r, n_theta, n_axial]). `region` (bed): one cell.
analysis::StatGridSpec read_grid(const CaseTable& t, bool region) {
  analysis::StatGridSpec g;
  g.cylindrical = t.choice("shape", {"box", "cylinder"}) == "cylinder";
  if (!region) {
    const auto n = t.numbers("cells", Limits::positive());
    if (n.size() != 3) t.fail("cells", "give three cell counts");
    for (std::size_t k = 0; k < 3; ++k) {
      if (n[k] != std::floor(n[k]) || n[k] > 100000)
        t.fail("cells", "cell counts are whole numbers from 1 to 100000");
      g.cells[k] = static_cast<std::size_t>(n[k]);
    }
    if (g.cells[0] * g.cells[1] * g.cells[2] > 10'000'000)
      t.fail("cells", "more than 10 million cells");
  }
  if (!g.cylindrical) {
    g.lo = t.vec3("lo");
    g.hi = t.vec3("hi");
    if (!(g.hi.x > g.lo.x && g.hi.y > g.lo.y && g.hi.z > g.lo.z))
      t.fail("hi", "hi must exceed lo in every direction");
    return g;
  }
  g.origin = t.vec3("origin", {}, Vec3{});
  g.axis = t.vec3("axis", {}, Vec3{0, 0, 1});
  if (!(norm(g.axis) > 0)) t.fail("axis", "the axis must not be zero");
  g.r_max = t.number("radius", Limits::positive());
  g.r_min = t.number("inner_radius", Limits::non_negative(), 0.0);
  if (!(g.r_min < g.r_max)) t.fail("inner_radius", "inner_radius must be below radius");
  g.z_min = t.number("z_min");
  g.z_max = t.number("z_max");
  if (!(g.z_max > g.z_min)) t.fail("z_max", "z_max must exceed z_min");
  return g;
}

int wall_index(const CaseTable& t, const char* key, const Simulation& sim) {
  if (!t.has(key)) return -1;
  const std::string name = t.string(key);
  for (std::size_t k = 0; k < sim.walls.size(); ++k)
    if (sim.walls[k]->name == name) return static_cast<int>(k);
  t.fail(key, fmt::format("no wall is named '{}'", name));
}

void add_grid(const CaseTable& root, const CaseTable& t, Simulation& sim) {
  analysis::GridStatisticsOptions o;
  o.primary_frequency_factor = coarse_graining_of(root).frequency_factor();
  o.grid = read_grid(t, false);
  o.start = t.number("start", Limits::non_negative(), 0.0);
  if (t.has("end")) o.end = t.number("end", Limits::positive());
  if (!(o.end > o.start)) t.fail("end", "the window must end after it starts");
  o.every = static_cast<std::uint64_t>(t.has("every") ? t.integer("every", 1, 1'000'000'000) : 1);
  o.rotate_with = wall_index(t, "rotate_with", sim);
  if (o.rotate_with >= 0 && !o.grid.cylindrical)
    t.fail("rotate_with", "only a cylindrical grid turns with a wall");
  o.spectrum_bins = count(t, "spectrum_bins", 50);
  o.spectrum_max = t.number("spectrum_max", Limits::non_negative(), 0.0);
  if (t.has("output_interval"))
    o.cadence.interval = t.number("output_interval", Limits::positive());
  sim.modules.push_back(std::make_unique<analysis::GridStatistics>(o));
}

void add_bed(const CaseTable& t, Simulation& sim) {
  analysis::BedStatisticsOptions o;
  o.region = read_grid(t, true);
  o.layers = count(t, "layers", 1);
  o.threshold = t.number("force_threshold", Limits::non_negative(), 0.0);
  o.every =
      static_cast<std::uint64_t>(t.has("every") ? t.integer("every", 1, 1'000'000'000) : 1000);
  o.load_wall = wall_index(t, "load_wall", sim);
  o.force_chains = t.boolean("force_chains", true);
  auto m = std::make_unique<analysis::BedStatistics>(o);
  m->register_fields(sim.particles);  // before a checkpoint is read: it holds the fields
  sim.modules.push_back(std::move(m));
}

}  // namespace

void add_statistics(const CaseTable& root, Simulation& sim) {
  if (auto t = root.optional_table("grid_statistics")) add_grid(root, *t, sim);
  if (auto t = root.optional_table("bed_statistics")) add_bed(*t, sim);
}

}  // namespace comminute::io
