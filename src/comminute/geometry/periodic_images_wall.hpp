#pragma once
// A wall given for one period of a periodic domain (`periodic_images = true`): the machine is the
// union of its images under the periodic map (a single mixer blade and its n − 1 turned copies
// about a sector's axis; a chute plate and its copies one period along a periodic axis). A
// particle meets every image: its own images are tested against the one stored wall and each
// contact found is brought back into the particle's frame (point by the inverse image, normal
// turned back). Each physical contact is found once as long as the images do not overlap one
// another. Feature keys are (feature of the stored wall) × (image count) + (image index), so
// that history follows a contact, and feature_after_wrap re-keys it when the particle is wrapped
// into the domain (the same physical copy is then another image of the particle).
//
// Forces and torques of all images are summed on this wall about its own centre: for a sector
// that is the sector's share of the machine (× n gives the whole machine's torque about the axis).
#include <memory>
#include <vector>

#include "comminute/geometry/periodic_map.hpp"
#include "comminute/geometry/wall.hpp"

namespace comminute {

class PeriodicImagesWall : public Wall {
 public:
  // Takes over `inner` (its name, material and kinematics move to this wall).
  PeriodicImagesWall(std::unique_ptr<Wall> inner, const PeriodicMap& map);

  std::string type() const override { return inner_->type(); }
  int contacts(const Vec3& x, double r, double margin,
               std::vector<WallContact>& out) const override;
  void advance(double dt) override;
  SurfaceMesh surface(double extent) const override;
  // (the stored wall's kinematics follow this wall's at each advance)
  bool surface_moves() const override { return inner_->surface_moves(); }
  double travel(double dt) const override { return inner_->travel(dt); }
  bool full_scan() const override { return inner_->full_scan(); }
  bool continues(int from, int to) const override;
  int feature_after_wrap(int feature, const std::array<int, 3>& shift) const override;
  bool tracks_wear() const override { return inner_->tracks_wear(); }
  void wear(int element, double fn, double s) override { inner_->wear(element, fn, s); }
  bool can_rotate() const override { return inner_->can_rotate(); }
  void save(Archive& a, const std::string& prefix) const override;
  void load(const Archive& a, const std::string& prefix) override;

  // The images a particle is tested at: the identity first, then every turn of a sector, or
  // every shift in {-1, 0, 1} along the periodic axes.
  const std::vector<PeriodicMap::Shift>& images() const { return images_; }
  const Wall& stored() const { return *inner_; }

 private:
  int image_index(const PeriodicMap::Shift& s) const;  // -1 when not an image

  std::unique_ptr<Wall> inner_;
  PeriodicMap map_;
  std::vector<PeriodicMap::Shift> images_;
};

}  // namespace comminute
