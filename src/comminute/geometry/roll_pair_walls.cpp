// The `hpgr` machine (WallGroupRegistry): two counter-rotating rolls, a feed chute and side
// plates generated from their dimensions (geometry/roll_pair.hpp); keys in docs/case-file.md
// (HPGR machines).
#include <numbers>

#include "comminute/geometry/roll_pair.hpp"
#include "comminute/geometry/wall_group.hpp"

namespace comminute {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

// A roll turning about its own axis (y) towards the pinch, the speed reached linearly over the
// ramp: sign +1 for the roll at -x (its pinch side moves down, -z), -1 for the roll at +x.
class RollDrive : public MotionModel {
 public:
  RollDrive(double sign, double speed, double ramp_time)
      : sign_(sign), speed_(speed), ramp_(ramp_time) {}
  void at(double t, Vec3& v, Vec3& w) const override {
    v = {};
    w = {0, sign_ * speed_ * (ramp_ > 0 ? std::min(1.0, t / ramp_) : 1.0), 0};
  }

 private:
  double sign_, speed_, ramp_;
};

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
  try {
    check_roll_pair(g);
  } catch (const GeometryError& e) {
    t.fail(e.key(), e.what());
  }
  return g;
}

const bool registered = WallGroupRegistry::add("hpgr", [](const CaseTable& t) {
  const RollPairGeometry g = read_geometry(t);
  const Vec3 center = t.vec3("center", Limits::any(), {});
  const double speed = t.number("speed_rpm", Limits::positive()) * 2 * std::numbers::pi / 60;
  const double ramp = t.number("ramp_time", Limits::non_negative(), 0.0);
  const ArchardWear wear = read_part_wear(t);
  auto group = std::make_unique<WallGroup>();
  const double c = roll_offset(g);
  group->parts.push_back(make_part(t, "roll1", roll_mesh(g, 0), center,
                                   std::make_unique<RollDrive>(1.0, speed, ramp), {-c, 0, 0},
                                   wear));
  group->parts.push_back(make_part(t, "roll2", roll_mesh(g, 1), center,
                                   std::make_unique<RollDrive>(-1.0, speed, ramp), {c, 0, 0},
                                   wear));
  if (g.chute)
    group->parts.push_back(make_part(t, "chute", chute_mesh(g), center, nullptr, {}, wear));
  if (g.side_plates)
    group->parts.push_back(
        make_part(t, "side_plates", side_plates_mesh(g), center, nullptr, {}, wear));
  return group;
});

}  // namespace
}  // namespace comminute
