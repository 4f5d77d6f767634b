#include "comminute/neighbor/first_owners.hpp"

#include <algorithm>

namespace comminute {

void FirstOwners::find(const std::vector<std::uint32_t>& first,
                       const std::vector<std::uint32_t>& second, std::size_t n, std::size_t from) {
  if (from == 0) lowest_.assign(n, kNone);
  lowest_.resize(n, kNone);
  // (serial: the second slots are scattered; one pass over the pairs at a build)
  std::uint32_t* lowest = lowest_.data();
  std::uint32_t last = kNone;
  for (std::size_t k = from; k < first.size(); ++k) {
    const std::uint32_t i = first[k], j = second[k];
    if (i != last) lowest[i] = std::min(lowest[i], i);  // (its row's pairs are consecutive)
    last = i;
    lowest[j] = std::min(lowest[j], i);
  }
}

}  // namespace comminute
