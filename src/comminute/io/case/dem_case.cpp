#include "comminute/io/case/dem_case.hpp"

#include <fmt/format.h>

#include <cmath>

#include "comminute/core/error.hpp"
#include "comminute/core/memory.hpp"
#include "comminute/core/units.hpp"
#include "comminute/engine/insertion.hpp"
#include "comminute/io/case/cluster_case.hpp"
#include "comminute/io/case/coarse_graining_case.hpp"
#include "comminute/io/case/collisions_case.hpp"
#include "comminute/io/case/lammps_data.hpp"
#include "comminute/io/case/machine_case.hpp"
#include "comminute/io/case/periodic_case.hpp"
#include "comminute/io/case/statistics_case.hpp"
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
  p.surface_energy = t.number("surface_energy", Limits::non_negative(), base.surface_energy);
  if (t.has("dynamic_friction")) {
    p.dynamic_friction = t.number("dynamic_friction", Limits::non_negative());
    if (p.dynamic_friction > p.friction)
      t.fail("dynamic_friction", "the dynamic friction coefficient must not exceed `friction`");
  } else if (t.has("friction")) {
    p.dynamic_friction = -1.0;  // a pair that sets only `friction` slides with it too
  }
  return p;
}

std::uint16_t material_index(const CaseTable& t, std::string_view key, const Simulation& sim) {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < sim.materials.size(); ++k)
    names.push_back(sim.materials.material(static_cast<std::uint16_t>(k)).name);
  return static_cast<std::uint16_t>(sim.materials.find(t.choice(key, names)));
}

// [interaction] and its pairs, for the primary particles; coarse graining scales them
// (particles/coarse_graining.hpp) before the material table derives the pair constants.
void read_interactions(const CaseTable& root, Simulation& sim) {
  const CoarseGraining cg = coarse_graining_of(root);
  PairInput base;
  std::vector<CaseTable> pairs;
  if (auto it = root.optional_table("interaction")) {
    base = read_pair(*it, base);
    pairs = it->tables("pairs");
  }
  const auto n = static_cast<std::uint16_t>(sim.materials.size());
  for (std::uint16_t a = 0; a < n; ++a)
    for (std::uint16_t b = a; b < n; ++b) sim.materials.set_pair(a, b, cg.scaled(base));
  for (const auto& t : pairs) {
    std::vector<std::string> two = t.strings("materials");
    if (two.size() != 2) t.fail("materials", "expected two material names [\"a\", \"b\"]");
    int a = sim.materials.find(two[0]), b = sim.materials.find(two[1]);
    if (a < 0 || b < 0)
      t.fail("materials", fmt::format("unknown material \"{}\"", a < 0 ? two[0] : two[1]));
    sim.materials.set_pair(static_cast<std::uint16_t>(a), static_cast<std::uint16_t>(b),
                           cg.scaled(read_pair(t, base)));
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

}  // namespace

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

namespace {

// [insert.size]: the distribution by name; it reads its own keys.
std::shared_ptr<const SizeDistribution> read_size(const CaseTable& t) {
  return SizeDistributionRegistry::create(
      t.choice("distribution", SizeDistributionRegistry::names()), t);
}

// The smallest particle an insertion can create, and its material (for the time step); the
// largest and where the particles start (for the periodic bounds).
struct SmallestParticle {
  double radius;
  std::uint16_t material;
  double largest_radius = 0;
  Vec3 lo, hi;  // m, bounding box of the region or the read particles
};

SmallestParticle read_insertion(const CaseTable& root, const CaseTable& t, std::size_t index,
                                Simulation& sim) {
  const std::string type = t.choice("type", {"fill", "pour", "data_file", "clusters"});
  const std::uint16_t mat = material_index(t, "material", sim);
  if (type == "clusters") {
    const InsertedClusters c = insert_clusters(root, t, mat, index, sim);
    return {c.radius, mat, c.radius, c.lo, c.hi};
  }
  if (type == "data_file") {
    auto particles = read_lammps_data(t.input_file("file"), t.key_path("file"));
    double rmin = std::numeric_limits<double>::infinity();
    SmallestParticle out{0, mat, 0, {}, {}};
    const double inf = std::numeric_limits<double>::infinity();
    out.lo = Vec3{inf, inf, inf};
    out.hi = -out.lo;
    for (auto& p : particles) {
      p.material = mat;
      sim.particles.add(p);
      rmin = std::min(rmin, p.radius);
      out.largest_radius = std::max(out.largest_radius, p.radius);
      for (int a = 0; a < 3; ++a) {
        out.lo[a] = std::min(out.lo[a], p.x[a] - p.radius);
        out.hi[a] = std::max(out.hi[a], p.x[a] + p.radius);
      }
    }
    out.radius = rmin;
    return out;
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
  SmallestParticle out{0.5 * s.size->min_diameter(), mat, 0.5 * s.size->max_diameter(), {}, {}};
  s.region.bounds(out.lo, out.hi);
  sim.modules.push_back(std::make_unique<InsertionModule>(std::move(s), sim.seed));
  return out;
}

}  // namespace

namespace {

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
  if (s.has("prune_buffer"))
    sim.options.prune_buffer = s.number("prune_buffer", Limits::non_negative());

  read_materials(root, sim);
  read_interactions(root, sim);
  read_contact(root, sim);
  check_coarse_graining(root, sim);
  // the table each wall came from (a generated machine gives several walls from one table)
  std::vector<CaseTable> walls;
  const auto wall_tables = root.tables("walls");
  for (std::size_t k = 0; k < wall_tables.size(); ++k)
    for (auto& w : build_walls(wall_tables[k], k, sim)) {
      sim.walls.push_back(std::move(w));
      walls.push_back(wall_tables[k]);
    }

  const auto inserts = root.tables("insert");
  if (inserts.empty()) root.fail({}, "no particles: add at least one [[insert]] table");
  // the time step resolves the smallest particle of each insertion (wall materials do not count)
  out.time_step = std::make_unique<TimeStepPolicy>(s, out.end_time);
  ParticleReach reach;
  for (std::size_t k = 0; k < inserts.size(); ++k) {
    const SmallestParticle sp = read_insertion(root, inserts[k], k, sim);
    out.time_step->add({sp.radius, sp.material, fmt::format("insert[{}]", k), false});
    reach.largest_diameter = std::max(reach.largest_diameter, 2 * sp.largest_radius);
    for (int a = 0; a < 3; ++a) {
      reach.lo[a] = std::min(reach.lo[a], sp.lo[a]);
      reach.hi[a] = std::max(reach.hi[a], sp.hi[a]);
    }
  }
  check_wall_names(walls, sim);
  add_machines(root, walls, sim);
  add_collision_log(root, sim);
  add_statistics(root, sim);
  read_periodic(root, sim, reach);
  return out;
}

void decide_time_step(DemCase& c) {
  TimeStepPolicy::Decision d = c.time_step->decide(*c.sim);
  c.time_step_note = std::move(d.note);
  c.warnings.insert(c.warnings.end(), d.warnings.begin(), d.warnings.end());
}

DemCase load_plain_dem_case(const std::filesystem::path& path) {
  const CaseFile file = CaseFile::load(path);
  DemCase c = build_dem_case(file.root());
  decide_time_step(c);
  file.reject_unknown();
  return c;
}

}  // namespace comminute::io
