// The `hpgr` machine (WallGroupRegistry): two counter-rotating rolls, a feed chute and side
// plates generated from their dimensions (geometry/roll_pair.hpp); keys in docs/case-file.md
// (HPGR machines).
#include <numbers>

#include "comminute/geometry/ramped_rotation.hpp"
#include "comminute/geometry/roll_pair.hpp"
#include "comminute/geometry/wall_group.hpp"

namespace comminute {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

RollPairGeometry read_geometry(const CaseTable& t) {
  RollPairGeometry g;
  g.diameter = t.number("diameter", Limits::positive());
  g.width = t.number("width", Limits::positive());
  g.gap = t.number("gap", Limits::positive());
  g.segments = static_cast<int>(t.integer("segments", 12, 100000, 360));
  g.axial_divisions = static_cast<int>(t.integer("axial_divisions", 0, 100000, 0));
  g.chute = t.boolean("chute", true);
  if (g.chute) {
    g.chute_opening = t.number("chute_opening", Limits::positive());
    g.chute_height = t.number("chute_height", Limits::positive());
    g.chute_angle = t.number("chute_angle", Limits{0.0, 80.0, false, true}, 0.0) * kDegree;
    g.chute_clearance = t.number("chute_clearance", Limits::positive(), 0.1 * g.gap);
  }
  g.side_plates = t.boolean("side_plates", true);
  if (g.side_plates)
    g.side_plate_clearance = t.number("side_plate_clearance", Limits::positive(), 0.1 * g.gap);
  else
    g.overhang = t.number("overhang", Limits::positive(), g.diameter);
  return checked(t, g, &check_roll_pair);
}

const bool registered = WallGroupRegistry::add("hpgr", [](const CaseTable& t) {
  const RollPairGeometry g = read_geometry(t);
  const MachineKeys k = read_machine_keys(t);
  const double ramp = t.number("ramp_time", Limits::non_negative(), 0.0);
  auto group = std::make_unique<WallGroup>();
  // each roll turns about its own axis (y) towards the pinch: the roll at -x about +y (its
  // pinch side moving down, -z), the roll at +x about -y
  const double c = roll_offset(g);
  group->parts.push_back(make_part(t, "roll1", roll_mesh(g, 0), k.center,
                                   std::make_unique<RampedRotation>(Vec3{0, k.speed, 0}, ramp),
                                   {-c, 0, 0}, k.wear));
  // a floating roll 2 (`floating` table, read with its force control by the case builder,
  // io/case/floating_roll_case.cpp) translates as its control says
  group->parts.push_back(
      make_part(t, "roll2", roll_mesh(g, 1), k.center,
                std::make_unique<RampedRotation>(Vec3{0, -k.speed, 0}, ramp, t.has("floating")),
                {c, 0, 0}, k.wear));
  if (g.chute)
    group->parts.push_back(make_part(t, "chute", chute_mesh(g), k.center, nullptr, {}, k.wear));
  if (g.side_plates)
    group->parts.push_back(
        make_part(t, "side_plates", side_plates_mesh(g), k.center, nullptr, {}, k.wear));
  return group;
});

}  // namespace
}  // namespace comminute
