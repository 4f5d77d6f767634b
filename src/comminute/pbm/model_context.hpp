#pragma once
// What a population-balance model's factory may need besides its own case table: the size grid
// (volume <-> size conversions) and the solid density. Every model family of this folder is a
// Registry<Interface, const CaseTable&, const ModelContext&> filled by the models' own files.
#include "comminute/core/case_table.hpp"
#include "comminute/core/registry.hpp"
#include "comminute/pbm/size_grid.hpp"

namespace comminute::pbm {

struct ModelContext {
  const SizeGrid& grid;
  double density;  // kg/m³
};

}  // namespace comminute::pbm
