#include "comminute/breakage/texture/texture_inheritance.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "comminute/core/error.hpp"

namespace comminute::breakage::texture {

std::vector<std::size_t> apportion(std::size_t total, const std::vector<double>& weights) {
  const double sum = std::accumulate(weights.begin(), weights.end(), 0.0);
  std::vector<std::size_t> n(weights.size(), 0);
  if (weights.empty() || !(sum > 0)) return n;
  std::vector<std::pair<double, std::size_t>> rest;
  std::size_t given = 0;
  for (std::size_t j = 0; j < weights.size(); ++j) {
    const double exact = static_cast<double>(total) * weights[j] / sum;
    n[j] = static_cast<std::size_t>(std::floor(exact));
    given += n[j];
    rest.emplace_back(exact - static_cast<double>(n[j]), j);
  }
  std::stable_sort(rest.begin(), rest.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t k = 0; given < total; ++k, ++given) ++n[rest[k % rest.size()].second];
  return n;
}

namespace {
// Interleaves the bits of i, j, k (Morton code).
std::uint64_t morton_code(std::uint32_t i, std::uint32_t j, std::uint32_t k) {
  std::uint64_t c = 0;
  for (unsigned b = 0; b < 21; ++b)
    c |= ((std::uint64_t{i} >> b & 1) << (3 * b)) | ((std::uint64_t{j} >> b & 1) << (3 * b + 1)) |
         ((std::uint64_t{k} >> b & 1) << (3 * b + 2));
  return c;
}

std::size_t ceil_cbrt(std::size_t m) {
  auto n = static_cast<std::size_t>(std::cbrt(static_cast<double>(m)));
  while (n * n * n < m) ++n;
  while (n > 1 && (n - 1) * (n - 1) * (n - 1) >= m) --n;
  return std::max<std::size_t>(n, 1);
}

// Changes the fewest labels of `c` so that phase k occurs quota[k] times, preferring cells next
// (in the Morton sequence) to a cell of the phase that is short.
void meet_quota(std::vector<std::uint8_t>& c, const std::vector<std::size_t>& quota) {
  std::vector<long> need(quota.size(), 0);
  for (std::size_t k = 0; k < quota.size(); ++k) need[k] = static_cast<long>(quota[k]);
  for (std::uint8_t l : c) --need[l];
  auto open = [&] { return std::any_of(need.begin(), need.end(), [](long x) { return x != 0; }); };
  while (open()) {
    bool changed = false;
    for (std::size_t t = 0; t < c.size(); ++t) {
      const std::uint8_t a = c[t];
      if (need[a] >= 0) continue;  // phase a is not in excess
      for (std::size_t nb : {t - 1, t + 1}) {
        if (nb >= c.size()) continue;  // t - 1 wraps to a huge value at t = 0
        const std::uint8_t b = c[nb];
        if (b != a && need[b] > 0) {
          c[t] = b;
          ++need[a];
          --need[b];
          changed = true;
          break;
        }
      }
    }
    if (changed) continue;
    // No excess cell touches a short phase: change any excess cell.
    for (std::size_t t = 0; t < c.size(); ++t) {
      const std::uint8_t a = c[t];
      if (need[a] >= 0) continue;
      for (std::size_t b = 0; b < need.size(); ++b)
        if (need[b] > 0) {
          c[t] = static_cast<std::uint8_t>(b);
          ++need[a];
          --need[b];
          break;
        }
    }
  }
}
}  // namespace

const std::vector<std::uint32_t>& TextureInheritance::morton(std::size_t n) {
  auto it = morton_.find(n);
  if (it != morton_.end()) return it->second;
  std::vector<std::uint32_t> cells(n * n * n);
  std::iota(cells.begin(), cells.end(), 0u);
  std::vector<std::uint64_t> code(cells.size());
  for (std::size_t v = 0; v < cells.size(); ++v)
    code[v] = morton_code(static_cast<std::uint32_t>(v % n), static_cast<std::uint32_t>(v / n % n),
                          static_cast<std::uint32_t>(v / (n * n)));
  std::sort(cells.begin(), cells.end(),
            [&](std::uint32_t a, std::uint32_t b) { return code[a] < code[b]; });
  return morton_.emplace(n, std::move(cells)).first->second;
}

TextureInheritance::Split TextureInheritance::split(const Cube& parent,
                                                    const std::vector<double>& volumes,
                                                    std::size_t phases) {
  if (parent.n == 0 || parent.labels.size() != parent.n * parent.n * parent.n)
    throw Error("texture inheritance: parent cube size mismatch");
  Split s;
  const std::size_t total = parent.labels.size();
  s.blocks = apportion(total, volumes);
  // A fragment left without a cell takes one from the largest block while cells last.
  for (std::size_t j = 0; j < s.blocks.size(); ++j)
    if (s.blocks[j] == 0) {
      auto big = std::max_element(s.blocks.begin(), s.blocks.end());
      if (*big > 1) {
        --*big;
        s.blocks[j] = 1;
      }
    }
  const auto& order = morton(parent.n);
  std::size_t start = 0;
  for (std::size_t j = 0; j < s.blocks.size(); ++j) {
    const std::size_t m = s.blocks[j];
    std::vector<std::uint8_t> block;
    std::vector<std::uint32_t> cells;
    for (std::size_t t = start; t < start + m; ++t) {
      cells.push_back(order[t]);
      block.push_back(parent.labels[order[t]]);
    }
    start += m;
    Cube c;
    if (m == 0) {  // more fragments than parent voxels: the label at the cut
      c.n = 1;
      c.labels = {parent.labels[order[std::min(start, total - 1)]]};
    } else {
      c.n = std::min(max_resolution_, ceil_cbrt(m));
      const std::size_t k = c.n * c.n * c.n;
      std::vector<std::uint8_t> seq(k);
      for (std::size_t t = 0; t < k; ++t)  // stretch the block over the fragment's cells
        seq[t] = block[static_cast<std::size_t>((static_cast<double>(t) + 0.5) *
                                                static_cast<double>(m) / static_cast<double>(k))];
      std::vector<double> b(phases, 0.0);
      for (std::uint8_t l : block) b[l] += 1;
      meet_quota(seq, apportion(k, b));
      c.labels.resize(k);
      const auto& own = morton(c.n);
      for (std::size_t t = 0; t < k; ++t) c.labels[own[t]] = seq[t];
    }
    s.cubes.push_back(std::move(c));
    s.cells.push_back(std::move(cells));
  }
  return s;
}

}  // namespace comminute::breakage::texture
