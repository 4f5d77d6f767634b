#pragma once
// Output of `comminute pbm` and `comminute calibrate`: CSV files with unit headers, written
// atomically, and the PNG plots made by scripts/plot_pbm.py.
#include <Eigen/Dense>
#include <filesystem>
#include <string>
#include <vector>

#include "comminute/analysis/size_distribution.hpp"
#include "comminute/pbm/problem.hpp"

namespace comminute::app {

analysis::SizeDistribution distribution(const pbm::Problem& p, const Eigen::VectorXd& number);

// distributions.csv: one row per (time, class), every basis in fraction, density and cumulative.
void write_distributions(const std::filesystem::path& file, const pbm::Problem& p,
                         const std::vector<double>& times,
                         const std::vector<Eigen::VectorXd>& number);
// rates.csv (S per class) and breakage_function.csv (B against d/D for a few parents).
void write_models(const std::filesystem::path& dir, const pbm::Problem& p, const pbm::Solution& s);
// Runs `/usr/bin/python3 scripts/plot_pbm.py <kind> <dir>`; warns (never throws) on failure.
void plot(const std::string& kind, const std::filesystem::path& dir);

}  // namespace comminute::app
