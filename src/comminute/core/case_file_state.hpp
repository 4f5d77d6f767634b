#pragma once
// What every CaseTable of one file shares (internal to core/: the case-file implementation files).
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include <toml++/toml.h>

namespace comminute {

struct CaseFileState {
  std::filesystem::path path;
  toml::table doc;
  std::set<std::string> used;
  std::set<std::string> asked;  // every key a reader looked for, present or not (suggestions)
  std::map<std::string, std::filesystem::path> files;  // data files named, by key path
};

}  // namespace comminute
