#pragma once
// An analytic wall (plane, box, cylinder) moving by a MotionModel of its [walls.motion] table —
// rotation, translation, oscillation, eccentric, table: the same models as a mesh wall
// (docs/case-file.md). Before each step it takes the model's velocities at the middle of the step
// (second order in a time-dependent motion, as MeshWall) and moves the inner wall rigidly by
// them; after it, the velocities at the end of the step are the wall's kinematics (so contacts
// see the wall's present velocity). The motion's own time is checkpointed with the wall.
#include <memory>

#include "comminute/geometry/motion_model.hpp"
#include "comminute/geometry/wall.hpp"

namespace comminute {

class PrescribedMotionWall : public Wall {
 public:
  // Takes over `inner` (its name, material and rotation centre move to this wall).
  PrescribedMotionWall(std::unique_ptr<Wall> inner, std::unique_ptr<MotionModel> motion);
  std::string type() const override { return inner_->type(); }
  int contacts(const Vec3& x, double r, double margin,
               std::vector<WallContact>& out) const override {
    return inner_->contacts(x, r, margin, out);
  }
  void advance(double dt) override;
  SurfaceMesh surface(double extent) const override { return inner_->surface(extent); }
  bool surface_moves() const override;
  double travel(double dt) const override;
  bool full_scan() const override;
  bool can_rotate() const override { return inner_->can_rotate(); }
  void save(Archive& a, const std::string& prefix) const override;
  void load(const Archive& a, const std::string& prefix) override;

  const Wall& inner() const { return *inner_; }
  double motion_time() const { return time_; }

 private:
  // The inner wall with this wall's kinematics (its queries read them).
  void sync() const { inner_->kinematics = kinematics; }
  std::unique_ptr<Wall> inner_;
  std::unique_ptr<MotionModel> motion_;
  double time_ = 0;  // s, the motion's time
};

}  // namespace comminute
