#pragma once
// Places bonded-grain templates in a region: the region is cut into `layers` equal slices along
// its axis (a box: z; a cylinder: its axis), layer 1 at the low end; each layer receives its share
// of the grains (the remainder to the lowest layers). Each grain takes template k mod (number of
// templates), a uniformly random orientation (a random unit quaternion, Shoemake, Graphics Gems
// III, 1992) and a uniformly random centre in its slice; a candidate with a sub-sphere outside
// the region, overlapping an earlier sub-sphere or a wall is redrawn (random sequential addition
// of whole grains), up to `attempts` times per grain. A grain's layer is the slice of its centre.
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "comminute/bonds/cluster_packing.hpp"
#include "comminute/geometry/region.hpp"
#include "comminute/geometry/wall.hpp"

namespace comminute::bonds {

struct PlacedSphere {
  Vec3 x;                                                     // m
  double radius = 0;                                          // m
  std::uint32_t grain = 0, layer = 0, sphere = 0, templ = 0;  // sphere: index in its template
};

struct PlacementRequest {
  Region region;
  std::uint64_t grains = 0;
  int layers = 1;
  int attempts = 2000;
};

// Throws Error naming the layer when a grain does not fit.
std::vector<PlacedSphere> place_grains(const std::vector<GrainTemplate>& templates,
                                       const PlacementRequest& request,
                                       const std::vector<const Wall*>& walls,
                                       const std::vector<Vec3>& occupied_x,
                                       const std::vector<double>& occupied_r, Rng& rng);

// A uniformly random orientation as a unit quaternion (w, x, y, z) (Shoemake, Graphics Gems III,
// 1992, "Uniform random rotations": three uniform numbers u1, u2, u3).
std::array<double, 4> random_quaternion(Rng& rng);
// Rows of the rotation matrix of the unit quaternion q = (w, x, y, z).
std::array<Vec3, 3> rotation_matrix(const std::array<double, 4>& q);
// Rotation matrix rows of a uniformly random orientation: rotation_matrix(random_quaternion(rng)).
std::array<Vec3, 3> random_rotation(Rng& rng);

// Spheres already placed, hashed on a grid of cells of the largest diameter (cell must be at
// least the largest diameter that is added or asked about).
class SphereGrid {
 public:
  explicit SphereGrid(double cell) : cell_(cell) {}
  void add(const Vec3& x, double r);
  bool overlaps(const Vec3& x, double r) const;

 private:
  long cell_of(const Vec3& x, int a) const;
  static std::int64_t key(long i, long j, long k);
  double cell_;
  std::vector<Vec3> x_;
  std::vector<double> r_;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

// One grain placed: its centre, orientation and the world positions of its sub-spheres.
struct GrainPose {
  Vec3 centre;                     // m
  std::array<double, 4> rotation;  // unit quaternion (w, x, y, z), body -> world
  std::vector<Vec3> spheres;       // m, world positions in template order
};

// Random sequential addition of one grain: up to `attempts` times, a centre uniform in
// `sample_from` and a uniformly random orientation; accepted when every sub-sphere lies inside
// `inside`, overlaps no sphere of `grid` and no wall. Returns false when every attempt failed.
bool try_place_grain(const GrainTemplate& t, const Region& sample_from, const Region& inside,
                     const SphereGrid& grid, const std::vector<const Wall*>& walls, int attempts,
                     Rng& rng, GrainPose& pose);

}  // namespace comminute::bonds
