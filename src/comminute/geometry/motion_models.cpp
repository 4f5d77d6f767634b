// The motion models of MotionRegistry; keys in docs/case-file.md ([walls.motion]).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "comminute/geometry/motion_model.hpp"
#include "comminute/geometry/rigid_motion.hpp"
#include "comminute/geometry/wall_keys.hpp"

namespace comminute {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// Linear ramp factor min(1, t / ramp); 1 without a ramp.
double ramp(double t, double ramp_time) {
  return ramp_time > 0 ? std::min(1.0, t / ramp_time) : 1;
}

// An angular speed (rad/s) from exactly one of `angular_speed` (rad/s) and `speed_rpm` (1/min).
double read_angular_speed(const CaseTable& t) {
  const bool rad = t.has("angular_speed"), rpm = t.has("speed_rpm");
  if (rad == rpm)
    t.fail(rad ? "speed_rpm" : "angular_speed",
           "give one of angular_speed "
           "(rad/s) and speed_rpm");
  return rad ? t.number("angular_speed") : t.number("speed_rpm") * kTwoPi / 60.0;
}

class ConstantMotion : public MotionModel {
 public:
  explicit ConstantMotion(const CaseTable& t)
      : v_(t.vec3("velocity", Limits::any(), {})),
        w_(t.vec3("angular_velocity", Limits::any(), {})) {}
  void at(double, Vec3& v, Vec3& w) const override {
    v = v_;
    w = w_;
  }

 private:
  Vec3 v_, w_;
};

class RotationMotion : public MotionModel {
 public:
  explicit RotationMotion(const CaseTable& t)
      : axis_(read_unit_vector(t, "axis", {0, 0, 1})),
        speed_(read_angular_speed(t)),
        ramp_(t.number("ramp_time", Limits::non_negative(), 0.0)) {}
  void at(double t, Vec3& v, Vec3& w) const override {
    v = {};
    w = axis_ * (speed_ * ramp(t, ramp_));
  }

 private:
  Vec3 axis_;
  double speed_, ramp_;
};

class TranslationMotion : public MotionModel {
 public:
  explicit TranslationMotion(const CaseTable& t)
      : v_(t.vec3("velocity")), ramp_(t.number("ramp_time", Limits::non_negative(), 0.0)) {}
  void at(double t, Vec3& v, Vec3& w) const override {
    v = v_ * ramp(t, ramp_);
    w = {};
  }

 private:
  Vec3 v_;
  double ramp_;
};

// Displacement amplitude sin(2 pi f t + phase) along direction: velocity is its derivative.
class OscillationMotion : public MotionModel {
 public:
  explicit OscillationMotion(const CaseTable& t)
      : dir_(read_unit_vector(t, "direction", {0, 0, 1})),
        amplitude_(t.number("amplitude", Limits::non_negative())),
        omega_(kTwoPi * t.number("frequency", Limits::positive())),
        phase_(t.number("phase", Limits::any(), 0.0)) {}
  void at(double t, Vec3& v, Vec3& w) const override {
    v = dir_ * (amplitude_ * omega_ * std::cos(omega_ * t + phase_));
    w = {};
  }

 private:
  Vec3 dir_;
  double amplitude_, omega_, phase_;
};

// An eccentric shaft turning at Omega about `axis`: the wall's centre runs on a circle of radius
// e (displacement e (cos Omega t u + sin Omega t w), u, w perpendicular to the axis), and the wall
// swings about the axis through its centre by swing_amplitude sin(Omega t + swing_phase).
class EccentricMotion : public MotionModel {
 public:
  explicit EccentricMotion(const CaseTable& t)
      : axis_(read_unit_vector(t, "axis", {0, 0, 1})),
        e_(t.number("eccentricity", Limits::non_negative())),
        omega_(read_angular_speed(t)),
        swing_(t.number("swing_amplitude", Limits::non_negative(), 0.0)),
        phase_(t.number("swing_phase", Limits::any(), 0.0)) {
    u_ = perpendicular(axis_);
    w_ = cross(axis_, u_);
  }
  void at(double t, Vec3& v, Vec3& w) const override {
    const double a = omega_ * t;
    v = (std::cos(a) * w_ - std::sin(a) * u_) * (e_ * omega_);
    w = axis_ * (swing_ * omega_ * std::cos(a + phase_));
  }

 private:
  Vec3 axis_;
  double e_, omega_, swing_, phase_;
  Vec3 u_, w_;
};

// Velocities given at times t_0 < t_1 < ...: linear in between, held beyond the ends.
class TableMotion : public MotionModel {
 public:
  explicit TableMotion(const CaseTable& t) : time_(t.numbers("time", Limits::non_negative())) {
    if (time_.empty()) t.fail("time", "needs at least one time");
    for (std::size_t k = 1; k < time_.size(); ++k)
      if (!(time_[k] > time_[k - 1])) t.fail("time", "times must increase");
    v_ = read(t, "velocity");
    w_ = read(t, "angular_velocity");
  }
  void at(double t, Vec3& v, Vec3& w) const override {
    const auto hi = std::upper_bound(time_.begin(), time_.end(), t);
    if (hi == time_.begin() || hi == time_.end()) {
      const std::size_t k = hi == time_.begin() ? 0 : time_.size() - 1;
      v = v_[k];
      w = w_[k];
      return;
    }
    const auto k = static_cast<std::size_t>(hi - time_.begin());
    const double s = (t - time_[k - 1]) / (time_[k] - time_[k - 1]);
    v = v_[k - 1] + (v_[k] - v_[k - 1]) * s;
    w = w_[k - 1] + (w_[k] - w_[k - 1]) * s;
  }

 private:
  std::vector<Vec3> read(const CaseTable& t, const char* key) const {
    std::vector<Vec3> out(time_.size());
    if (!t.has(key)) return out;
    const auto flat = t.numbers(key);
    if (flat.size() != 3 * time_.size())
      t.fail(key, fmt::format("needs 3 numbers (x, y, z) per time: {} for {} times, got {}",
                              3 * time_.size(), time_.size(), flat.size()));
    for (std::size_t k = 0; k < out.size(); ++k)
      out[k] = {flat[3 * k], flat[3 * k + 1], flat[3 * k + 2]};
    return out;
  }
  std::vector<double> time_;
  std::vector<Vec3> v_, w_;
};

template <class M>
MotionRegistry::Factory factory() {
  return [](const CaseTable& t) -> std::unique_ptr<MotionModel> { return std::make_unique<M>(t); };
}

const bool registered = MotionRegistry::add("constant", factory<ConstantMotion>()) &&
                        MotionRegistry::add("rotation", factory<RotationMotion>()) &&
                        MotionRegistry::add("translation", factory<TranslationMotion>()) &&
                        MotionRegistry::add("oscillation", factory<OscillationMotion>()) &&
                        MotionRegistry::add("eccentric", factory<EccentricMotion>()) &&
                        MotionRegistry::add("table", factory<TableMotion>());

}  // namespace

std::unique_ptr<MotionModel> make_motion(const CaseTable& t) {
  return MotionRegistry::create(t.choice("type", MotionRegistry::names()), t);
}

}  // namespace comminute
