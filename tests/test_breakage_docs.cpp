// Every key the breakage examples (examples/breakage, and the machine rigs examples/hpgr and
// examples/jaw_crusher) use is documented: breakage keys in docs/breakage.md, the others in
// docs/case-file.md (as `key`); and each example builds without unknown keys, as `comminute
// check` builds it.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "comminute/io/case/breakage_case.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "comminute/io/case/output_case.hpp"
#include "source_file.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using comminute::testing::read_source_file;

TEST(BreakageDocs, EveryKeyOfTheBreakageExamplesIsDocumented) {
  const std::string breakage_doc = read_source_file("docs/breakage.md"),
                    case_doc = read_source_file("docs/case-file.md");
  ASSERT_FALSE(breakage_doc.empty());
  ASSERT_FALSE(case_doc.empty());
  const std::string src = COMMINUTE_SOURCE_DIR;
  std::vector<std::string> cases;
  for (const char* name : {"drop_weight", "slow_compression", "bed_impact", "repeated_impacts"})
    cases.push_back(src + "/examples/breakage/" + name + ".toml");
  // the machine rigs write their generated STL files when built: copies in a scratch folder do
  const comminute::testing::TestDir dir;
  for (const char* rig : {"hpgr/hpgr.toml", "jaw_crusher/jaw_crusher.toml"}) {
    const std::filesystem::path to = dir.path() / std::filesystem::path(rig).filename();
    std::filesystem::copy_file(src + "/examples/" + rig, to);
    cases.push_back(to.string());
  }
  for (const std::string& name : cases) {
    CaseFile f = CaseFile::load(name);
    io::DemCase dem = io::build_dem_case(f.root());
    ASSERT_NE(io::add_breakage(f.root(), dem), nullptr) << name;
    if (auto o = f.root().optional_table("output")) io::read_output_options(*o);
    f.reject_unknown();
    for (const std::string& path : f.used_keys()) {
      std::string leaf = path.substr(path.find_last_of('.') + 1);
      leaf = leaf.substr(0, leaf.find('['));
      if (path.rfind("materials.", 0) == 0 && path.find('.', 10) == std::string::npos) continue;
      const bool breakage_key =
          path.find(".breakage") != std::string::npos || path.rfind("breakage", 0) == 0;
      if (path.find('.') == std::string::npos) {  // a top-level table
        EXPECT_NE((breakage_key ? breakage_doc : case_doc).find("[" + leaf), std::string::npos)
            << name << ": " << path;
        continue;
      }
      if (breakage_key && (leaf == "breakage" || leaf == "progeny")) continue;  // sub-tables
      EXPECT_NE((breakage_key ? breakage_doc : case_doc).find("`" + leaf + "`"), std::string::npos)
          << name << ": " << path << " is not documented";
    }
  }
}
