// The one CSV seam: `name [unit]` headers, cells that read back to the same doubles, whole
// tables written atomically, and row-by-row series.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <fstream>
#include <iterator>
#include <sstream>

#include "comminute/core/csv_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/core/series_writer.hpp"
#include "temp_dir.hpp"

using namespace comminute;

namespace {
std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
}  // namespace

TEST(CsvTable, HeaderHasUnitsAndCellsReadBackExactly) {
  const comminute::testing::TestDir dir;
  Table t("example", {{"time", "s"}, {"count", "-"}, {"energy", "J/kg"}, {"name", "-"}});
  const double third = 1.0 / 3.0, tiny = 1e-300;
  t.add_row({third, std::uint64_t{18446744073709551615u}, tiny, "ore"});
  t.add_row({0.1, -3, 2.0 / 7.0, std::string("gangue")});
  t.write(dir.path());
  EXPECT_FALSE(std::filesystem::exists(dir / "example.csv.part"));
  std::istringstream in(slurp(dir / "example.csv"));
  std::string header, row1, row2;
  std::getline(in, header);
  std::getline(in, row1);
  std::getline(in, row2);
  EXPECT_EQ(header, "time [s],count [-],energy [J/kg],name [-]");
  EXPECT_EQ(row1.substr(row1.rfind(',') + 1), "ore");
  EXPECT_EQ(std::stod(row1.substr(0, row1.find(','))), third);  // full precision
  EXPECT_EQ(row2, fmt::format("0.1,-3,{},gangue", 2.0 / 7.0));
  EXPECT_NE(row1.find(",18446744073709551615,1e-300,"), std::string::npos) << row1;
}

TEST(CsvTable, RejectsWhatWouldBreakTheFile) {
  EXPECT_THROW(Table("t", {{"a,b", "m"}}), Error);
  EXPECT_THROW(Table("t", {{"a", ""}}), Error);
  EXPECT_THROW(Table("t", {{"a", "[m]"}}), Error);
  EXPECT_THROW(Cell(std::string("x\ny")), Error);
  Table t("t", {{"a", "m"}, {"b", "m"}});
  EXPECT_THROW(t.add_row({1.0}), Error);
}

TEST(CsvTable, RewriteReplacesTheWholeFile) {
  const comminute::testing::TestDir dir;
  Table t("t", {{"a", "-"}});
  for (int k = 0; k < 5; ++k) t.add_row({k});
  t.write(dir.path());
  Table shorter("t", {{"a", "-"}});
  shorter.add_row({7});
  shorter.write(dir.path());
  EXPECT_EQ(slurp(dir / "t.csv"), "a [-]\n7\n");
}

TEST(SeriesWriter, AppendsRowsAndResumesAtATime) {
  const comminute::testing::TestDir dir;
  {
    SeriesWriter w(dir / "s.csv", {{"time", "s"}, {"x", "m"}});
    w.start_fresh();
    for (int k = 0; k < 4; ++k) w.append({0.25 * k, 1.0 / (k + 1)});
    EXPECT_THROW(w.append({1.0}), Error);
  }
  std::ofstream(dir / "s.csv", std::ios::app) << "1.0,0.";  // killed mid-row
  SeriesWriter again(dir / "s.csv", {{"time", "s"}, {"x", "m"}});
  again.resume(0.5);
  again.append({0.6, 2.0});
  EXPECT_EQ(slurp(dir / "s.csv"),
            fmt::format("time [s],x [m]\n0,1\n0.25,0.5\n0.5,{}\n0.6,2\n", 1.0 / 3.0));
  SeriesWriter other(dir / "s.csv", {{"time", "s"}, {"y", "m"}});
  EXPECT_THROW(other.resume(0.5), Error);
}
