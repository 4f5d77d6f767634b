#include "comminute/io/case/coarse_graining_case.hpp"

namespace comminute::io {

CoarseGraining coarse_graining_of(const CaseTable& root) {
  CoarseGraining cg;
  const auto t = root.optional_table("coarse_graining");
  if (!t) return cg;
  cg.scale = t->number("scale", Limits::at_least(1.0));
  cg.frequency_exponent = t->number("frequency_exponent", Limits::between(-3.0, 3.0), 0.0);
  return cg;
}

void check_coarse_graining(const CaseTable& root, const Simulation& sim) {
  const auto t = root.optional_table("coarse_graining");
  if (!t || !coarse_graining_of(root).active()) return;
  // the scaling keeps forces ∝ k² for a law without a length of its own (Hertz); the linear
  // law's stiffness (N/m) would have to scale as k, and the case gives it per law, not per pair
  if (sim.law && sim.law->name() != "hertz_mindlin")
    t->fail("scale", "coarse graining scales the hertz_mindlin law only ([contact] model)");
  const auto refuse = [&](const std::string& table) {
    t->fail("scale", "coarse graining cannot be combined with [" + table +
                         "]: a coarse particle's breakage or bonds are not those of its primary "
                         "particles");
  };
  for (const char* other : {"breakage", "bonds", "grain_breakage"})
    if (root.has(other)) refuse(other);
  if (const auto mats = root.optional_table("materials"))
    for (const auto& name : mats->keys())
      if (mats->table(name).has("breakage")) refuse("materials." + name + ".breakage");
}

}  // namespace comminute::io
