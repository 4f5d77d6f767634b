#include "comminute/neighbor/pruned_pairs.hpp"

#include <algorithm>

#include "comminute/core/memory.hpp"
#include "comminute/core/parallel.hpp"

namespace comminute {

template <class Keeps>
void PrunedPairs::select(std::size_t n, std::vector<std::uint32_t>& out, Keeps keeps) {
  const int nt = n >= 65536 ? max_threads() : 1;
  parts_.resize(static_cast<std::size_t>(nt));
  offsets_.assign(static_cast<std::size_t>(nt) + 1, 0);
#pragma omp parallel num_threads(nt)
  {
    const auto t = static_cast<std::size_t>(thread_id());
    const auto unt = static_cast<std::size_t>(nt);
    auto& part = parts_[t];
    part.clear();
    // room for every pair of the range, its pages resident at once (core/memory.hpp): filled by
    // push_back from empty, the array would reallocate and fault in its pages one by one
    make_resident(part, n * (t + 1) / unt - n * t / unt);
    keeps(n * t / unt, n * (t + 1) / unt, part);
    offsets_[t + 1] = part.size();
#pragma omp barrier
#pragma omp single
    {
      for (std::size_t u = 0; u < unt; ++u) offsets_[u + 1] += offsets_[u];
      out.resize(offsets_[unt]);
    }
    std::copy(part.begin(), part.end(), out.begin() + static_cast<std::ptrdiff_t>(offsets_[t]));
    std::vector<std::uint32_t>().swap(part);  // not resident between prunes
  }
}

void PrunedPairs::prune(const ParticleStore& p, const NeighborList& list, double buffer,
                        const std::uint8_t* keep) {
  const std::uint32_t *first = list.first.data(), *second = list.second.data();
  const Vec3* X = p.x.data();
  const double* R = p.radius.data();
  const std::uint32_t* flags = p.flags.data();
  select(list.size(), pairs_,
         [&](std::size_t k0, std::size_t k1, std::vector<std::uint32_t>& part) {
           for (std::size_t k = k0; k < k1; ++k) {
             const std::uint32_t i = first[k], j = second[k];
             const double within = R[i] + R[j] + buffer;
             const bool growing = ((flags[i] | flags[j]) & pflag::growing) != 0;
             if (norm2(X[i] - X[j]) < within * within || growing || (keep && keep[k] != 0))
               part.push_back(static_cast<std::uint32_t>(k));
           }
         });
}

std::pair<std::size_t, std::size_t> PrunedPairs::range(std::size_t k0, std::size_t k1) const {
  const auto at = [&](std::size_t k) {
    return static_cast<std::size_t>(std::lower_bound(pairs_.begin(), pairs_.end(), k) -
                                    pairs_.begin());
  };
  return {at(k0), at(k1)};
}

}  // namespace comminute
