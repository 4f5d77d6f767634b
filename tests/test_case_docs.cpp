// Every key the DEM case builder and the [output] reader accept in the examples is documented in
// docs/case-file.md (as `key` in a table row).
#include <gtest/gtest.h>

#include "comminute/io/case/dem_case.hpp"
#include "comminute/io/case/output_case.hpp"
#include "source_file.hpp"

using namespace comminute;

TEST(CaseDocs, EveryKeyOfTheDemExamplesIsDocumented) {
  const std::string doc = comminute::testing::read_source_file("docs/case-file.md");
  ASSERT_FALSE(doc.empty());
  for (const char* name :
       {"/examples/settle/settle.toml", "/examples/drum/rotating_drum.toml",
        "/examples/piston/confined_compression.toml", "/examples/machines/servo_compression.toml",
        "/examples/machines/discharge.toml", "/examples/periodic/drum_slice.toml"}) {
    CaseFile f = CaseFile::load(std::string(COMMINUTE_SOURCE_DIR) + name);
    io::build_dem_case(f.root());
    if (auto o = f.root().optional_table("output")) io::read_output_options(*o);
    f.reject_unknown();
    for (const std::string& path : f.used_keys()) {
      std::string leaf = path.substr(path.find_last_of('.') + 1);
      leaf = leaf.substr(0, leaf.find('['));
      if (path.rfind("materials.", 0) == 0 && path.find('.', 10) == std::string::npos) continue;
      if (path.find('.') == std::string::npos) {  // a top-level table: documented as a heading
        EXPECT_NE(doc.find("[" + leaf), std::string::npos)
            << path << " is not in docs/case-file.md";
        continue;
      }
      EXPECT_NE(doc.find("`" + leaf + "`"), std::string::npos)
          << path << " is not in docs/case-file.md";
    }
  }
}
