// Every key the DEM case builder and the [output] reader accept in the examples is documented in
// docs/case-file.md (as `key` in a table row).
#include <gtest/gtest.h>

#include "case_docs_check.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "comminute/io/case/output_case.hpp"
#include "source_file.hpp"
#include "temp_dir.hpp"

using namespace comminute;

TEST(CaseDocs, EveryKeyOfTheDemExamplesIsDocumented) {
  const std::string doc = comminute::testing::read_source_file("docs/case-file.md");
  ASSERT_FALSE(doc.empty());
  const std::string src = COMMINUTE_SOURCE_DIR;
  // the ball mill writes its generated STL when built: a copy in a scratch folder does it there
  const comminute::testing::TestDir dir;
  std::filesystem::copy_file(src + "/examples/ball_mill/ball_mill.toml", dir / "ball_mill.toml");
  // so do the mixer's walls
  for (const char* m : {"mixer_6p25.toml", "mixer_9p5.toml", "mixer_13.toml"})
    std::filesystem::copy_file(src + "/examples/mixer/" + m, dir / m);
  for (const std::string& name :
       {src + "/examples/settle/settle.toml", src + "/examples/drum/rotating_drum.toml",
        src + "/examples/piston/confined_compression.toml",
        src + "/examples/machines/servo_compression.toml",
        src + "/examples/machines/discharge.toml", src + "/examples/periodic/drum_slice.toml",
        src + "/examples/mesh_drum/mesh_drum.toml", (dir / "ball_mill.toml").string(),
        (dir / "mixer_6p25.toml").string(), (dir / "mixer_9p5.toml").string(),
        (dir / "mixer_13.toml").string()}) {
    CaseFile f = CaseFile::load(name);
    io::build_dem_case(f.root());
    if (auto o = f.root().optional_table("output")) io::read_output_options(*o);
    f.reject_unknown();
    comminute::testing::expect_used_keys_documented(f, doc);
  }
}
