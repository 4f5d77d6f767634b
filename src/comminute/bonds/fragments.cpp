#include "comminute/bonds/fragments.hpp"

#include <numeric>

namespace comminute::bonds {

UnionFind::UnionFind(std::size_t n) : parent_(n), size_(n, 1) {
  std::iota(parent_.begin(), parent_.end(), std::size_t{0});
}

std::size_t UnionFind::find(std::size_t i) {
  while (parent_[i] != i) {
    parent_[i] = parent_[parent_[i]];
    i = parent_[i];
  }
  return i;
}

void UnionFind::join(std::size_t a, std::size_t b) {
  a = find(a);
  b = find(b);
  if (a == b) return;
  if (size_[a] < size_[b]) std::swap(a, b);
  parent_[b] = a;
  size_[a] += size_[b];
}

std::vector<std::uint32_t> component_labels(std::size_t n, const std::vector<std::uint32_t>& first,
                                            const std::vector<std::uint32_t>& second,
                                            std::uint32_t& count) {
  UnionFind u(n);
  for (std::size_t k = 0; k < first.size(); ++k) u.join(first[k], second[k]);
  constexpr std::uint32_t unset = 0xFFFFFFFFu;
  std::vector<std::uint32_t> root_label(n, unset), label(n);
  count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = u.find(i);
    if (root_label[r] == unset) root_label[r] = count++;
    label[i] = root_label[r];
  }
  return label;
}

}  // namespace comminute::bonds
