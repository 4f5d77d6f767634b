#pragma once
// Samples a particle's texture from a texture volume: the particle's ball, of radius r, centred at
// a random point of the volume and turned by a random rotation, is read at the centre of each of
// its n^3 cube cells mapped onto the ball by the equal-volume map (nearest voxel of the volume).
#include <cstdint>
#include <vector>

#include "comminute/breakage/texture/texture_pool.hpp"
#include "comminute/breakage/texture/texture_volume.hpp"
#include "comminute/core/rng.hpp"

namespace comminute::breakage::texture {

// The ball point (radius r, centred at 0) of cell (i, j, k) of an n-cube.
Vec3 cell_in_ball(std::size_t i, std::size_t j, std::size_t k, std::size_t n, double r);

// An n-cube sampled from `volume` for a ball of radius r (m) at a uniform random position and a
// uniformly random orientation (Shoemake's quaternion), drawn from rng.
Cube sample_cube(const TextureVolume& volume, std::size_t n, double r, Rng& rng);

// Voxel count of each of `phases` phases in a cube.
std::vector<std::uint64_t> phase_counts(const Cube& c, std::size_t phases);

}  // namespace comminute::breakage::texture
