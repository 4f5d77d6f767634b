#pragma once
// The per-particle textures of a run, in one shared, compact pool: each particle's n^3 cube of
// phase labels (n its resolution), bit-packed (1, 2, 4 or 8 bits per voxel for up to 2, 4, 16,
// 255 phases) into one array of 64-bit words. A texture is keyed by the id of the particle that
// owns it. Cube cells are listed x fastest; cell (i, j, k) of an n-cube is the unit-cube point
// ((i + 1/2)/n - 1/2, ...), mapped onto the particle's ball by the equal-volume map
// (ball_cube_map.hpp), so every cell holds the same volume of the particle.
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "comminute/core/archive.hpp"

namespace comminute::breakage::texture {

// Phase labels of one cube, unpacked (the working form of sampling and inheritance).
struct Cube {
  std::size_t n = 0;                 // cells per edge
  std::vector<std::uint8_t> labels;  // n^3, x fastest
};

class TexturePool {
 public:
  explicit TexturePool(std::size_t phases = 2);
  std::size_t phases() const { return phases_; }
  unsigned bits_per_voxel() const { return bits_; }

  // Stores (or replaces) the texture of particle `owner`.
  void put(std::uint64_t owner, const Cube& c);
  bool has(std::uint64_t owner) const { return entries_.count(owner) > 0; }
  Cube get(std::uint64_t owner) const;  // throws Error if absent
  std::size_t resolution(std::uint64_t owner) const;
  // Voxel count of each phase in the texture of `owner`.
  std::vector<std::uint64_t> counts(std::uint64_t owner) const;
  void erase(std::uint64_t owner);
  std::size_t size() const { return entries_.size(); }
  // Ids of the particles that own a texture, ascending.
  std::vector<std::uint64_t> owners() const;

  // Bytes per the live textures: packed labels plus the index (deterministic, so restarts
  // reproduce it; the words of erased textures, reclaimed once they outnumber the live ones, and
  // the vector's spare capacity come on top: at most about twice the packed labels).
  std::size_t bytes() const;
  // Bytes of the packed labels of the live textures only.
  std::size_t live_bytes() const { return live_words_ * sizeof(std::uint64_t); }

  // Checkpoint (names prefixed by `prefix`), bit for bit.
  void save(Archive& a, const std::string& prefix) const;
  void load(const Archive& a, const std::string& prefix);

 private:
  struct Entry {
    std::size_t offset = 0;  // first word
    std::uint32_t n = 0;     // resolution
  };
  std::size_t words_for(std::size_t n) const;
  void reclaim();  // drops the words of erased textures

  std::size_t phases_;
  unsigned bits_;
  std::vector<std::uint64_t> words_;
  std::unordered_map<std::uint64_t, Entry> entries_;
  std::size_t live_words_ = 0;
};

}  // namespace comminute::breakage::texture
