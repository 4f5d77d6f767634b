#include "comminute/io/case/machine_case.hpp"

#include <fmt/format.h>

#include "comminute/engine/outlet.hpp"
#include "comminute/engine/sampling_plane.hpp"
#include "comminute/engine/stop_condition.hpp"
#include "comminute/engine/wall_control.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "comminute/io/case/floating_roll_case.hpp"

namespace comminute::io {

namespace {

const Limits kPositive = Limits::positive();

Vec3 unit_vector(const CaseTable& t, const char* key) {
  const Vec3 v = t.vec3(key);
  if (!(norm(v) > 0)) t.fail(key, "the direction must not be zero");
  return v / norm(v);
}

// A name that becomes part of a CSV column or a field name: refused here (check), not when the
// outputs are opened (run). Names of one kind must differ.
std::string column_name(const CaseTable& t, const std::string& fallback,
                        const std::vector<std::string>& taken) {
  const std::string n = t.string("name", fallback);
  if (n.empty() || n.find_first_of(",\"\r\n[] ") != std::string::npos)
    t.fail("name", fmt::format("name '{}' cannot name a CSV column (empty, or holds a space, "
                               "comma, quote, bracket or line break)",
                               n));
  for (const auto& other : taken)
    if (other == n)
      t.fail("name", fmt::format("the name '{}' is used twice; names must differ", n));
  return n;
}

void add_outlets(const CaseTable& root, Simulation& sim) {
  const auto tables = root.tables("outlets");
  if (tables.empty()) return;
  std::vector<OutletSpec> specs;
  std::vector<std::string> names;
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const CaseTable& t = tables[k];
    OutletSpec o;
    o.name = column_name(t, fmt::format("outlet{}", k), names);
    names.push_back(o.name);
    const bool has_region = t.has("region"), has_plane = t.has("plane");
    if (has_region == has_plane) t.fail({}, "give exactly one of 'region' or 'plane'");
    if (has_region) {
      o.region = read_region(t.table("region"));
    } else {
      const CaseTable p = t.table("plane");
      o.half_space = true;
      o.point = p.vec3("point");
      o.normal = unit_vector(p, "normal");
    }
    specs.push_back(o);
  }
  sim.modules.push_back(std::make_unique<OutletModule>(std::move(specs)));
}

// The bound of a sampling plane: `radius` (a disc about `point`) or `size` = [a, b] with `u`, the
// direction of side a (projected onto the plane), or neither (the infinite plane).
void read_sampling_extent(const CaseTable& t, SamplingPlaneSpec& s) {
  const bool disc = t.has("radius"), rectangle = t.has("size");
  if (disc && rectangle) t.fail("size", "give one of 'radius' (a disc) or 'size' (a rectangle)");
  if (disc) {
    s.extent = SamplingPlaneSpec::Extent::disc;
    s.radius = t.number("radius", kPositive);
  } else if (rectangle) {
    s.extent = SamplingPlaneSpec::Extent::rectangle;
    const auto size = t.numbers("size", kPositive);
    if (size.size() != 2) t.fail("size", "needs two side lengths [a, b] (m)");
    s.half_u = 0.5 * size[0];
    s.half_v = 0.5 * size[1];
    if (!t.has("u")) t.fail("size", "a rectangle needs 'u' ([x, y, z]), the direction of side a");
    const Vec3 u = t.vec3("u");
    const Vec3 in_plane = u - dot(u, s.normal) * s.normal;
    if (!(norm(in_plane) > 1e-9 * norm(u)))
      t.fail("u", "the rectangle's side direction must not be along the plane's normal");
    s.u = in_plane / norm(in_plane);
  } else if (t.has("u")) {
    t.fail("u", "'u' orients a rectangle: give 'size' too");
  }
}

void add_sampling_planes(const CaseTable& root, Simulation& sim) {
  const auto tables = root.tables("sampling_planes");
  if (tables.empty()) return;
  std::vector<SamplingPlaneSpec> specs;
  std::vector<std::string> names;
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const CaseTable& t = tables[k];
    SamplingPlaneSpec s;
    s.name = column_name(t, fmt::format("plane{}", k), names);
    names.push_back(s.name);
    s.point = t.vec3("point");
    s.normal = unit_vector(t, "normal");
    read_sampling_extent(t, s);
    s.log = t.boolean("log", false);
    specs.push_back(s);
  }
  auto m = std::make_unique<SamplingPlaneModule>(std::move(specs));
  m->register_fields(sim.particles);  // before a checkpoint is read: it holds the fields
  sim.modules.push_back(std::move(m));
}

