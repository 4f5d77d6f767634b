#include "comminute/io/case/cluster_case.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "comminute/bonds/cluster_packing.hpp"
#include "comminute/bonds/grain_placement.hpp"
#include "comminute/bonds/grain_pour.hpp"
#include "comminute/core/error.hpp"
#include "comminute/geometry/stl_file.hpp"

namespace comminute::io {

namespace {

std::unique_ptr<bonds::ClusterShape> read_shape(const CaseTable& t) {
  const Limits positive = Limits::positive();
  const std::string shape = t.choice("shape", {"sphere", "ellipsoid", "stl"});
  if (shape == "sphere") return bonds::make_sphere_shape(t.number("diameter", positive));
  if (shape == "ellipsoid")
    return bonds::make_ellipsoid_shape(t.number("length", positive), t.number("width", positive),
                                       t.number("thickness", positive));
  const double scale = t.number("scale", positive, 1.0);
  IndexedMesh mesh;
  try {
    mesh = read_stl(t.input_file("file"));
    for (Vec3& v : mesh.vertices) v *= scale;
    return bonds::make_mesh_shape(mesh);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    t.fail("file", e.what());
  }
}

}  // namespace

namespace {

// The grain templates of an [[insert]] of type "clusters": packed with sub-spheres, bonded within
// [bonds] gap_tolerance, each checked to be one piece.
std::vector<bonds::GrainTemplate> read_templates(const CaseTable& root, const CaseTable& t,
                                                 Rng& rng) {
  const auto bonds_table = root.optional_table("bonds");
  if (!bonds_table || !bonds_table->boolean("within_grain", false))
    t.fail("type",
           "clusters need a [bonds] table with within_grain = true (else the grains would be "
           "bonded to each other where they touch)");
  const double gap = bonds_table->number("gap_tolerance", Limits::non_negative(), 0.0);
  const auto shape = read_shape(t);
  const int n = static_cast<int>(t.integer("spheres_per_grain", 1, 100000));
  const double fraction = t.number("solid_fraction", Limits{0.0, 0.74, true, false}, 0.6);
  const int templates = static_cast<int>(t.integer("templates", 1, 1000, 1));
  std::vector<bonds::GrainTemplate> tpl;
  for (int k = 0; k < templates; ++k) {
    try {
      tpl.push_back(bonds::pack_cluster(*shape, n, fraction, rng));
    } catch (const Error& e) {
      t.fail("spheres_per_grain", e.what());
    }
    tpl.back().bonds = bonds::pairs_within_gap(tpl.back().centres, tpl.back().radius, gap);
    const std::size_t pieces = bonds::count_components(tpl.back().centres.size(), tpl.back().bonds);
    if (pieces != 1)
      t.fail("spheres_per_grain",
             fmt::format("template {} falls into {} pieces with [bonds] gap_tolerance = {} m "
                         "(sub-sphere radius {:.4g} m): raise gap_tolerance (and [simulation] "
                         "skin) or the solid_fraction",
                         k, pieces, gap, tpl.back().radius));
  }
  return tpl;
}

// mode = "pour": the pour module (bonds/grain_pour.hpp), added to sim.modules.
void add_grain_pour(const CaseTable& t, std::vector<bonds::GrainTemplate> templates,
                    std::uint16_t material, std::size_t index, Simulation& sim) {
  const Limits positive = Limits::positive();
  bonds::GrainPourSpec s;
  s.label = fmt::format("insert[{}]", index);
  s.stream = index;
  s.templates = std::move(templates);
  s.material = material;
  s.density = sim.materials.material(material).density;
  s.region = read_region(t.table("region"));
  s.rate = t.number("rate", positive);
  const bool has_count = t.has("count"), has_mass = t.has("mass");
  if (has_count == has_mass)
    t.fail({}, "a pour of grains needs exactly one target: 'count' (grains) or 'mass' (kg)");
  if (has_count) s.count = static_cast<std::uint64_t>(t.integer("count", 1, 100'000'000));
  if (has_mass) s.mass = t.number("mass", positive);
  s.start = t.number("start", Limits::non_negative(), 0.0);
  s.end = t.number("end", positive, std::numeric_limits<double>::infinity());
  if (!(s.end > s.start)) t.fail("end", fmt::format("must exceed start = {} s", s.start));
  s.interval = t.number("interval", positive, 1e-3);
  s.layers = static_cast<int>(t.integer("layers", 1, 1000, 1));
  if (s.layers > 1 && !std::isfinite(s.end))
    t.fail("layers", "poured layers are time windows of [start, end]: give 'end'");
  s.attempts = static_cast<int>(t.integer("attempts", 1, 10'000'000, 50));
  s.velocity = t.vec3("velocity", Limits::any(), {});
  s.velocity_spread = t.number("velocity_spread", Limits::non_negative(), 0.0);
  ParticleStore& p = sim.particles;
  p.add_field("grain", -1);
  p.add_field("layer", 0);
  p.add_field("batch", 0);
  sim.modules.push_back(std::make_unique<bonds::GrainPourModule>(std::move(s), sim.seed));
}

}  // namespace

InsertedClusters insert_clusters(const CaseTable& root, const CaseTable& t, std::uint16_t material,
                                 std::size_t index, Simulation& sim) {
  Rng rng(sim.seed, rng_stream::clusters + 16 * index);
  std::vector<bonds::GrainTemplate> tpl = read_templates(root, t, rng);
  InsertedClusters out;
  out.radius = tpl.front().radius;
  for (const auto& g : tpl) out.radius = std::min(out.radius, g.radius);
  const std::string mode = t.choice("mode", {"fill", "pour"}, "fill");
  if (mode == "pour") {
    add_grain_pour(t, std::move(tpl), material, index, sim);
    read_region(t.table("region")).bounds(out.lo, out.hi);
    return out;
  }
  bonds::PlacementRequest req;
  req.grains = static_cast<std::uint64_t>(t.integer("count", 1, 100'000'000));
  req.layers = static_cast<int>(t.integer("layers", 1, 1000, 1));
  req.attempts = static_cast<int>(t.integer("attempts", 1, 10'000'000, 2000));
  req.region = read_region(t.table("region"));
  std::vector<const Wall*> walls;
  for (const auto& w : sim.walls) walls.push_back(w.get());
  ParticleStore& p = sim.particles;
  std::vector<bonds::PlacedSphere> placed;
  try {
    placed = bonds::place_grains(tpl, req, walls, p.x, p.radius, rng);
  } catch (const Error& e) {
    t.fail("count", e.what());
  }
  const std::size_t gf = p.add_field("grain", -1), lf = p.add_field("layer", 0);
  double grain0 = 0;  // grain ids continue those of an earlier clusters insertion
  for (double g : p.field(gf)) grain0 = std::max(grain0, g + 1);
  const double rho = sim.materials.material(material).density;
  for (const bonds::PlacedSphere& s : placed) {
    const bonds::GrainTemplate& g = tpl[s.templ];
    // the sub-spheres carry the grain's mass: density scaled by shape volume / sphere volume
    const double v = 4.0 / 3.0 * std::numbers::pi * g.radius * g.radius * g.radius;
    ParticleInit init;
    init.x = s.x;
    init.radius = s.radius;
    init.density = rho * g.volume / (static_cast<double>(g.centres.size()) * v);
    init.material = material;
    p.add(init);
    p.field(gf).back() = grain0 + s.grain;
    p.field(lf).back() = s.layer;
  }
  req.region.bounds(out.lo, out.hi);
  return out;
}

bonds::GrainBreakageModule* add_grain_breakage(const CaseTable& root, DemCase& dem,
                                               const bonds::BondsModule* bonds) {
  const auto t = root.optional_table("grain_breakage");
  if (!t) return nullptr;
  if (!bonds) t->fail("", "needs a [bonds] table (grains are bonded clusters)");
  if (!dem.sim->particles.has_field("grain"))
    t->fail("", "needs an [[insert]] of type \"clusters\" (no particle belongs to a grain)");
  bonds::GrainBreakageOptions opt;
  opt.broken_below = t->number("broken_below", Limits{0.0, 1.0, true, false}, 0.9);
  const bool has_piston = t->has("piston");
  if (has_piston) {
    opt.piston = t->string("piston");
    opt.floor = t->string("floor");
    opt.area = t->number("area", Limits::positive());
    for (const std::string* name : {&opt.piston, &opt.floor}) {
      bool found = false;
      for (const auto& w : dem.sim->walls)
        if (w->name == *name) {
          found = true;
          if (w->type() != "plane")
            t->fail(name == &opt.piston ? "piston" : "floor",
                    fmt::format("wall '{}' is a {}, not a plane", *name, w->type()));
        }
      if (!found)
        t->fail(name == &opt.piston ? "piston" : "floor",
                fmt::format("no wall is named '{}'", *name));
    }
  }
  auto m = std::make_unique<bonds::GrainBreakageModule>(*bonds, opt);
  bonds::GrainBreakageModule* out = m.get();
  dem.sim->modules.push_back(std::move(m));
  return out;
}

}  // namespace comminute::io
