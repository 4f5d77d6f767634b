#pragma once
// Builds the bonds module from a case file's [bonds] table (the law by name and its parameters,
// when and which pairs to bond). Every key: docs/case-file.md, [bonds].
#include "comminute/bonds/bonds_module.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/io/case/dem_case.hpp"

namespace comminute::io {

// When the case has a [bonds] table, appends a BondsModule to sim.modules and returns it;
// otherwise returns nullptr. Call after build_dem_case, before add_breakage (bond forces are in
// place before breakage looks at the step) and before CaseFile::reject_unknown().
bonds::BondsModule* add_bonds(const CaseTable& root, DemCase& dem);

}  // namespace comminute::io
