// Case file → pbm::Problem: grids in either coordinate, initial distributions in any basis.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>

#include "comminute/core/error.hpp"
#include "comminute/io/case/pbm_case.hpp"

using namespace comminute;

namespace {
const char* rest = R"(
[rate]
model = "power_law"
variable = "volume"
k = 1e9
alpha = 1.0
[breakage]
function = "diemer_olson"
q = 1.0
nu = 2.0
)";

pbm::Problem problem(const std::string& text, const std::string& name = "case.toml") {
  // one folder per test: ctest runs the tests of this file as parallel processes, which must not
  // rewrite each other's feed table while it is read
  const auto dir = std::filesystem::temp_directory_path() /
                   ("comminute_pbm_case_" +
                    std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "feed.csv") << "size_m,cumulative_passing\n1e-4,0.1\n2e-4,0.3\n4e-4,1.0\n";
  std::ofstream(dir / name) << text << rest;
  const auto f = CaseFile::load(dir / name);
  auto p = io::read_pbm_problem(f.root());
  f.reject_unknown();
  return p;
}
}  // namespace

TEST(PbmCase, VolumeGridAndNumberBasis) {
  // Logarithmic in volume: edges 1e−15 … 1e−9 m³ in 6 classes (one decade each); 1000 particles
  // of the class holding d = 2e−4 m (v = π/6·8e−12 = 4.19e−12 m³, class [1e−12, 1e−11)).
  const auto p = problem(R"(
[grid]
spacing = "logarithmic"
coordinate = "volume"
min = 1e-15
max = 1e-9
classes = 6
[initial]
basis = "number"
total = 1000
kind = "monodisperse"
size = 2e-4
[solver]
times = [0, 1]
)");
  EXPECT_NEAR(p.grid.volume_edge(3), 1e-12, 1e-24);
  EXPECT_DOUBLE_EQ(p.initial_number[3], 1000.0);
  EXPECT_DOUBLE_EQ(p.initial_number.sum(), 1000.0);
}

TEST(PbmCase, TableFeedInMassBasis) {
  // Feed passing 10 % at 100 µm, 30 % at 200 µm, 100 % at 400 µm on edges 25, 50, 100, 200,
  // 400 µm: the finest class takes everything below 50 µm, P(50 µm) = 0.1·0.5^s from the
  // power-law tail through the first two points (s = ln 3/ln 2); the rest are differences.
  const auto p = problem(R"(
[material]
density = 2000.0
[grid]
spacing = "edges"
edges = [2.5e-5, 5e-5, 1e-4, 2e-4, 4e-4]
[initial]
basis = "mass"
total = 2.0
kind = "table"
file = "feed.csv"
[solver]
times = [0, 1]
)");
  std::vector<double> mass;
  for (std::size_t i = 0; i < 4; ++i)
    mass.push_back(p.initial_number[static_cast<Eigen::Index>(i)] * 2000 * p.grid.pivot_volume(i));
  const double slope = std::log(0.3 / 0.1) / std::log(2.0);  // tail below the first sieve
  EXPECT_NEAR(mass[0], 2.0 * 0.1 * std::pow(0.5, slope), 1e-12);
  EXPECT_NEAR(mass[1], 2.0 * (0.1 - 0.1 * std::pow(0.5, slope)), 1e-12);
  EXPECT_NEAR(mass[2], 2.0 * 0.2, 1e-12);
  EXPECT_NEAR(mass[3], 2.0 * 0.7, 1e-12);
}

TEST(PbmCase, KumarSwitchOnlyForTheMethodOfClasses) {
  try {
    problem(R"(
[grid]
spacing = "geometric"
top = 1e-3
classes = 5
[initial]
kind = "monodisperse"
size = 9e-4
[solver]
method = "batch_grinding"
kumar_correction = false
)",
            "k.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "solver.kumar_correction");
  }
}

TEST(PbmCase, RenamedKeysNameTheirNewKey) {
  const std::string head = R"(
[solver]
times = [1.0]
[initial]
sigma = 0.3
median = 5e-4
kind = "lognormal"
[grid]
classes = 4
max = 1e-3
min = 1e-4
spacing = "logarithmic"
[rate]
model = "power_law"
variable = "size"
k = 1.0
alpha = 1.0
[breakage]
function = "t10"
A = 50
alpha = [1, 1, 1, 1, 1]
beta = [1, 1, 1, 1, 1]
energy = 100
)";
  for (const auto& [keys, old_key, new_key] :
       {std::tuple{"b = 1\ne_inf = 100\n", "b", "b_prime"},
        std::tuple{"b_prime = 1\ne50_inf = 100\n", "e50_inf", "e_inf"}}) {
    const auto f = CaseFile::parse(head + keys, "renamed.toml");
    try {
      io::read_pbm_problem(f.root());
      ADD_FAILURE() << old_key << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), std::string("breakage.") + old_key);
      EXPECT_NE(std::string(e.what()).find(std::string("use '") + new_key + "'"), std::string::npos)
          << e.what();
    }
  }
}
