// Population balance benchmarks (issue 4): 200 size classes integrated to 120 s with the adaptive
// integrator, and a 15-start calibration of 6 parameters against one measured distribution.
//   build/bench/bench_pbm --benchmark_filter=. (see bench/RESULTS.md, "Population balance")
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "comminute/calibrate/multistart.hpp"
#include "comminute/io/case/calibration_case.hpp"
#include "comminute/pbm/method_of_classes.hpp"
#include "comminute/pbm/power_law_rate.hpp"
#include "comminute/pbm/product_function.hpp"
#include "comminute/pbm/solve.hpp"

using namespace comminute;

namespace {

// 200 log-spaced classes 1 µm – 2 mm; S = 0.5 (d/1 mm)^1.2 1/s (carbon-black-like magnitudes);
// brittle carbon black product function q = 3.8, ν = 27.6; lognormal-ish feed at 600 µm.
struct Case200 {
  pbm::SizeGrid grid =
      pbm::SizeGrid::logarithmic(1e-6, 2e-3, 200, pbm::GridCoordinate::size, 0.5235987755982988);
  pbm::PowerLawRate rate{{0.5, 1.2, pbm::GridCoordinate::size, 1e-3, std::nullopt, 2.0}};
  pbm::ProductFunction function{3.8, 27.6};
  Eigen::VectorXd n0() const {
    Eigen::VectorXd n(200);
    for (Eigen::Index i = 0; i < 200; ++i) {
      const double l = std::log(grid.pivot_size(static_cast<std::size_t>(i)) / 6e-4) / 0.3;
      n[i] = std::exp(-0.5 * l * l) / grid.pivot_volume(static_cast<std::size_t>(i));
    }
    return n;
  }
};

void BM_Pbm200Classes_Build(benchmark::State& st) {
  const Case200 c;
  for (auto _ : st) {
    pbm::MethodOfClasses moc(c.grid, c.rate, c.function, true);
    benchmark::DoNotOptimize(moc.birth_matrix().data());
  }
}
BENCHMARK(BM_Pbm200Classes_Build)->Unit(benchmark::kMillisecond);

void BM_Pbm200Classes_Adaptive120s(benchmark::State& st) {
  const Case200 c;
  const pbm::MethodOfClasses moc(c.grid, c.rate, c.function, true);
  const auto sys = moc.system();
  const Eigen::VectorXd n0 = c.n0();
  std::size_t steps = 0;
  for (auto _ : st) {
    pbm::DormandPrince dp({1e-6, 1e-12, 1000000});
    auto sol = pbm::solve(sys, dp, n0, {120.0});
    benchmark::DoNotOptimize(sol.back().data());
    steps = dp.stats().steps;
  }
  st.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(BM_Pbm200Classes_Adaptive120s)->Unit(benchmark::kMillisecond);

// For comparison: the carbon-black study's fixed RK4 step Δt = 0.1 s (1200 steps).
void BM_Pbm200Classes_Rk4Step0p1To120s(benchmark::State& st) {
  const Case200 c;
  const pbm::MethodOfClasses moc(c.grid, c.rate, c.function, true);
  const auto sys = moc.system();
  const Eigen::VectorXd n0 = c.n0();
  for (auto _ : st) {
    pbm::Rk4 rk4(0.1);
    auto sol = pbm::solve(sys, rk4, n0, {120.0});
    benchmark::DoNotOptimize(sol.back().data());
  }
}
BENCHMARK(BM_Pbm200Classes_Rk4Step0p1To120s)->Unit(benchmark::kMillisecond);

void BM_Pbm200Classes_BuildAndAdaptive120s(benchmark::State& st) {
  const Case200 c;
  const Eigen::VectorXd n0 = c.n0();
  for (auto _ : st) {
    const pbm::MethodOfClasses moc(c.grid, c.rate, c.function, true);
    pbm::DormandPrince dp({1e-6, 1e-12, 1000000});
    auto sol = pbm::solve(moc.system(), dp, n0, {120.0});
    benchmark::DoNotOptimize(sol.back().data());
  }
}
BENCHMARK(BM_Pbm200Classes_BuildAndAdaptive120s)->Unit(benchmark::kMillisecond);

// The example calibration (examples/pbm/calibrate_carbon_black.toml: 6 parameters, 15 starts)
// against one measured distribution — its 60 s data set only (the 10 s entry is dropped in a
// temporary copy); threads as OpenMP decides (OMP_NUM_THREADS).
void BM_Calibration15Starts6Parameters(benchmark::State& st) {
  const auto dir = std::filesystem::path(COMMINUTE_SOURCE_DIR) / "examples/pbm";
  std::ifstream in(dir / "calibrate_carbon_black.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto first = text.find("[[calibration.data]]");
  text.erase(first, text.find("[[calibration.data]]", first + 1) - first);
  for (const std::string f : {"mixer_contact_frequency.csv", "measured_60s.csv"})
    text.replace(text.find('"' + f + '"'), f.size() + 2, '"' + (dir / f).string() + '"');
  const auto path = std::filesystem::temp_directory_path() / "comminute_bench_calibration.toml";
  std::ofstream(path) << text;
  const auto cc = io::read_calibration(CaseFile::load(path));
  double best = 0, evals = 0;
  for (auto _ : st) {
    const auto r = calibrate::multistart(cc.space, cc.objective, cc.options);
    best = r.starts[r.best].f;
    evals = 0;
    for (const auto& s : r.starts) evals += static_cast<double>(s.run.evaluations);
  }
  st.counters["best_error"] = best;
  st.counters["evaluations"] = evals;
}
BENCHMARK(BM_Calibration15Starts6Parameters)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
