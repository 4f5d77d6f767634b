// Every key the breakage examples use is documented: breakage keys in docs/breakage.md, the
// others in docs/case-file.md (as `key`); and each example builds without unknown keys.
#include <gtest/gtest.h>

#include "comminute/io/case/breakage_case.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "comminute/io/case/output_case.hpp"
#include "source_file.hpp"

using namespace comminute;
using comminute::testing::read_source_file;

TEST(BreakageDocs, EveryKeyOfTheBreakageExamplesIsDocumented) {
  const std::string breakage_doc = read_source_file("docs/breakage.md"),
                    case_doc = read_source_file("docs/case-file.md");
  ASSERT_FALSE(breakage_doc.empty());
  ASSERT_FALSE(case_doc.empty());
  for (const char* name : {"drop_weight", "slow_compression", "bed_impact", "repeated_impacts"}) {
    CaseFile f =
        CaseFile::load(std::string(COMMINUTE_SOURCE_DIR) + "/examples/breakage/" + name + ".toml");
    io::DemCase dem = io::build_dem_case(f.root());
    ASSERT_NE(io::add_breakage(f.root(), dem), nullptr) << name;
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
