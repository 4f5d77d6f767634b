#include "comminute/analysis/product_size.hpp"

namespace comminute::analysis {

ProductSizes product_sizes(const std::vector<ParticleRecord>& log, double t_from, double t_to,
                           const std::vector<double>& sieves, std::optional<std::uint32_t> outlet) {
  ProductSizes out;
  out.mass_passing.assign(sieves.size(), 0.0);
  for (const auto& r : log) {
    if (!(r.time > t_from && r.time <= t_to)) continue;
    if (outlet && r.site != *outlet) continue;
    ++out.count;
    out.mass += r.mass;
    for (std::size_t s = 0; s < sieves.size(); ++s)
      if (r.diameter <= sieves[s]) out.mass_passing[s] += r.mass;
  }
  return out;
}

}  // namespace comminute::analysis
