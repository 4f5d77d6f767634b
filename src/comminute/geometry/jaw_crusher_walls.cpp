// The `jaw_crusher` machine (WallGroupRegistry): a fixed jaw, a swinging jaw driven by an
// eccentric (about a fixed top pivot, or hung on the eccentric and held by a single toggle) and
// cheek plates generated from their dimensions (geometry/jaw_crusher.hpp); keys in
// docs/case-file.md (Jaw crusher machines).
#include <cmath>
#include <numbers>

#include "comminute/geometry/jaw_crusher.hpp"
#include "comminute/geometry/single_toggle.hpp"
#include "comminute/geometry/wall_group.hpp"

namespace comminute {

namespace {

// The swing about the pivot, alpha(t) = alpha_open (1 - cos(Omega t)) / 2 about +y: its angular
// velocity alpha'(t) = alpha_open Omega sin(Omega t) / 2 (docs/models.md eq. J1, a simplification
// of the eccentric and toggle linkage, ours).
class JawSwing : public MotionModel {
 public:
  JawSwing(double alpha_open, double omega) : alpha_(alpha_open), omega_(omega) {}
  void at(double t, Vec3& v, Vec3& w) const override {
    v = {};
    w = {0, 0.5 * alpha_ * omega_ * std::sin(omega_ * t), 0};
  }

 private:
  double alpha_, omega_;
};

// The single-toggle drive (geometry/single_toggle.hpp, docs/models.md J3-J5): the rotation
// centre is the pin A on the eccentric, turning counter-clockwise (about -y) at Omega from the
// closed side; the jaw's pose is the linkage's, in closed form.
class SingleToggleSwing : public MotionModel {
 public:
  SingleToggleSwing(const SingleToggleLinkage& k, double omega) : k_(k), omega_(omega) {}
  void at(double t, Vec3& v, Vec3& w) const override {
    const double theta = k_.start_angle + omega_ * t;
    v = (omega_ * k_.eccentricity) * Vec3{-std::sin(theta), 0, std::cos(theta)};
    w = {0, -k_.jaw_angular_speed(theta, omega_), 0};
  }
  bool pose(double t, Vec3& d, Vec3& rotation) const override {
    const double theta = k_.start_angle + omega_ * t;
    d = k_.pin(theta) - k_.hang_start;
    rotation = {0, -(k_.jaw_angle(theta) - k_.jaw_angle(k_.start_angle)), 0};
    return true;
  }

 private:
  SingleToggleLinkage k_;
  double omega_;
};

JawCrusherGeometry read_geometry(const CaseTable& t) {
  JawCrusherGeometry g;
  g.height = t.number("height", Limits::positive());
  g.width = t.number("width", Limits::positive());
  g.gape = t.number("gape", Limits::positive());
  g.closed_side_setting = t.number("closed_side_setting", Limits::positive());
  g.jaw_throw = t.number("throw", Limits::positive());
  g.divisions = static_cast<int>(t.integer("divisions", 1, 100000, 16));
  g.side_plates = t.boolean("side_plates", true);
  if (!g.side_plates) g.overhang = t.number("overhang", Limits::positive(), g.height);
  return checked(t, g, &check_jaw_crusher);
}

const bool registered = WallGroupRegistry::add("jaw_crusher", [](const CaseTable& t) {
  const JawCrusherGeometry g = read_geometry(t);
  const MachineKeys k = read_machine_keys(t);
  auto group = std::make_unique<WallGroup>();
  group->parts.push_back(
      make_part(t, "fixed_jaw", fixed_jaw_mesh(g), k.center, nullptr, {}, k.wear));
  std::unique_ptr<MotionModel> swing;
  if (t.choice("drive", {"pivot", "single_toggle"}, "pivot") == "pivot") {
    swing = std::make_unique<JawSwing>(jaw_opening_angle(g), k.speed);
  } else {
    const double toggle = t.number("toggle_length", Limits::positive());
    const double angle = t.number("toggle_angle", Limits::any()) * std::numbers::pi / 180;
    SingleToggleLinkage linkage;
    try {
      linkage = single_toggle_linkage(g.height, g.gape, g.closed_side_setting, g.jaw_throw, toggle,
                                      angle);
    } catch (const GeometryError& e) {
      t.fail(e.key(), e.what());
    }
    swing = std::make_unique<SingleToggleSwing>(linkage, k.speed);
  }
  group->parts.push_back(make_part(t, "swing_jaw", swing_jaw_mesh(g), k.center, std::move(swing),
                                   jaw_pivot(g), k.wear));
  if (g.side_plates)
    group->parts.push_back(
        make_part(t, "side_plates", cheek_plates_mesh(g), k.center, nullptr, {}, k.wear));
  return group;
});

}  // namespace
}  // namespace comminute
