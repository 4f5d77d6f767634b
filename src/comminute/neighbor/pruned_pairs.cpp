#include "comminute/neighbor/pruned_pairs.hpp"

#include <algorithm>

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

void PrunedPairs::carry(const std::vector<std::uint32_t>& kept_from) {
  // kept_from ascends (the kept pairs in their old order, then `none` for the new ones), so each
  // thread finds its first old pair among the kept ones by a search, then walks both in step
  const std::vector<std::uint32_t>& old = pairs_;
  std::vector<std::uint32_t> next;
  select(kept_from.size(), next,
         [&](std::size_t w0, std::size_t w1, std::vector<std::uint32_t>& part) {
           if (w0 == w1) return;
           auto q = std::lower_bound(old.begin(), old.end(), kept_from[w0]);
           for (std::size_t w = w0; w < w1; ++w) {
             const std::uint32_t from = kept_from[w];
             if (from != NeighborList::none) {
               while (q != old.end() && *q < from) ++q;
               if (q == old.end() || *q != from) continue;
             }
             part.push_back(static_cast<std::uint32_t>(w));
           }
         });
  pairs_.swap(next);
}

std::pair<std::size_t, std::size_t> PrunedPairs::range(std::size_t k0, std::size_t k1) const {
  const auto at = [&](std::size_t k) {
    return static_cast<std::size_t>(std::lower_bound(pairs_.begin(), pairs_.end(), k) -
                                    pairs_.begin());
  };
  return {at(k0), at(k1)};
}

}  // namespace comminute
