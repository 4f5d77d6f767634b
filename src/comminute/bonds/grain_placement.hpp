#pragma once
// Places bonded-grain templates in a region: the region is cut into `layers` equal slices along
// its axis (a box: z; a cylinder: its axis), layer 1 at the low end; each layer receives its share
// of the grains (the remainder to the lowest layers). Each grain takes template k mod (number of
// templates), a uniformly random orientation (a random unit quaternion, Shoemake, Graphics Gems
// III, 1992) and a uniformly random centre in its slice; a candidate with a sub-sphere outside
// the region, overlapping an earlier sub-sphere or a wall is redrawn (random sequential addition
// of whole grains), up to `attempts` times per grain. A grain's layer is the slice of its centre.
#include <cstdint>
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

// Rotation matrix rows of a uniformly random orientation.
std::array<Vec3, 3> random_rotation(Rng& rng);

}  // namespace comminute::bonds
