#include "comminute/breakage/placement/placement_model.hpp"

namespace comminute::breakage {

std::vector<Sphere> InsideParentPlacement::place(const Sphere& parent,
                                                 const std::vector<double>& radii,
                                                 const std::vector<double>& masses,
                                                 const std::vector<Sphere>& neighbours,
                                                 const WallOverlap& walls, Rng& rng) const {
  return place_fragments(parent, radii, masses, neighbours, walls, opt_, rng);
}

namespace {
// Keys of the [breakage] table: overlap_ratio (eps, (0, 0.5], 0.01), placement_attempts (30).
std::unique_ptr<FragmentPlacement> make(const CaseTable& t) {
  PlacementOptions opt;
  opt.overlap_ratio = t.number("overlap_ratio", Limits{0.0, 0.5, true, false}, 0.01);
  opt.attempts = static_cast<int>(t.integer("placement_attempts", 1, 10000, 30));
  return std::make_unique<InsideParentPlacement>(opt);
}
const bool registered = PlacementRegistry::add("inside_parent", &make);
}  // namespace

}  // namespace comminute::breakage
