#pragma once
// Artificial ores: target-phase grains in a matrix (phase 0), voxelised into a periodic
// TextureVolume. Two models (docs/models.md eq. T2-T3):
//   boolean_spheres  grains are spheres with Poisson-distributed centres (Boolean model); grain
//                    radii log-normal (median, log-standard-deviation); the intensity is chosen
//                    so that the expected volume fraction is the one asked for;
//   lattice          a cubic lattice of cubic grains of one edge (Wiegel's random-lattice model),
//                    each grain of phase k with probability equal to its volume fraction.
// Several grain phases are laid down in order, each only into the matrix left by the earlier
// ones, so each phase's expected volume fraction is the one asked for.
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/breakage/texture/texture_volume.hpp"
#include "comminute/core/rng.hpp"

namespace comminute::breakage::texture {

// One grain phase of a generated ore.
struct GrainSpec {
  std::uint8_t phase = 1;        // label (0 is the matrix)
  double volume_fraction = 0.1;  // -, of the whole volume
  double grain_radius = 1e-3;    // m: median radius (boolean_spheres), half the cell edge (lattice)
  double grain_radius_sigma = 0;  // -, log-standard-deviation of the radius (boolean_spheres)
};

enum class TextureModel { boolean_spheres, lattice };

struct GeneratorSpec {
  TextureModel model = TextureModel::boolean_spheres;
  std::size_t nx = 64, ny = 64, nz = 64;  // voxels
  double voxel_size = 1e-4;               // m
  std::vector<GrainSpec> grains;
};

// The stream the generator draws from: derived from the texture stream, so that sampling
// particle textures (rng_stream::texture) and generating the volume do not share numbers.
inline constexpr std::uint64_t generator_stream = rng_stream::texture | (std::uint64_t{1} << 32);

// Generates the volume with Rng(seed, generator_stream). Throws Error on inconsistent fractions.
TextureVolume generate_texture(const GeneratorSpec& spec, std::vector<Phase> phases,
                               std::uint64_t seed);

}  // namespace comminute::breakage::texture
