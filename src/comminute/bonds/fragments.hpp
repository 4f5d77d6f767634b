#pragma once
// Fragments of bonded grains: the connected components of the particles over the intact bonds,
// found with a disjoint-set forest (union by size, path halving; Tarjan, J. ACM 1975). The
// grain-breakage module rebuilds them on every step in which a bond failed (bonds only ever
// fail, so components only split; a rebuild costs O(particles + bonds) and happens only on such
// steps).
#include <cstdint>
#include <vector>

namespace comminute::bonds {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n);
  std::size_t find(std::size_t i);
  void join(std::size_t a, std::size_t b);

 private:
  std::vector<std::size_t> parent_, size_;
};

// Component label (0 … count−1, numbered in order of first appearance) of each of n nodes.
std::vector<std::uint32_t> component_labels(std::size_t n, const std::vector<std::uint32_t>& first,
                                            const std::vector<std::uint32_t>& second,
                                            std::uint32_t& count);

}  // namespace comminute::bonds
