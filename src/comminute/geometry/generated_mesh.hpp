#pragma once
// Helpers shared by the wall types that generate their mesh from dimensions (ball mill, mixer):
// the optional `stl_file` key. (Their drive is a RampedRotation, ramped_rotation.hpp.)
#include "comminute/core/case_table.hpp"
#include "comminute/geometry/stl_file.hpp"

namespace comminute {

// When table t has `stl_file`: writes m there as a binary STL (folders created; a failure is the
// key's InputError).
void write_stl_if_asked(const CaseTable& t, const IndexedMesh& m);

}  // namespace comminute
