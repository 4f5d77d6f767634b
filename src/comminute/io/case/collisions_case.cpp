#include "comminute/io/case/collisions_case.hpp"

#include <fmt/format.h>

#include <cmath>

#include "comminute/analysis/collision_log.hpp"

namespace comminute::io {

namespace {
// A material or wall name becomes part of a file name and a CSV cell.
void check_type_name(const CaseTable& t, const std::string& kind, const std::string& n) {
  if (n.empty() || n.find_first_of(",\"\r\n/\\ ") != std::string::npos)
    t.fail({}, fmt::format("{} name '{}' cannot name a collision spectrum file (empty, or holds a "
                           "space, comma, quote, slash or line break)",
                           kind, n));
}
}  // namespace

void add_collision_log(const CaseTable& root, Simulation& sim) {
  const auto t = root.optional_table("collisions");
  if (!t) return;
  analysis::CollisionLogSettings s;
  if (const auto steady = t->optional_table("steady_state")) {
    if (t->has("start")) t->fail("start", "give either 'start' or [collisions.steady_state]");
    s.detect = true;
    s.rule.block = steady->number("block", Limits::positive());
    s.rule.blocks = static_cast<int>(steady->integer("blocks", 2, 1000, 4));
    s.rule.tolerance = steady->number("tolerance", Limits::positive(), 0.05);
  } else {
    s.start = t->number("start", Limits::non_negative(), 0.0);
  }
  if (t->has("end")) {
    s.end = t->number("end", Limits::positive());
    if (!(s.end > s.start)) t->fail("end", "the window must end after its start");
  }
  s.energy_min = t->number("energy_min", Limits::positive(), 1e-9);
  s.energy_max = t->number("energy_max", Limits::positive(), 1e3);
  if (!(s.energy_max > s.energy_min)) t->fail("energy_max", "must be larger than energy_min");
  s.bins = static_cast<int>(t->integer("bins", 1, 10000, 120));
  s.interval = t->number("interval", Limits::non_negative(), 0.0);
  const std::string e =
      t->choice("energy", {"impact_reduced_mass", "impact_average_mass", "dissipated"},
                "impact_reduced_mass");
  s.spectrum = e == "impact_reduced_mass"   ? analysis::SpectrumEnergy::impact_reduced_mass
               : e == "impact_average_mass" ? analysis::SpectrumEnergy::impact_average_mass
                                            : analysis::SpectrumEnergy::dissipated;
  for (std::size_t m = 0; m < sim.materials.size(); ++m) {
    s.materials.push_back(sim.materials.material(static_cast<std::uint16_t>(m)).name);
    check_type_name(*t, "material", s.materials.back());
  }
  for (const auto& w : sim.walls) {
    s.walls.push_back(w->name);
    check_type_name(*t, "wall", s.walls.back());
  }
  sim.modules.push_back(std::make_unique<analysis::CollisionLogModule>(std::move(s)));
}

}  // namespace comminute::io
