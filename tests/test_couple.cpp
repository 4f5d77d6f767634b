// The [couple] table and the checks of `comminute couple` (run/couple.hpp): defaults and refusals
// of its keys, the pbm case deferred only for the files the DEM stage has yet to write, and the
// link check (the pbm case must read this DEM run's outputs, not stale files). The chain itself,
// its determinism and its equality with the two stages run by hand: tests/scripts/
// test_couple_cli.sh.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <regex>
#include <sstream>

#include "case_docs_check.hpp"
#include "comminute/core/error.hpp"
#include "comminute/run/couple.hpp"
#include "source_file.hpp"
#include "temp_dir.hpp"

namespace comminute {
namespace {

void write(const std::filesystem::path& p, const std::string& text) {
  std::filesystem::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The UFRJ example fed by the DEM, its spectrum file and output folder moved.
std::string ufrj_case(const std::string& spectrum, const std::string& output) {
  std::string t = read(std::filesystem::path(COMMINUTE_EXAMPLES) / "ball_mill/ufrj_from_dem.toml");
  t = std::regex_replace(t, std::regex("\nspectrum_file = [^\n]*"),
                         "\nspectrum_file = \"" + spectrum + "\"");
  t = std::regex_replace(t, std::regex("\ndirectory = [^\n]*"), "\ndirectory = \"" + output + "\"");
  return t;
}

std::string key_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.key();
  }
  return "(no error)";
}

TEST(Couple, ReadsItsTableWithDefaults) {
  testing::TestDir dir;
  write(dir / "dem.toml", "");
  write(dir / "pbm.toml", "");
  write(dir / "couple.toml", "[couple]\ndem = \"dem.toml\"\npbm = \"pbm.toml\"\n");
  const auto cf = CaseFile::load(dir / "couple.toml");
  const run::CoupleCase c = run::read_couple_case(cf.root());
  cf.reject_unknown();
  EXPECT_EQ(c.dem, dir / "dem.toml");
  EXPECT_EQ(c.pbm, dir / "pbm.toml");
  EXPECT_EQ(c.directory, dir / "output" / "couple");
  EXPECT_EQ(c.threads, 1);  // one thread: a chain that gives the same files every time
  EXPECT_FALSE(c.window.has_value());
  EXPECT_TRUE(c.plots);
}

TEST(Couple, RefusesBadKeysNamingThem) {
  testing::TestDir dir;
  write(dir / "dem.toml", "");
  write(dir / "pbm.toml", "");
  const std::string head = "[couple]\ndem = \"dem.toml\"\npbm = \"pbm.toml\"\n";
  auto key = [&](const std::string& extra) {
    write(dir / "c.toml", head + extra);
    return key_of([&] {
      const auto cf = CaseFile::load(dir / "c.toml");
      run::read_couple_case(cf.root());
      cf.reject_unknown();
    });
  };
  EXPECT_EQ(key("threads = 0\n"), "couple.threads");
  EXPECT_EQ(key("window = 0.0\n"), "couple.window");
  EXPECT_EQ(key("windw = 1.0\n"), "couple.windw");
  EXPECT_EQ(key("plots = 1\n"), "couple.plots");
  write(dir / "c.toml", "[couple]\ndem = \"none.toml\"\npbm = \"pbm.toml\"\n");
  EXPECT_EQ(key_of([&] { run::read_couple_case(CaseFile::load(dir / "c.toml").root()); }),
            "couple.dem");
}

TEST(Couple, PbmCaseWaitsOnlyForFilesTheDemStageWrites) {
  testing::TestDir dir;
  const auto dem = dir / "dem_out";
  // the spectrum is in the DEM folder and not written yet: checked after the DEM stage
  write(dir / "pbm.toml", ufrj_case("dem_out/collision_spectrum_ball-ball.csv", "pbm_out"));
  EXPECT_FALSE(run::read_pbm_case(dir / "pbm.toml", dem, true).has_value());
  EXPECT_EQ(key_of([&] { run::read_pbm_case(dir / "pbm.toml", dem, false); }),
            "mill.spectrum_file");
  // a missing file elsewhere is an error at once
  write(dir / "pbm2.toml", ufrj_case("elsewhere/spectrum.csv", "pbm_out"));
  EXPECT_EQ(key_of([&] { run::read_pbm_case(dir / "pbm2.toml", dem, true); }),
            "mill.spectrum_file");
  // so is a typo of the case once its files exist
  const std::string spectrum =
      read(std::filesystem::path(COMMINUTE_EXAMPLES) / "pbm/ball_mill_spectrum.csv");
  write(dem / "collision_spectrum_ball-ball.csv", spectrum);
  write(dir / "pbm3.toml", ufrj_case("dem_out/collision_spectrum_ball-ball.csv", "pbm_out") +
                               "\n[mill2]\nholdup = 1.0\n");
  EXPECT_EQ(key_of([&] { run::read_pbm_case(dir / "pbm3.toml", dem, true); }).rfind("mill2", 0),
            0u);
  const auto p = run::read_pbm_case(dir / "pbm.toml", dem, true);
  ASSERT_TRUE(p.has_value());
  EXPECT_FALSE(p->calibrates);
}

TEST(Couple, PbmCaseMustReadThisDemRun) {
  testing::TestDir dir;
  const auto dem = dir / "dem_out";
  const std::string spectrum =
      read(std::filesystem::path(COMMINUTE_EXAMPLES) / "pbm/ball_mill_spectrum.csv");
  write(dem / "collision_spectrum_ball-ball.csv", spectrum);
  write(dir / "dem.toml", "");
  // its output folder inside the DEM's is an output, not a link
  write(dir / "pbm.toml", ufrj_case("dem_out/collision_spectrum_ball-ball.csv", "dem_out/ufrj"));
  write(dir / "couple.toml", "[couple]\ndem = \"dem.toml\"\npbm = \"pbm.toml\"\n");
  const auto cf = CaseFile::load(dir / "couple.toml");
  const run::CoupleCase c = run::read_couple_case(cf.root());
  const auto p = run::read_pbm_case(dir / "pbm.toml", dem, false);
  ASSERT_TRUE(p.has_value());
  const auto links = run::dem_inputs(p->file, dem);
  ASSERT_EQ(links.size(), 1u);
  EXPECT_EQ(links[0].first, "mill.spectrum_file");

  // a spectrum older than the DEM stage's start is a stale file of an earlier run
  const auto marker = dir / "marker";
  write(marker, "");
  const auto started = std::filesystem::last_write_time(marker);
  std::filesystem::last_write_time(dem / "collision_spectrum_ball-ball.csv",
                                   started - std::chrono::seconds(10));
  EXPECT_EQ(key_of([&] { run::check_pbm_reads_dem(c, p->file, dem, marker); }),
            "mill.spectrum_file");
  std::filesystem::last_write_time(dem / "collision_spectrum_ball-ball.csv",
                                   started + std::chrono::seconds(1));
  EXPECT_NO_THROW(run::check_pbm_reads_dem(c, p->file, dem, marker));

  // a pbm case that reads nothing of the DEM folder is refused on couple.pbm
  write(dir / "elsewhere/spectrum.csv", spectrum);
  write(dir / "pbm2.toml", ufrj_case("elsewhere/spectrum.csv", "pbm_out"));
  const auto p2 = run::read_pbm_case(dir / "pbm2.toml", dem, false);
  EXPECT_EQ(key_of([&] { run::check_pbm_reads_dem(c, p2->file, dem, marker); }), "couple.pbm");
}

TEST(Couple, ExampleReadsAndItsKeysAreDocumented) {
  const auto ex = std::filesystem::path(COMMINUTE_EXAMPLES) / "ball_mill";
  const auto cf = CaseFile::load(ex / "couple.toml");
  const run::CoupleCase c = run::read_couple_case(cf.root());
  cf.reject_unknown();
  testing::expect_used_keys_documented(cf, testing::read_source_file("docs/case-file.md"));
  EXPECT_EQ(c.dem, ex / "ball_mill.toml");
  // valid up to the spectrum the DEM stage writes (read whole when a run left it there)
  EXPECT_NO_THROW(run::read_pbm_case(c.pbm, ex / "output", true));
}

TEST(Couple, SummaryTableNamesTheLinks) {
  run::CoupleSummary s;
  s.dem_end_time = 0.4;
  s.window_start = 0.2;
  s.window_length = 0.2;
  s.links = {{"mill.spectrum_file", "/x/dem_out/collision_spectrum_ball-ball.csv"}};
  const Table t = run::couple_table(s);
  EXPECT_EQ(t.rows(), 5u);
}

}  // namespace
}  // namespace comminute
