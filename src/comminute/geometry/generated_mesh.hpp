#pragma once
// Helpers shared by the wall types that generate their mesh from dimensions (ball mill, mixer):
// a steady turn about a fixed axis reached over a linear ramp, and the optional `stl_file` key.
#include "comminute/core/case_table.hpp"
#include "comminute/geometry/motion_model.hpp"
#include "comminute/geometry/stl_file.hpp"

namespace comminute {

// Angular velocity omega (rad/s) about the unit vector `axis`, rising linearly from 0 over
// `ramp` (s; 0: from the start); no translation.
class RampedTurn : public MotionModel {
 public:
  RampedTurn(const Vec3& axis, double omega, double ramp)
      : axis_(axis), omega_(omega), ramp_(ramp) {}
  void at(double t, Vec3& v, Vec3& w) const override;

 private:
  Vec3 axis_;
  double omega_, ramp_;
};

// When table t has `stl_file`: writes m there as a binary STL (folders created; a failure is the
// key's InputError).
void write_stl_if_asked(const CaseTable& t, const IndexedMesh& m);

}  // namespace comminute
