#pragma once
// A wall made of a triangle mesh (STL), moving rigidly by a MotionModel or the constant
// kinematics of the [[walls]] table. The mesh stays in its body frame (contact queries transform
// the sphere centre into it, so a moving mesh is never re-binned); the pose is an orientation
// matrix and a translation. Contacts follow MeshSurface (face, edge and corner regions, one
// contact per touched feature); a contact passing to an adjacent feature keeps its history
// (continues()). Archard wear is summed per triangle.
#include <memory>
#include <vector>

#include "comminute/geometry/mesh_surface.hpp"
#include "comminute/geometry/motion_model.hpp"
#include "comminute/geometry/wall.hpp"

namespace comminute {

struct ArchardWear {
  double coefficient = 0;  // k, dimensionless (0: no wear)
  double hardness = 1;     // H, Pa
};

class MeshWall : public Wall {
 public:
  // `motion` may be null: the wall then keeps the constant kinematics set on it.
  MeshWall(MeshSurface surface, std::unique_ptr<MotionModel> motion, ArchardWear wear);
  std::string type() const override { return "mesh"; }
  int contacts(const Vec3& x, double r, double margin,
               std::vector<WallContact>& out) const override;
  bool near_elements(const Vec3& x, double r, double margin,
                     std::vector<std::uint32_t>& out) const override;
  int contacts_among(const Vec3& x, double r, double margin,
                     std::span<const std::uint32_t> elements,
                     std::vector<WallContact>& out) const override;
  void advance(double dt) override;
  SurfaceMesh surface(double extent) const override;
  bool surface_moves() const override { return kinematics.moving() || motion_ != nullptr; }
  double travel(double dt) const override;
  bool full_scan() const override { return false; }
  bool continues(int from, int to) const override { return mesh_.adjacent(from, to); }
  bool tracks_wear() const override { return archard_.coefficient > 0; }
  void wear(int element, double fn, double s) override;
  void save(Archive& a, const std::string& prefix) const override;
  void load(const Archive& a, const std::string& prefix) override;

  const MeshSurface& mesh() const { return mesh_; }
  // Archard wear volume per triangle (m3).
  const std::vector<double>& wear_volume() const { return wear_volume_; }
  Vec3 to_world(const Vec3& body) const;
  std::size_t bytes() const;

 private:
  Vec3 to_body(const Vec3& world) const;
  Vec3 rotate_to_body(const Vec3& world) const;
  Vec3 rotate_to_world(const Vec3& body) const;
  // Brings contacts out[first, end) from the body frame to the world; returns their count.
  int to_world(std::vector<WallContact>& out, std::size_t first) const;
  // The pose at t_new from a motion with a closed-form pose (MotionModel::pose); false without.
  bool place_exactly(double t_old, double t_new);

  MeshSurface mesh_;
  std::unique_ptr<MotionModel> motion_;
  ArchardWear archard_;
  std::vector<double> wear_volume_;
  std::array<Vec3, 3> axes_{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};  // columns of R
  Vec3 offset_;                                                            // T: world = R body + T
  double motion_time_ = 0;                                                 // s
  Vec3 start_center_;  // m, the rotation centre at t = 0 (closed-form poses)
  bool start_center_known_ = false;
  // travel(): the largest distance of a vertex from a body-frame rotation centre and from the
  // axis through it (m), cached for the centre and axis they were measured from
  struct Reach {
    Vec3 center, axis;
    double from_center = -1, from_axis = -1;  // (< 0: not measured yet)
  };
  mutable Reach reach_;
  // The largest distance of a vertex from the line through body-frame point c along unit a (m),
  // or an upper bound of it within a millionth of the reach.
  double axis_reach(const Vec3& c, const Vec3& a) const;
};

}  // namespace comminute
