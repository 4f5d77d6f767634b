#pragma once
// Checks that every key a case file used is documented in docs/case-file.md: a key as `key` in a
// table row, a top-level table as its [heading].
#include <gtest/gtest.h>

#include <string>

#include "comminute/core/case_table.hpp"

namespace comminute::testing {

inline void expect_used_keys_documented(const CaseFile& f, const std::string& doc) {
  for (const std::string& path : f.used_keys()) {
    std::string leaf = path.substr(path.find_last_of('.') + 1);
    leaf = leaf.substr(0, leaf.find('['));
    if (path.rfind("materials.", 0) == 0 && path.find('.', 10) == std::string::npos) continue;
    if (path.find('.') == std::string::npos) {  // a top-level table: documented as a heading
      EXPECT_NE(doc.find("[" + leaf), std::string::npos) << path << " is not in docs/case-file.md";
      continue;
    }
    EXPECT_NE(doc.find("`" + leaf + "`"), std::string::npos)
        << path << " is not in docs/case-file.md";
  }
}

}  // namespace comminute::testing
