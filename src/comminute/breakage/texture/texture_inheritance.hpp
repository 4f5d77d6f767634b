#pragma once
// Texture inheritance on breakage (docs/breakage.md, "Texture inheritance"; the scheme of the
// seed study's texture model). The parent's cube (its voxels already stand for equal volumes of
// its ball: ball_cube_map.hpp) is listed in Morton (Z-) order, so that consecutive cells form
// compact regions, and cut into consecutive blocks with cell counts M_j in proportion to the
// fragment volumes (largest remainder: every parent voxel goes to exactly one fragment, no gaps,
// no duplicates). Block j becomes fragment j's own cube at the fragment's resolution
// n_j = min(max_resolution, ceil(M_j^(1/3))): its K_j = n_j^3 cells, in the fragment cube's own
// Morton order, take the block's labels stretched from M_j to K_j cells, then the phase counts are
// set to K_j b_jk / M_j rounded by largest remainder (b_jk the block's count of phase k). So each
// fragment's composition equals its block's exactly when K_j b_jk / M_j are integers and to one
// fragment voxel otherwise, and the blocks together hold exactly the parent's voxels. The cube
// then maps onto the fragment's ball by the same equal-volume map. Every generation inherits.
// When fragments outnumber the parent's voxels, a fragment without a block (M_j = 0) takes the
// one label at its cut (a 1-cube) — the only case where a voxel is counted twice.
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

#include "comminute/breakage/texture/texture_pool.hpp"

namespace comminute::breakage::texture {

// Integer counts summing to `total`, in proportion to `weights`, each the floor or the ceiling of
// its exact share (largest-remainder method, ties to the lower index).
std::vector<std::size_t> apportion(std::size_t total, const std::vector<double>& weights);

class TextureInheritance {
 public:
  explicit TextureInheritance(std::size_t max_resolution) : max_resolution_(max_resolution) {}

  struct Split {
    std::vector<Cube> cubes;          // one per fragment
    std::vector<std::size_t> blocks;  // M_j, parent cells given to fragment j
    // parent cells (indices into the parent cube, x fastest) of fragment j's block
    std::vector<std::vector<std::uint32_t>> cells;
  };
  // Splits `parent` among fragments of the given volumes (any unit, > 0).
  Split split(const Cube& parent, const std::vector<double>& volumes, std::size_t phases);

  // The cells of an n-cube in Morton order (cached per n).
  const std::vector<std::uint32_t>& morton(std::size_t n);

 private:
  std::size_t max_resolution_;
  std::map<std::size_t, std::vector<std::uint32_t>> morton_;
};

}  // namespace comminute::breakage::texture
