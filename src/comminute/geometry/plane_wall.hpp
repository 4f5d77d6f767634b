#pragma once
// An infinite plane through `point` whose `normal` points to the side where the particles are.
#include "comminute/geometry/wall.hpp"

namespace comminute {

class PlaneWall : public Wall {
 public:
  PlaneWall(const Vec3& point, const Vec3& normal);
  std::string type() const override { return "plane"; }
  int contacts(const Vec3& x, double r, double margin,
               std::vector<WallContact>& out) const override;
  void advance(double dt) override;
  SurfaceMesh surface(double extent) const override;
  bool surface_moves() const override;
  void save(Archive& a, const std::string& prefix) const override;
  void load(const Archive& a, const std::string& prefix) override;

  const Vec3& point() const { return point_; }
  const Vec3& normal() const { return normal_; }

 private:
  Vec3 point_, normal_;
};

}  // namespace comminute
