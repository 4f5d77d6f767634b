// Time-series CSV: header with units, rows that read back to the same doubles, clean
// continuation after a restart.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "comminute/core/error.hpp"
#include "comminute/io/output/timeseries_csv.hpp"
#include "temp_dir.hpp"

using namespace comminute;

namespace {

class NoWall : public Wall {
 public:
  std::string type() const override { return "none"; }
  int contacts(const Vec3&, double, double, std::vector<WallContact>&) const override { return 0; }
  void advance(double) override {}
  void save(Archive&, const std::string&) const override {}
  void load(const Archive&, const std::string&) override {}
  SurfaceMesh surface(double) const override { return {}; }
};

std::vector<std::string> read_lines(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

std::vector<double> split(const std::string& line) {
  std::vector<double> v;
  std::stringstream s(line);
  for (std::string c; std::getline(s, c, ',');) v.push_back(std::stod(c));
  return v;
}

Observables sample(double t) {
  Observables o;
  o.time = t;
  o.step = static_cast<std::uint64_t>(t * 1e6);
  o.dt = 1e-6 / 3.0;
  o.particles = 1000;
  o.contacts = 2345;
  o.wall_contacts = 17;
  o.kinetic_translational = 0.1 * t + 1.0 / 3.0;
  o.kinetic_rotational = 1e-300;
  o.potential_gravity = -12.5;
  o.elastic = 2.0 / 7.0;
  o.ledger = {0.125, 0.25, 0.5, 1.0};
  return o;
}

struct Fixture {
  std::vector<std::unique_ptr<Wall>> walls;
  Fixture() {
    walls.push_back(std::make_unique<NoWall>());
    walls.push_back(std::make_unique<NoWall>());
    walls[0]->name = "floor";
    walls[1]->name = "piston";
    walls[1]->force = {0.1, -0.2, 1e5 / 3.0};
    walls[1]->torque = {0, 0, -7.25};
  }
  std::vector<std::string> names() const { return {"floor", "piston"}; }
};

}  // namespace

TEST(TimeSeriesCsv, HeaderNamesColumnsWithUnitsAndRowsReadBackExactly) {
  const comminute::testing::TestDir dir;
  Fixture fx;
  io::TimeSeriesWriter w(dir / "ts.csv", fx.names());
  w.start_fresh();
  w.append(sample(0.0), fx.walls);
  w.append(sample(1e-3), fx.walls);
  const auto lines = read_lines(dir / "ts.csv");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0],
            "time [s],step [-],time_step [s],particles [-],contacts [-],wall_contacts [-],"
            "kinetic_translational [J],kinetic_rotational [J],potential_gravity [J],elastic [J],"
            "dissipated_damping [J],dissipated_friction [J],energy_removed [J],wall_work [J],"
            "elastic_bonds [J],dissipated_bonds [J],energy_balance [J],floor_Fx [N],floor_Fy "
            "[N],floor_Fz [N],floor_Tx [N m],"
            "floor_Ty [N m],floor_Tz [N m],floor_P [W],piston_Fx [N],piston_Fy [N],piston_Fz [N],"
            "piston_Tx [N m],piston_Ty [N m],piston_Tz [N m],piston_P [W]");
  const auto v = split(lines[2]);
  ASSERT_EQ(v.size(), 31u);
  const Observables o = sample(1e-3);
  EXPECT_EQ(v[0], o.time);
  EXPECT_EQ(v[1], 1000);
  EXPECT_EQ(v[2], 1e-6 / 3.0);
  EXPECT_EQ(v[4], 2345);
  EXPECT_EQ(v[6], o.kinetic_translational);  // exact: shortest round-trip formatting
  EXPECT_EQ(v[7], 1e-300);
  EXPECT_EQ(v[9], 2.0 / 7.0);
  // balance = 1/3 + 1e-4 + 1e-300 - 12.5 + 2/7 + 0.125 + 0.25 + 0.5 - 1.0, summed in that order
  EXPECT_EQ(v[16], o.kinetic_translational + 1e-300 - 12.5 + 2.0 / 7.0 + 0.125 + 0.25 + 0.5 - 1.0);
  EXPECT_EQ(v[26], 1e5 / 3.0);
  EXPECT_EQ(v[29], -7.25);
  EXPECT_EQ(v[30], 0.0);  // the piston does not move: no power
}

TEST(TimeSeriesCsv, ResumeDropsRowsAfterCheckpointAndHalfLine) {
  const comminute::testing::TestDir dir;
  Fixture fx;
  {
    io::TimeSeriesWriter w(dir / "ts.csv", fx.names());
    w.start_fresh();
    for (int k = 0; k <= 5; ++k) w.append(sample(0.1 * k), fx.walls);
  }
  std::ofstream(dir / "ts.csv", std::ios::app) << "0.6,600000,10";  // killed mid-row
  io::TimeSeriesWriter again(dir / "ts.csv", fx.names());
  again.resume(0.1 * 3);  // checkpoint at the 4th row's time (same double)
  again.append(sample(0.35), fx.walls);
  const auto lines = read_lines(dir / "ts.csv");
  ASSERT_EQ(lines.size(), 6u);  // header, 0, 0.1, 0.2, 0.3, 0.35
  EXPECT_EQ(split(lines[4])[0], 0.1 * 3);
  EXPECT_EQ(split(lines[5])[0], 0.35);
  for (std::size_t k = 1; k < lines.size(); ++k) EXPECT_EQ(split(lines[k]).size(), 31u);
}

TEST(TimeSeriesCsv, ResumeRejectsAnotherCasesHeader) {
  const comminute::testing::TestDir dir;
  Fixture fx;
  io::TimeSeriesWriter w(dir / "ts.csv", {"floor"});
  w.start_fresh();
  io::TimeSeriesWriter other(dir / "ts.csv", fx.names());
  try {
    other.resume(1.0);
    FAIL() << "resumed a file with other columns";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("header"), std::string::npos) << e.what();
  }
}

TEST(TimeSeriesCsv, ResumeWithoutFileStartsFresh) {
  const comminute::testing::TestDir dir;
  Fixture fx;
  io::TimeSeriesWriter w(dir / "ts.csv", fx.names());
  w.resume(2.0);
  w.append(sample(2.5), fx.walls);
  EXPECT_EQ(read_lines(dir / "ts.csv").size(), 2u);
}

TEST(TimeSeriesCsv, BadWallNamesAreRejected) {
  const comminute::testing::TestDir dir;
  EXPECT_THROW(io::TimeSeriesWriter(dir / "a.csv", {"a,b"}), Error);
  EXPECT_THROW(io::TimeSeriesWriter(dir / "a.csv", {""}), Error);
  EXPECT_THROW(io::TimeSeriesWriter(dir / "a.csv", {"x", "x"}), Error);
}
