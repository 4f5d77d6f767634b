#pragma once
// A finite cylinder of radius R and length L centred at `center` along unit `axis`.
// inside = true: particles inside (a drum or a die); the lateral surface is feature 0 and the
//   optional end caps are features 1 (at -L/2) and 2 (at +L/2).
// inside = false: particles outside a solid cylinder (a roll, a pin): contact with the nearest
//   point of its surface (lateral, rim or end face), feature 0.
#include "comminute/geometry/wall.hpp"

namespace comminute {

class CylinderWall : public Wall {
 public:
  CylinderWall(const Vec3& center, const Vec3& axis, double radius, double length, bool inside,
               bool caps);
  std::string type() const override { return "cylinder"; }
  int contacts(const Vec3& x, double r, double margin,
               std::vector<WallContact>& out) const override;
  void advance(double dt) override;
  SurfaceMesh surface(double extent) const override;
  bool surface_moves() const override;
  void save(Archive& a, const std::string& prefix) const override;
  void load(const Archive& a, const std::string& prefix) override;

 private:
  Vec3 center_, axis_;
  double radius_, length_;
  bool inside_, caps_;
};

}  // namespace comminute