// The direction of a controlled wall: given, or a plane's normal (into the particles).
Vec3 control_direction(const CaseTable& c, const Wall& w) {
  if (c.has("direction")) return unit_vector(c, "direction");
  if (const auto* p = dynamic_cast<const PlaneWall*>(&w)) return p->normal();
  c.fail("direction", fmt::format("a {} wall needs a 'direction' of motion ([x, y, z])", w.type()));
}

void add_wall_controls(const std::vector<CaseTable>& walls, Simulation& sim) {
  std::vector<WallControlSpec> specs;
  for (std::size_t k = 0; k < walls.size() && k < sim.walls.size(); ++k) {
    if (auto f = floating_roll_control(walls[k], k, *sim.walls[k])) {
      specs.push_back(*f);
      continue;
    }
    const auto c = walls[k].optional_table("control");
    if (!c) continue;
    for (const char* key : {"velocity", "angular_velocity", "motion"})
      if (walls[k].has(key))
        walls[k].fail(key,
                      "a wall with a 'control' table moves as its control says: remove "
                      "the prescribed motion");
    WallControlSpec s;
    s.wall = k;
    s.name = sim.walls[k]->name;
    s.mode = c->choice("mode", {"servo", "dead_weight"}) == "servo"
                 ? WallControlSpec::Mode::servo
                 : WallControlSpec::Mode::dead_weight;
    s.direction = control_direction(*c, *sim.walls[k]);
    if (s.mode == WallControlSpec::Mode::servo) {
      const bool has_force = c->has("target_force"), has_stress = c->has("target_stress");
      if (has_force == has_stress)
        c->fail({}, "a servo needs exactly one of 'target_force' (N) or 'target_stress' (Pa)");
      if (has_stress) {
        s.area = c->number("area", kPositive);
        s.target_force = c->number("target_stress", Limits::non_negative()) * s.area;
      } else {
        s.area = c->number("area", kPositive, 0.0);
        s.target_force = c->number("target_force", Limits::non_negative());
      }
      s.gain = c->number("gain", kPositive);
      s.max_speed = c->number("max_speed", kPositive);
      // a light pre-load held before the ramp: the target is the pre-load until preload_time
      const bool pre_force = c->has("preload_force"), pre_stress = c->has("preload_stress");
      if (pre_force && pre_stress)
        c->fail("preload_stress", "give one of 'preload_force' (N) or 'preload_stress' (Pa)");
      if (pre_stress && !(s.area > 0))
        c->fail("preload_stress", "needs 'area' (m²) to turn the stress into a force");
      if (pre_force || pre_stress) {
        s.preload_force = pre_stress ? c->number("preload_stress", Limits::non_negative()) * s.area
                                     : c->number("preload_force", Limits::non_negative());
        s.preload_time = c->number("preload_time", kPositive);
      } else if (c->has("preload_time")) {
        c->fail("preload_time", "give 'preload_force' (N) or 'preload_stress' (Pa) to hold");
      }
    } else {
      s.mass = c->number("mass", kPositive);
      s.area = c->has("area") ? c->number("area", kPositive) : 0.0;
    }
    specs.push_back(s);
  }
  if (!specs.empty()) sim.modules.push_back(std::make_unique<WallControlModule>(std::move(specs)));
}

void add_stop_conditions(const CaseTable& root, Simulation& sim) {
  const auto tables = root.tables("stop");
  if (tables.empty()) return;
  std::vector<std::string> wall_names;
  for (const auto& w : sim.walls) wall_names.push_back(w->name);
  std::vector<StopConditionSpec> specs;
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const CaseTable& t = tables[k];
    StopConditionSpec s;
    s.label = fmt::format("stop[{}]", k);
    if (wall_names.empty()) t.fail("wall", "the case has no walls to watch");
    const std::string wall = t.choice("wall", wall_names);
    for (std::size_t w = 0; w < wall_names.size(); ++w)
      if (wall_names[w] == wall) s.wall = w;
    const bool has_force = t.has("force"), has_stress = t.has("stress");
    if (has_force == has_stress) t.fail({}, "give exactly one of 'force' (N) or 'stress' (Pa)");
    if (has_stress) {
      s.area = t.number("area", kPositive);
      s.value = t.number("stress", Limits::non_negative());
    } else {
      s.value = t.number("force", Limits::non_negative());
    }
    if (t.has("direction")) s.direction = unit_vector(t, "direction");
    s.above = t.choice("when", {"above", "below"}, "above") == "above";
    s.after = t.number("after", Limits::non_negative(), 0.0);
    specs.push_back(s);
  }
  sim.modules.push_back(std::make_unique<StopConditionModule>(std::move(specs)));
}

}  // namespace

void add_machines(const CaseTable& root, const std::vector<CaseTable>& walls, Simulation& sim) {
  add_wall_controls(walls, sim);
  add_outlets(root, sim);
  add_sampling_planes(root, sim);
  add_stop_conditions(root, sim);
}

}  // namespace comminute::io
