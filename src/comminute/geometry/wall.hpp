#pragma once
// Walls behind one interface: infinite plane, box, finite cylinder (inside or outside); triangle
// meshes (MeshWall) implement the same interface. A wall reports the contact features a sphere
// touches (a box corner touches up to three faces), moves by its Kinematics, and accumulates the
// force and torque the particles exert on it (outputs). Each wall type is a plug-in: its factory in
// WallRegistry takes the view of its [[walls]] table and reads the keys of its shape; the keys
// common to all walls (name, material, motion) are read by the case builder.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "comminute/core/archive.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/core/registry.hpp"
#include "comminute/core/vec3.hpp"

namespace comminute {

// Prescribed rigid motion: translation at constant velocity plus rotation at constant angular
// velocity about an axis through `center` (which moves with the wall).
struct Kinematics {
  Vec3 velocity;          // m/s
  Vec3 angular_velocity;  // rad/s
  Vec3 center;            // m, a point on the rotation axis (current position)
  // Velocity of the wall material at point p.
  Vec3 velocity_at(const Vec3& p) const { return velocity + cross(angular_velocity, p - center); }
  bool moving() const { return norm2(velocity) > 0 || norm2(angular_velocity) > 0; }
};

struct WallContact {
  Vec3 normal;         // unit, from the wall into the particle
  Vec3 point;          // contact point on the wall surface, m
  double overlap = 0;  // m (> 0 when touching; candidates within the skin may be <= 0)
  int feature = 0;     // which face/edge/triangle (history key, stable over time)
  int element = -1;    // the triangle of a mesh wall that produced it (wear), else -1
};

// A triangle surface for visualisation (ParaView) of any wall.
struct SurfaceMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<double> wear_depth;  // m, per triangle (empty: the wall tracks no wear)
};

class Wall {
 public:
  virtual ~Wall() = default;
  virtual std::string type() const = 0;
  // Appends the features of this wall closer to sphere (x, r) than r + margin. Returns the count.
  virtual int contacts(const Vec3& x, double r, double margin,
                       std::vector<WallContact>& out) const = 0;
  // Candidate elements (the triangles of a mesh wall): appends, ascending, the elements closer to
  // sphere (x, r) than r + margin and returns true; a wall without elements returns false.
  virtual bool near_elements(const Vec3& /*x*/, double /*r*/, double /*margin*/,
                             std::vector<std::uint32_t>& /*out*/) const {
    return false;
  }
  // contacts(x, r, margin, out) looked up among `elements` only. Exact when they hold every
  // element closer than r + margin: a near_elements list taken with margin m covers every later
  // look-up with margin 0 while the sphere's reach grew and the wall travelled less than m in all.
  virtual int contacts_among(const Vec3& x, double r, double margin,
                             std::span<const std::uint32_t> /*elements*/,
                             std::vector<WallContact>& out) const {
    return contacts(x, r, margin, out);
  }
  // Moves the geometry rigidly over dt with the current kinematics.
  virtual void advance(double dt) = 0;
  // Triangulated surface for output; `extent` (m) bounds infinite walls.
  virtual SurfaceMesh surface(double extent) const = 0;
  // True when the wall's surface moves (so particles near it must be re-found): translation, or
  // rotation that changes the shape's position (a cylinder turning about its own axis does not).
  virtual bool surface_moves() const { return norm2(kinematics.velocity) > 0; }
  // Distance (m) the surface may have moved over dt with the current kinematics: the neighbour
  // lists are rebuilt once it adds up to half the skin.
  virtual double travel(double dt) const { return norm(kinematics.velocity) * dt; }
  // True when a rotating wall's candidates cannot be kept by travel() and every particle must be
  // checked every step (analytic walls turning about a point off their axis).
  virtual bool full_scan() const {
    return surface_moves() && norm2(kinematics.angular_velocity) > 0;
  }
  // True when a contact passing from feature `from` to feature `to` (a sphere rolling from one
  // triangle to the next) is the same contact, whose history carries over. Analytic walls: never.
  virtual bool continues(int /*from*/, int /*to*/) const { return false; }
  // The key of a touching feature after its particle was wrapped into a periodic domain by
  // `shift` (PeriodicMap::Shift): a wall that stands for its periodic images re-keys it to the
  // image the particle now meets; every other wall keeps it.
  virtual int feature_after_wrap(int feature, const std::array<int, 3>& /*shift*/) const {
    return feature;
  }
  // Sliding wear: a contact on `element` (WallContact::element) pressed with normal force fn (N)
  // slid a distance s (m) in this step. Walls that do not track wear ignore it.
  virtual bool tracks_wear() const { return false; }
  virtual void wear(int /*element*/, double /*fn*/, double /*s*/) {}
  // False for a wall that can translate but not rotate (the case builder refuses an
  // angular_velocity for it).
  virtual bool can_rotate() const { return true; }
  // Checkpoint of the geometry state under names prefixed by `prefix`.
  virtual void save(Archive& a, const std::string& prefix) const = 0;
  virtual void load(const Archive& a, const std::string& prefix) = 0;

  std::string name;  // from the case file, used in outputs
  std::uint16_t material = 0;
  Kinematics kinematics;
  Vec3 force;   // N, total force exerted by particles on the wall in the last step
  Vec3 torque;  // N m, about kinematics.center
};

using WallRegistry = Registry<Wall, const CaseTable&>;

}  // namespace comminute
