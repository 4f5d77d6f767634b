#pragma once
// Keys of the fracture models that were renamed when the DEM breakage tables and the population
// balance tables got one set of keys: an old key is an InputError that names the new one.
#include <initializer_list>
#include <utility>

#include "comminute/core/case_table.hpp"

namespace comminute::fracture {

struct RenamedKey {
  const char* old_key;
  const char* new_key;
};

// Fails with "key 'old' was renamed: use 'new'" (file, line, key) when `t` holds an old key.
void reject_renamed_keys(const CaseTable& t, std::initializer_list<RenamedKey> renamed);

}  // namespace comminute::fracture
