// The breakage module's tables through the output module: `name [unit]` headers, a sample at the
// start and always one at the run's end time, and the ledger agreeing with the time series.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <fstream>
#include <iterator>
#include <sstream>

#include "breakage_engine_fixture.hpp"
#include "comminute/analysis/size_distribution_observer.hpp"
#include "comminute/io/output/output_module.hpp"
#include "comminute/run/run_loop.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string c; std::getline(s, c, ',');) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  const auto it = std::find(header.begin(), header.end(), name);
  EXPECT_NE(it, header.end()) << name;
  return static_cast<std::size_t>(it - header.begin());
}

}  // namespace

TEST(BreakageOutputs, TablesHaveUnitsAndAFinalRowAtTheEndTime) {
  const TestDir dir;
  auto sim = box_gas(0.0, 17);
  sim->walls.back()->name = "box";
  std::vector<std::optional<breakage::MaterialBreakage>> mats;
  mats.emplace_back(weak_material(0.02, 0.3, 0.0008, 0.45, breakage::FinesRule::mass, 0.5));
  auto mod =
      std::make_unique<breakage::BreakageModule>(std::move(mats), breakage::BreakageOptions{});
  breakage::BreakageModule& b = *mod;
  sim->modules.push_back(std::move(mod));
  sim->modules.push_back(
      std::make_unique<analysis::SizeDistributionObserver>(&b, analysis::SieveOptions{}, 0.0));
  sim->dt = 0.2 * 3.1416 * 0.00018 * std::sqrt(2500 / (5e7 / 2.6)) / (0.1631 * 0.3 + 0.8766);
  const double end_time = 1500.5 * sim->dt;  // 1501 steps: not a multiple of 1000 (nor 2000)
  io::OutputOptions o;
  o.directory = dir.path();
  o.particles = false;
  o.timeseries_cadence.steps = 100;
  auto out = std::make_unique<io::OutputModule>(o, end_time);
  io::OutputModule& output = *out;
  sim->modules.push_back(std::move(out));
  sim->setup();
  ASSERT_EQ(run::run_until(*sim, end_time, &output, nullptr, nullptr), 0);
  ASSERT_EQ(sim->step_count, 1501u);
  ASSERT_GT(b.breakages(), 0u);
  const std::string end = fmt::format("{}", sim->time);

  // Ledger: the start, step 1000 and the end time.
  const auto ledger = read_csv(dir / "breakage_ledger.csv");
  ASSERT_EQ(ledger.size(), 4u);
  EXPECT_EQ(ledger[0][0], "time [s]");
  EXPECT_EQ(ledger[1][0], "0");
  EXPECT_EQ(ledger[3][0], end);
  EXPECT_EQ(ledger[3][column(ledger[0], "breakages [-]")], std::to_string(b.breakages()));
  // The same energy as the time series' last row, to the last digit.
  const auto ts = read_csv(dir / "timeseries.csv");
  EXPECT_EQ(ts.back()[0], end);
  EXPECT_EQ(ledger[3][column(ledger[0], "removed_energy_total [J]")],
            ts.back()[column(ts[0], "energy_removed [J]")]);

  // Size distribution: the start and the end time (its default is every 2000 steps).
  const auto psd = read_csv(dir / "size_distribution.csv");
  ASSERT_GT(psd.size(), 2u);
  EXPECT_EQ(psd[0][2], "sieve [m]");
  EXPECT_EQ(psd[1][0], "0");
  EXPECT_EQ(psd.back()[0], end);

  // Events: one row per logged event.
  const auto events = read_csv(dir / "breakage_events.csv");
  EXPECT_EQ(events.size(), b.log().size() + 1);
  EXPECT_EQ(events[0][column(events[0], "specific_energy [J/kg]")], "specific_energy [J/kg]");
  EXPECT_FALSE(read_csv(dir / "breakage_model.csv").empty());
  EXPECT_FALSE(std::filesystem::exists(dir / "breakage_events.csv.part"));
}
