// docs/ARCHITECTURE.md draws the rooms in the order the build enforces them: its room table, the
// CMake list COMMINUTE_ROOMS and the folders of src/comminute must agree.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "source_file.hpp"

namespace {
std::vector<std::string> rooms_in_docs() {
  std::vector<std::string> out;
  std::istringstream in(comminute::testing::read_source_file("docs/ARCHITECTURE.md"));
  const std::regex row(R"(^\| `([a-z_]+)/` \|)");
  std::smatch m;
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, m, row)) out.push_back(m[1]);
  return out;
}

std::vector<std::string> rooms_in_cmake() {
  const std::string text = comminute::testing::read_source_file("src/comminute/CMakeLists.txt");
  const auto at = text.find("set(COMMINUTE_ROOMS");
  std::istringstream in(text.substr(at + 19, text.find(')', at) - at - 19));
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}
}  // namespace

TEST(Architecture, DocsCMakeAndFoldersListTheSameRoomsInOneOrder) {
  const auto docs = rooms_in_docs(), cmake = rooms_in_cmake();
  ASSERT_FALSE(cmake.empty());
  EXPECT_EQ(docs, cmake);
  std::vector<std::string> folders;
  for (const auto& e : std::filesystem::directory_iterator(
           std::filesystem::path(COMMINUTE_SOURCE_DIR) / "src" / "comminute"))
    if (e.is_directory()) folders.push_back(e.path().filename().string());
  std::sort(folders.begin(), folders.end());
  auto sorted = cmake;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(folders, sorted);
}
