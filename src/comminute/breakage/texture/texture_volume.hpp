#pragma once
// A texture volume: a voxel image of an ore, one phase label (1 byte) per voxel, held once and
// shared by every particle that samples it (std::shared_ptr<const TextureVolume>); particles copy
// only their own small cube (texture_pool.hpp). The volume is periodic: a point outside it wraps,
// so particles larger than the image or placed anywhere in space still sample it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "comminute/core/vec3.hpp"

namespace comminute::breakage::texture {

// A phase of the ore (mineral): its density and its strength relative to the reference strength
// (f_rel = sigma / sigma_ref, the weights of the composition-dependent criterion).
struct Phase {
  std::string name;
  double density = 0;            // kg/m3
  double relative_strength = 1;  // -
};

class TextureVolume {
 public:
  // nx x ny x nz voxels of edge `voxel_size` (m); labels x fastest, then y, then z.
  TextureVolume(std::size_t nx, std::size_t ny, std::size_t nz, double voxel_size,
                std::vector<std::uint8_t> labels, std::vector<Phase> phases);

  std::size_t nx() const { return nx_; }
  std::size_t ny() const { return ny_; }
  std::size_t nz() const { return nz_; }
  double voxel_size() const { return voxel_; }
  Vec3 extent() const;  // m, edge lengths of the box
  const std::vector<Phase>& phases() const { return phases_; }
  std::uint8_t label(std::size_t i, std::size_t j, std::size_t k) const {
    return labels_[i + nx_ * (j + ny_ * k)];
  }
  // Phase at a point (m), the box repeated periodically.
  std::uint8_t at(const Vec3& x) const;
  // Volume fraction of each phase over the whole image.
  std::vector<double> fractions() const;
  std::size_t bytes() const { return labels_.size(); }

 private:
  std::size_t nx_, ny_, nz_;
  double voxel_;
  std::vector<std::uint8_t> labels_;
  std::vector<Phase> phases_;
};

// Reads a raw voxel image with a small text header (docs/breakage.md, "Texture images"):
//   comminute-texture 1
//   size <nx> <ny> <nz>
//   voxel_size <m>
//   end_header
// followed by exactly nx*ny*nz bytes, one phase label per voxel (x fastest). Labels must be below
// phases.size(). Throws Error with the file name on any mismatch.
TextureVolume read_raw_texture(const std::string& path, std::vector<Phase> phases);
// Writes the same format (tests, and saving a generated volume).
void write_raw_texture(const std::string& path, const TextureVolume& v);

}  // namespace comminute::breakage::texture
