#include "comminute/io/case/dem_case.hpp"

#include <fmt/format.h>

#include <cmath>

#include "comminute/core/error.hpp"
#include "comminute/core/memory.hpp"
#include "comminute/core/units.hpp"
#include "comminute/engine/insertion.hpp"
#include "comminute/io/case/lammps_data.hpp"
#include "comminute/io/case/wall_builders.hpp"

namespace comminute::io {

namespace {

const Limits kPositive = Limits::positive();

void read_materials(const CaseTable& root, Simulation& sim) {
  const CaseTable mats = root.table("materials");
  if (mats.keys().empty()) mats.fail({}, "define at least one material, e.g. [materials.rock]");
  for (const auto& name : mats.keys()) {
    const CaseTable m = mats.table(name);
    Material mat;
    mat.name = name;
    mat.density = m.number("density", kPositive);
    mat.youngs_modulus = m.number("youngs_modulus", kPositive);
    mat.poisson_ratio = m.number("poisson_ratio", Limits{-1.0, 0.5, true, true});
    sim.materials.add(mat);
  }
}

PairInput read_pair(const CaseTable& t, const PairInput& base) {
  PairInput p = base;
  p.restitution = t.number("restitution", Limits{0.0, 1.0, true, false}, base.restitution);
  p.friction = t.number("friction", Limits::non_negative(), base.friction);
  p.rolling_friction = t.number("rolling_friction", Limits::non_negative(), base.rolling_friction);
  p.rolling_damping = t.number("rolling_damping", Limits::non_negative(), base.rolling_damping);
  p.cohesion_energy_density =
      t.number("cohesion_energy_density", Limits::non_negative(), base.cohesion_energy_density);
  return p;
}

std::uint16_t material_index(const CaseTable& t, std::string_view key, const Simulation& sim) {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < sim.materials.size(); ++k)
    names.push_back(sim.materials.material(static_cast<std::uint16_t>(k)).name);
  return static_cast<std::uint16_t>(sim.materials.find(t.choice(key, names)));
}

void read_interactions(const CaseTable& root, Simulation& sim) {
  PairInput base;
  std::vector<CaseTable> pairs;
  if (auto it = root.optional_table("interaction")) {
    base = read_pair(*it, base);
    pairs = it->tables("pairs");
  }
  const auto n = static_cast<std::uint16_t>(sim.materials.size());
  for (std::uint16_t a = 0; a < n; ++a)
    for (std::uint16_t b = a; b < n; ++b) sim.materials.set_pair(a, b, base);
  for (const auto& t : pairs) {
    std::vector<std::string> two = t.strings("materials");
    if (two.size() != 2) t.fail("materials", "expected two material names [\"a\", \"b\"]");
    int a = sim.materials.find(two[0]), b = sim.materials.find(two[1]);
    if (a < 0 || b < 0)
      t.fail("materials", fmt::format("unknown material \"{}\"", a < 0 ? two[0] : two[1]));
    sim.materials.set_pair(static_cast<std::uint16_t>(a), static_cast<std::uint16_t>(b),
                           read_pair(t, base));
  }
}

// [contact]: the law, rolling resistance and adhesion by name; each reads its own keys.
void read_contact(const CaseTable& root, Simulation& sim) {
  const CaseTable c = root.table("contact");
  sim.law = ContactLawRegistry::create(c.choice("model", ContactLawRegistry::names()), c);
  std::vector<std::string> rolling = RollingResistanceRegistry::names();
  rolling.insert(rolling.begin(), "none");
  const std::string r = c.choice("rolling", rolling, "none");
  if (r != "none") sim.rolling = RollingResistanceRegistry::create(r, c);
  std::vector<std::string> coh = CohesionRegistry::names();
  coh.insert(coh.begin(), "none");
  const std::string h = c.choice("cohesion", coh, "none");
  if (h != "none") sim.cohesion = CohesionRegistry::create(h, c);
}

Region read_region(const CaseTable& t) {
  Region g;
  const std::string shape = t.choice("shape", {"box", "cylinder"});
  if (shape == "box") {
    g.lo = t.vec3("lo");
    g.hi = t.vec3("hi");
    for (int a = 0; a < 3; ++a)
      if (!(g.hi[a] > g.lo[a])) t.fail("hi", "every component of hi must exceed lo");
  } else {
    g.shape = Region::Shape::cylinder;
    g.center = t.vec3("center");
    g.axis = t.vec3("axis", Limits::any(), {0, 0, 1});
    if (norm(g.axis) == 0) t.fail("axis", "the axis must not be zero");
    g.axis = g.axis / norm(g.axis);
    g.radius = t.number("radius", kPositive);
    g.length = t.number("length", kPositive);
  }
  return g;
}

std::shared_ptr<const SizeDistribution> read_size(const CaseTable& t) {
  SizeParameters p;
  const std::string kind = t.choice("distribution", SizeDistributionRegistry::names());
  if (kind == "fixed") {
    p.diameter = t.number("diameter", kPositive);
  } else if (kind == "uniform") {
    p.min = t.number("min", kPositive);
    p.max = t.number("max", kPositive);
  } else if (kind == "normal" || kind == "lognormal") {
    if (kind == "normal") {
      p.mean = t.number("mean", kPositive);
      p.sd = t.number("sd", kPositive);
    } else {
      p.median = t.number("median", kPositive);
      p.sigma = t.number("sigma", kPositive);
    }
    p.min = t.number("min", kPositive);
    p.max = t.number("max", kPositive);
  } else {
    p.diameters = t.numbers("diameters", kPositive);
    p.fractions = t.numbers("fractions", Limits::non_negative());
    p.mass_fractions = t.choice("basis", {"mass", "number"}, "mass") == "mass";
    if (p.diameters.empty()) t.fail("diameters", "the table is empty");
    if (p.fractions.size() != p.diameters.size())
      t.fail("fractions", fmt::format("has {} entries but diameters has {}", p.fractions.size(),
                                      p.diameters.size()));
    double sum = 0;
    for (double f : p.fractions) sum += f;
    if (std::abs(sum - 1.0) > 1e-6)
      t.fail("fractions", fmt::format("fractions sum to {}, not 1", sum));
  }
  if ((kind == "uniform" || kind == "normal" || kind == "lognormal") && !(p.max > p.min))
    t.fail("max", fmt::format("max ({}) must exceed min ({})", p.max, p.min));
  return SizeDistributionRegistry::create(kind, p);
}

// The smallest particle an insertion can create, and its material (for the time step).
struct SmallestParticle {
  double radius;
  std::uint16_t material;
};

SmallestParticle read_insertion(const CaseTable& t, std::size_t index, Simulation& sim) {
  const std::string type = t.choice("type", {"fill", "pour", "data_file"});
  const std::uint16_t mat = material_index(t, "material", sim);
  if (type == "data_file") {
    auto particles = read_lammps_data(t.input_file("file"), t.key_path("file"));
    double rmin = std::numeric_limits<double>::infinity();
    for (auto& p : particles) {
      p.material = mat;
      sim.particles.add(p);
      rmin = std::min(rmin, p.radius);
    }
    return {rmin, mat};
  }
  InsertionSpec s;
  s.label = fmt::format("insert[{}]", index);
  s.stream = index;
  s.pour = type == "pour";
  s.material = mat;
  s.density = sim.materials.material(mat).density;
  s.region = read_region(t.table("region"));
  s.size = read_size(t.table("size"));
  s.velocity = t.vec3("velocity", Limits::any(), {});
  s.velocity_spread = t.number("velocity_spread", Limits::non_negative(), 0.0);
  if (s.pour) {
    s.rate = t.number("rate", kPositive);
    s.count = static_cast<std::uint64_t>(t.integer("count", 0, 1'000'000'000, 0));
    s.start = t.number("start", Limits::non_negative(), 0.0);
    s.end = t.number("end", kPositive, std::numeric_limits<double>::infinity());
    s.interval = t.number("interval", kPositive, 1e-3);
  } else {
    const bool has_count = t.has("count"), has_fraction = t.has("volume_fraction");
    if (has_count == has_fraction) t.fail({}, "give exactly one of 'count' or 'volume_fraction'");
    if (has_count) s.count = static_cast<std::uint64_t>(t.integer("count", 1, 1'000'000'000));
    // particles, neighbour list and contact state: about 1 kB per particle
    if (exceeds_memory(1024.0 * static_cast<double>(s.count)))
      t.fail("count", fmt::format("{} particles need about {:.3g} GB, more than this machine's "
                                  "{:.3g} GB",
                                  s.count, 1024.0 * static_cast<double>(s.count) / 1e9,
                                  physical_memory_bytes() / 1e9));
    if (has_fraction)
      s.volume_fraction = t.number("volume_fraction", Limits{0.0, 0.5, true, false});
  }
  const double rmin = 0.5 * s.size->min_diameter();
  sim.modules.push_back(std::make_unique<InsertionModule>(std::move(s), sim.seed));
  return {rmin, mat};
}

}  // namespace

namespace {

// More steps than this is a mistake (a time step in the wrong unit, an end time in ms): at 10^6
// particle-steps/s a run of one particle would take 10^3 s per 10^9 steps; docs/case-file.md.
constexpr double max_dem_steps = 1e9;

// The run must take at least one step and a countable number of them (max_dem_steps).
void check_steps(const CaseTable& s, double end_time, double dt) {
  const std::string key = s.has("time_step") ? "time_step" : "end_time";
  if (!(dt > 0) || !std::isfinite(dt)) s.fail(key, fmt::format("time step {:.4g} s", dt));
  if (dt > end_time)
    s.fail(key, fmt::format("the time step {:.4g} s exceeds the end time {:.4g} s: the run would "
                            "take no step",
                            dt, end_time));
  if (end_time / dt > max_dem_steps)
    s.fail(key, fmt::format("end time {:.4g} s / time step {:.4g} s = {:.3g} steps, more than the "
                            "limit of {:.0e} steps",
                            end_time, dt, end_time / dt, max_dem_steps));
}

// Wall names become column names of timeseries.csv: refused here (check) rather than when the
// output is opened (run).
void check_wall_names(const std::vector<CaseTable>& tables, const Simulation& sim) {
  for (std::size_t k = 0; k < sim.walls.size() && k < tables.size(); ++k) {
    const std::string& n = sim.walls[k]->name;
    if (n.empty() || n.find_first_of(",\"\r\n[]") != std::string::npos)
      tables[k].fail("name", fmt::format("wall name '{}' cannot name a CSV column (empty, or "
                                         "holds a comma, quote, bracket or line break)",
                                         n));
    for (std::size_t j = 0; j < k; ++j)
      if (sim.walls[j]->name == n)
        tables[k].fail("name", fmt::format("two walls are named '{}'; names must differ", n));
  }
}

}  // namespace

DemCase build_dem_case(const CaseTable& root) {
  DemCase out;
  out.sim = std::make_unique<Simulation>();
  Simulation& sim = *out.sim;
  const CaseTable s = root.table("simulation");
  sim.seed =
      static_cast<std::uint64_t>(s.integer("seed", 0, std::numeric_limits<std::int64_t>::max(), 1));
  out.end_time = s.number("end_time", kPositive);
  sim.gravity = s.vec3("gravity", Limits::any(), {0, 0, -9.81});
  sim.options.skin = s.number("skin", Limits::non_negative(), 0.0);
  sim.options.sort_every = static_cast<int>(s.integer("sort_every", 0, 1'000'000, 20));

  read_materials(root, sim);
  read_interactions(root, sim);
  read_contact(root, sim);
  const auto walls = root.tables("walls");
  for (std::size_t k = 0; k < walls.size(); ++k) sim.walls.push_back(build_wall(walls[k], k, sim));

  const auto inserts = root.tables("insert");
  if (inserts.empty()) root.fail({}, "no particles: add at least one [[insert]] table");
  // Time step: a fraction of the Rayleigh time of the smallest particle of each inserted material
  // (MODELS.md); wall materials do not count.
  double t_rayleigh = std::numeric_limits<double>::infinity();
  SmallestParticle smallest{std::numeric_limits<double>::infinity(), 0};
  for (std::size_t k = 0; k < inserts.size(); ++k) {
    const SmallestParticle sp = read_insertion(inserts[k], k, sim);
    const Material& mat = sim.materials.material(sp.material);
    t_rayleigh =
        std::min(t_rayleigh, units::pi * sp.radius * std::sqrt(mat.density / mat.shear_modulus()) /
                                 (0.1631 * mat.poisson_ratio + 0.8766));
    if (sp.radius < smallest.radius) smallest = sp;
  }
  const double fraction = s.number("time_step_fraction", Limits{0.0, 1.0, true, false}, 0.2);
  if (s.has("time_step")) {
    sim.dt = s.number("time_step", kPositive);
    out.time_step_note =
        fmt::format("time step {:.4g} s (set) = {:.1f} % of the Rayleigh time {:.4g} s", sim.dt,
                    100 * sim.dt / t_rayleigh, t_rayleigh);
    if (sim.dt > 0.3 * t_rayleigh)
      out.warnings.push_back(fmt::format(
          "the time step {:.4g} s is {:.0f} % of the Rayleigh time {:.4g} s of the smallest "
          "particle; above ~30 % contacts are under-resolved and the run may blow up",
          sim.dt, 100 * sim.dt / t_rayleigh, t_rayleigh));
  } else {
    sim.dt = fraction * t_rayleigh;
    out.time_step_note = fmt::format("time step {:.4g} s = {:.0f} % of the Rayleigh time {:.4g} s",
                                     sim.dt, 100 * fraction, t_rayleigh);
  }
  check_steps(s, out.end_time, sim.dt);
  check_wall_names(walls, sim);
  // the law's own limit for the lightest pair
  const double mass =
      sim.materials.material(smallest.material).density * units::sphere_volume(smallest.radius);
  const StepLimit limit = sim.law->step_limit(
      sim.materials.pair(smallest.material, smallest.material), smallest.radius, mass);
  if (sim.dt > limit.dt)
    out.warnings.push_back(fmt::format("the time step {:.4g} s {}", sim.dt, limit.reason));
  return out;
}

DemCase load_plain_dem_case(const std::filesystem::path& path) {
  const CaseFile file = CaseFile::load(path);
  DemCase c = build_dem_case(file.root());
  file.reject_unknown();
  return c;
}

}  // namespace comminute::io
