#include "comminute/io/case/bonds_case.hpp"

#include <fmt/format.h>

#include "comminute/core/error.hpp"

namespace comminute::io {

bonds::BondsModule* add_bonds(const CaseTable& root, DemCase& dem) {
  const auto t = root.optional_table("bonds");
  if (!t) return nullptr;
  if (root.has("periodic"))
    t->fail("",
            "bonds do not work with [periodic] boundaries yet (a bond across the boundary "
            "would need the periodic image of its partner)");
  Simulation& sim = *dem.sim;
  auto law = bonds::BondLawRegistry::create(t->choice("law", bonds::BondLawRegistry::names()), *t);
  bonds::BondOptions opt;
  opt.create_at = t->number("create_at", Limits::non_negative(), 0.0);
  opt.gap_tolerance = t->number("gap_tolerance", Limits::non_negative(), 0.0);
  opt.within_grain = t->boolean("within_grain", false);
  if (t->has("materials")) {
    for (const std::string& name : t->strings("materials")) {
      const int k = sim.materials.find(name);
      if (k < 0) t->fail("materials", fmt::format("'{}' is not a material of [materials]", name));
      opt.materials.push_back(static_cast<std::uint16_t>(k));
    }
    if (opt.materials.empty()) t->fail("materials", "is empty: name at least one material");
  }
  auto module = std::make_unique<bonds::BondsModule>(std::move(law), std::move(opt));
  bonds::BondsModule* out = module.get();
  sim.modules.push_back(std::move(module));
  return out;
}

}  // namespace comminute::io
