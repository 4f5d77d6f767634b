#pragma once
// The generated machines' tests: a table refused by a machine generator names the file, the
// key and its line.
#include <gtest/gtest.h>

#include <string>

#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/geometry/wall_group.hpp"

namespace comminute::testing {

// Builds machine `type` from `toml` (parsed as file `file`) and expects an InputError for `key`
// at its line, whose message holds `says`.
inline void expect_refused(const std::string& type, const std::string& toml,
                           const std::string& file, const std::string& key,
                           const std::string& says) {
  const CaseFile f = CaseFile::parse(toml, file);
  try {
    WallGroupRegistry::create(type, f.root());
    ADD_FAILURE() << "accepted: " << toml;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file);
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_EQ(e.line(), f.root().line(key)) << e.what();
    EXPECT_GT(e.line(), 0);
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
  }
}

}  // namespace comminute::testing
