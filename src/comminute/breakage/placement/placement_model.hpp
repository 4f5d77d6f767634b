#pragma once
// Fragment placement models: where the fragments of a broken particle start. One interface,
// chosen by name in the case file ([breakage] placement = "inside_parent", the default); the
// model's factory reads its own keys from the [breakage] table.
#include <memory>
#include <string>
#include <vector>

#include "comminute/breakage/placement/fragment_placement.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/core/registry.hpp"

namespace comminute::breakage {

class FragmentPlacement {
 public:
  virtual ~FragmentPlacement() = default;
  virtual std::string name() const = 0;
  // Centres and starting radii of fragments of final radii `radii` and masses `masses` (largest
  // first) replacing `parent`, given the neighbours and the walls.
  virtual std::vector<Sphere> place(const Sphere& parent, const std::vector<double>& radii,
                                    const std::vector<double>& masses,
                                    const std::vector<Sphere>& neighbours, const WallOverlap& walls,
                                    Rng& rng) const = 0;
};

using PlacementRegistry = Registry<FragmentPlacement, const CaseTable&>;

// "inside_parent": place_fragments (docs/models.md eq. C4) with its options.
class InsideParentPlacement final : public FragmentPlacement {
 public:
  explicit InsideParentPlacement(const PlacementOptions& opt) : opt_(opt) {}
  std::string name() const override { return "inside_parent"; }
  std::vector<Sphere> place(const Sphere& parent, const std::vector<double>& radii,
                            const std::vector<double>& masses,
                            const std::vector<Sphere>& neighbours, const WallOverlap& walls,
                            Rng& rng) const override;
  const PlacementOptions& options() const { return opt_; }

 private:
  PlacementOptions opt_;
};

}  // namespace comminute::breakage
