#pragma once
// Samples a particle's texture from a texture volume: the particle's ball, of radius r, centred at
// a random point of the volume and turned by a random rotation, is read at the centre of each of
// its n^3 cube cells mapped onto the ball by the equal-volume map (nearest voxel of the volume).
#include <cstdint>
#include <map>
#include <vector>

#include "comminute/breakage/texture/texture_pool.hpp"
#include "comminute/breakage/texture/texture_volume.hpp"
#include "comminute/core/rng.hpp"

namespace comminute::breakage::texture {

// The ball point (radius r, centred at 0) of cell (i, j, k) of an n-cube.
Vec3 cell_in_ball(std::size_t i, std::size_t j, std::size_t k, std::size_t n, double r);

// Samples n-cubes from a volume: for a ball of radius r (m) at a uniform random position and a
// uniformly random orientation (Shoemake's quaternion), drawn from rng. Keeps the cells' points on
// the unit ball per n, so the map is evaluated once per resolution, not once per particle.
class CubeSampler {
 public:
  Cube sample(const TextureVolume& volume, std::size_t n, double r, Rng& rng);

 private:
  const std::vector<Vec3>& unit_points(std::size_t n);
  std::map<std::size_t, std::vector<Vec3>> points_;
};

// One-off sampling (tests): a fresh CubeSampler.
Cube sample_cube(const TextureVolume& volume, std::size_t n, double r, Rng& rng);

// Voxel count of each of `phases` phases in a cube.
std::vector<std::uint64_t> phase_counts(const Cube& c, std::size_t phases);

}  // namespace comminute::breakage::texture
