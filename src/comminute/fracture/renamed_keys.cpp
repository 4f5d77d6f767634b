#include "comminute/fracture/renamed_keys.hpp"

#include <string>

namespace comminute::fracture {

void reject_renamed_keys(const CaseTable& t, std::initializer_list<RenamedKey> renamed) {
  for (const RenamedKey& r : renamed)
    if (t.has(r.old_key))
      t.fail(r.old_key,
             std::string("key '") + r.old_key + "' was renamed: use '" + r.new_key + "'");
}

}  // namespace comminute::fracture
