#pragma once
// The inside of an axis-aligned box [lo, hi] (particles inside); faces can be left open.
// Features 0..5 = faces -x, +x, -y, +y, -z, +z. Moves by translation only.
#include <array>

#include "comminute/geometry/wall.hpp"

namespace comminute {

class BoxWall : public Wall {
 public:
  BoxWall(const Vec3& lo, const Vec3& hi, std::array<bool, 6> open);
  std::string type() const override { return "box"; }
  int contacts(const Vec3& x, double r, double margin,
               std::vector<WallContact>& out) const override;
  void advance(double dt) override;
  SurfaceMesh surface(double extent) const override;
  bool can_rotate() const override { return false; }
  void save(Archive& a, const std::string& prefix) const override;
  void load(const Archive& a, const std::string& prefix) override;

 private:
  Vec3 lo_, hi_;
  std::array<bool, 6> open_;
};

}  // namespace comminute
