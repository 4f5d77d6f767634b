#pragma once
// Walls driven by force instead of a prescribed velocity. Each controlled wall translates along
// one unit direction n (for a plane: its normal, from the wall into the particles); the module
// sets its velocity v n after the forces of every step, and the wall moves with it in the next.
//   servo:       v = clamp(G (F_target − F), −v_max, v_max), F = −F_wall·n the compressive force
//                (F_target is the pre-load force until the pre-load time, if one is given: a
//                light pre-load held before the ramp, as in a confined-compression test)
//                of the particles on the wall (a stress target σ gives F_target = σ A and is
//                reported as F / A). The servo control of PFC and of Thornton's
//                compression tests (Thornton, Géotechnique 2000, 50(1), servo on the boundary
//                velocity): proportional, with a speed limit.
//   dead_weight: a free body of mass m on the line n under gravity and the particles' force,
//                m dv/dt = m g·n + F_wall·n, integrated like the particles (velocity Verlet:
//                the wall's velocity over a step is the mid-step velocity), from rest.
//   floating:    a free body pushed along n by a constant force (a hydraulic roll of a roll
//                press): m dv/dt = m g·n + F_push + F_wall·n − c v, integrated as the dead
//                weight, its travel along n limited to max_travel (an inelastic stop: the wall
//                halts there, the zero-gap stop of a press).
// State: the wall's velocity (in the wall's checkpointed kinematics) and the displacement
// along n (walls_control/...). Table (docs/outputs.md): wall_control.csv.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "comminute/core/vec3.hpp"
#include "comminute/engine/module.hpp"
#include "comminute/engine/sample_rows.hpp"
#include "comminute/engine/series_source.hpp"

namespace comminute {

struct WallControlSpec {
  enum class Mode { servo, dead_weight, floating } mode = Mode::servo;
  std::size_t wall = 0;      // index in Simulation::walls
  std::string name;          // the wall's name, for the output columns
  Vec3 direction;            // unit, the line of motion (into the particles for a servo)
  double area = 0;           // m², > 0: stress = force / area is reported (servo target in stress)
  double target_force = 0;   // N (servo)
  double preload_force = 0;  // N (servo): the target while time < preload_time (the hold)
  double preload_time = 0;   // s (servo): end of the pre-load hold; 0 = none
  double gain = 0;           // m/(N s) (servo)
  double max_speed = 0;      // m/s (servo)
  double mass = 0;           // kg (dead weight, floating)
  double push = 0;           // N, constant force along the direction (floating)
  double damping = 0;        // N s/m, viscous resistance to the motion (floating)
  // m, largest travel along the direction (floating: the stop); infinite without a stop
  double max_travel = std::numeric_limits<double>::infinity();
  // m, reported as <name>_gap = gap − displacement when finite (a floating roll's gap)
  double gap = std::numeric_limits<double>::quiet_NaN();
  bool free_body() const { return mode != Mode::servo; }
};

class WallControlModule final : public Module, public SeriesSource {
 public:
  explicit WallControlModule(std::vector<WallControlSpec> walls);
  std::string name() const override { return "wall_control"; }
  void setup(Simulation& sim) override;
  void post_force(Simulation& sim) override;
  void save(Archive& a) const override;
  void load(const Archive& a) override;
  SeriesSource* series_source() override { return this; }
  void sample(const Simulation& sim) override;
  std::vector<Table> tables(const Simulation& sim) const override;

  const std::vector<WallControlSpec>& specs() const { return specs_; }
  // Compressive force of the particles on controlled wall k along its direction (N), as of the
  // last force computation.
  double force(const Simulation& sim, std::size_t k) const;
  double displacement(std::size_t k) const { return displacement_[k]; }  // m, along the direction

 private:
  static double stopped(const WallControlSpec& s, double d, double v, double dt);

  std::vector<WallControlSpec> specs_;
  std::vector<double> displacement_;  // m, travelled along the direction since the start
  SampleRows samples_;                // per sample: time, then 4 numbers per wall
};

}  // namespace comminute
