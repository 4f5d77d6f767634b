// Every example case of examples/pbm reads without error (unknown keys included), and every key
// it uses is documented in docs/pbm.md.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "comminute/io/case/calibration_case.hpp"
#include "comminute/io/case/pbm_case.hpp"

using namespace comminute;

TEST(PbmExamples, ReadCleanlyAndEveryKeyIsDocumented) {
  std::ifstream in(std::filesystem::path(COMMINUTE_SOURCE_DIR) / "docs/pbm.md");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string docs = ss.str();
  int cases = 0;
  for (const auto& e :
       std::filesystem::directory_iterator(std::filesystem::path(COMMINUTE_EXAMPLES) / "pbm")) {
    if (e.path().extension() != ".toml") continue;
    ++cases;
    const auto file = CaseFile::load(e.path());
    io::read_pbm_problem(file.root());
    io::read_pbm_output(file.root(), e.path());
    if (file.root().has("calibration")) io::read_calibration(file);
    EXPECT_NO_THROW(file.reject_unknown()) << e.path();
    for (const std::string& key : file.used_keys()) {
      std::string path;  // dotted path without array indices
      for (std::size_t i = 0; i < key.size(); ++i)
        if (key[i] == '[')
          i = key.find(']', i);
        else
          path += key[i];
      const std::string leaf = path.substr(path.find_last_of('.') + 1);
      // a key as `leaf` or `leaf = …`; a table as [path] or [[path]]
      const bool documented = docs.find("`" + leaf + "`") != std::string::npos ||
                              docs.find("`" + leaf + " ") != std::string::npos ||
                              docs.find("[" + path + "]") != std::string::npos;
      EXPECT_TRUE(documented) << "key '" << key << "' of " << e.path().filename()
                              << " is not in docs/pbm.md";
    }
  }
  EXPECT_GE(cases, 5);
}
