#pragma once
// Bonded grains from a case file: [[insert]] type = "clusters" (grain templates packed with
// sub-spheres and placed in layers, bonds/cluster_packing.hpp and bonds/grain_placement.hpp) and
// the [grain_breakage] table (bonds/grain_breakage_module.hpp). Every key: docs/case-file.md.
#include <cstdint>

#include "comminute/bonds/bonds_module.hpp"
#include "comminute/bonds/grain_breakage_module.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/io/case/dem_case.hpp"

namespace comminute::io {

struct InsertedClusters {
  double radius = 0;  // m, of the sub-spheres (the smallest particle, for the time step)
  Vec3 lo, hi;        // m, bounds of the region
};

// Packs the templates, places the grains and adds their sub-spheres to sim.particles now (with
// the per-particle fields `grain` and `layer`). `root` is the whole case (its [bonds] table must
// bond within grains, and its gap tolerance must join every template into one piece).
InsertedClusters insert_clusters(const CaseTable& root, const CaseTable& t, std::uint16_t material,
                                 std::size_t index, Simulation& sim);

// When the case has a [grain_breakage] table, appends the module (after the bonds module) and
// returns it; otherwise nullptr. Call after add_bonds.
bonds::GrainBreakageModule* add_grain_breakage(const CaseTable& root, DemCase& dem,
                                               const bonds::BondsModule* bonds);

}  // namespace comminute::io
