#include "comminute/io/case/cluster_case.hpp"

#include <fmt/format.h>

#include <numbers>

#include "comminute/bonds/cluster_packing.hpp"
#include "comminute/bonds/grain_placement.hpp"
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

InsertedClusters insert_clusters(const CaseTable& root, const CaseTable& t, std::uint16_t material,
                                 std::size_t index, Simulation& sim) {
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
  bonds::PlacementRequest req;
  req.grains = static_cast<std::uint64_t>(t.integer("count", 1, 100'000'000));
  req.layers = static_cast<int>(t.integer("layers", 1, 1000, 1));
  req.attempts = static_cast<int>(t.integer("attempts", 1, 10'000'000, 2000));
  req.region = read_region(t.table("region"));
  Rng rng(sim.seed, rng_stream::clusters + 16 * index);
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
  InsertedClusters out;
  out.radius = tpl.front().radius;
  for (const auto& g : tpl) out.radius = std::min(out.radius, g.radius);
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
