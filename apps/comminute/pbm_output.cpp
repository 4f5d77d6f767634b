#include "pbm_output.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>
#include <cstdlib>

#include "comminute/core/csv_table.hpp"

namespace comminute::app {

analysis::SizeDistribution distribution(const pbm::Problem& p, const Eigen::VectorXd& number) {
  const auto& g = p.grid;
  std::vector<double> edges, vol, n;
  for (std::size_t i = 0; i <= g.classes(); ++i) edges.push_back(g.size_edge(i));
  for (std::size_t i = 0; i < g.classes(); ++i) {
    vol.push_back(g.pivot_volume(i));
    n.push_back(number[static_cast<Eigen::Index>(i)]);
  }
  return analysis::SizeDistribution(edges, vol, n, p.density);
}

void write_distributions(const std::filesystem::path& file, const pbm::Problem& p,
                         const std::vector<double>& times,
                         const std::vector<Eigen::VectorXd>& number) {
  using analysis::Basis;
  Table t("distributions", {{"time", "s"},
                            {"class", "-"},
                            {"size_lower", "m"},
                            {"size_upper", "m"},
                            {"size_pivot", "m"},
                            {"volume_pivot", "m^3"},
                            {"number", "-"},
                            {"mass", "kg"},
                            {"number_fraction", "-"},
                            {"volume_fraction", "-"},
                            {"mass_fraction", "-"},
                            {"number_density", "1/m"},
                            {"volume_density", "1/m"},
                            {"mass_density", "1/m"},
                            {"cumulative_number", "-"},
                            {"cumulative_volume", "-"},
                            {"cumulative_mass", "-"}});
  for (std::size_t k = 0; k < times.size(); ++k) {
    const auto d = distribution(p, number[k]);
    const auto mass = d.amounts(Basis::mass);
    const Basis bases[] = {Basis::number, Basis::volume, Basis::mass};
    std::vector<std::vector<double>> frac, dens, cum;
    for (Basis b : bases) {
      frac.push_back(d.fractions(b));
      dens.push_back(d.density(b));
      cum.push_back(d.cumulative(b));
    }
    for (std::size_t i = 0; i < d.classes(); ++i) {
      std::vector<Cell> row = {times[k],
                               i,
                               p.grid.size_edge(i),
                               p.grid.size_edge(i + 1),
                               p.grid.pivot_size(i),
                               p.grid.pivot_volume(i),
                               number[k][static_cast<Eigen::Index>(i)],
                               mass[i]};
      for (const auto* v : {&frac, &dens, &cum})
        for (const auto& col : *v) row.emplace_back(col[i]);
      t.add_row(row);
    }
  }
  t.write_file(file);
}

void write_models(const std::filesystem::path& dir, const pbm::Problem& p, const pbm::Solution& s) {
  const auto& g = p.grid;
  {
    Table rates("rates", {{"class", "-"}, {"size", "m"}, {"rate", "1/s"}});
    for (std::size_t i = 0; i < g.classes(); ++i) rates.add_row({i, s.rate_sizes[i], s.rates[i]});
    rates.write(dir);
  }
  Table b("breakage_function",
          {{"parent_size", "m"}, {"size_ratio", "-"}, {"cumulative_mass_passing", "-"}});
  const std::size_t n = g.classes();
  std::size_t dominant = 0;  // UFRJ: progeny at the energy class carrying most collision energy
  if (p.mill) {
    const auto& sp = p.mill_spectrum;
    for (std::size_t k = 1; k < sp.energy.size(); ++k)
      if (sp.energy[k] * sp.frequency[k] > sp.energy[dominant] * sp.frequency[dominant])
        dominant = k;
  }
  for (std::size_t k : {n - 1, n / 2, n / 4}) {
    const double y = g.pivot_volume(k);
    for (int j = 0; j <= 120; ++j) {
      const double r = std::pow(10.0, -4.0 + 4.0 * j / 120.0);  // d/D from 1e-4 to 1
      const double cum = p.mill ? p.mill->progeny(k, dominant).passing(r)
                                : p.function->cumulative_mass(y * r * r * r, y);
      b.add_row({g.pivot_size(k), r, cum});
    }
  }
  b.write(dir);
  if (s.median_fracture_energy.empty()) return;
  Table fe(
      "fracture_energy",
      {{"time", "s"}, {"class", "-"}, {"size_pivot", "m"}, {"median_fracture_energy", "J/kg"}});
  for (std::size_t t = 0; t < s.times.size(); ++t)
    for (std::size_t i = 0; i < n; ++i)
      fe.add_row({s.times[t], i, g.pivot_size(i),
                  s.median_fracture_energy[t][static_cast<Eigen::Index>(i)]});
  fe.write(dir);
  if (s.fracture_energy.empty() || s.fracture_energy.front().mass.size() == 0) return;
  // The whole distribution per class and time (UFRJ eq. U4), not only its median.
  Table fd("fracture_energy_distribution", {{"time", "s"},
                                            {"class", "-"},
                                            {"size_pivot", "m"},
                                            {"bin", "-"},
                                            {"energy_lower", "J/kg"},
                                            {"energy_upper", "J/kg"},
                                            {"mass", "kg"},
                                            {"fraction", "-"},
                                            {"cumulative_fraction", "-"}});
  for (std::size_t t = 0; t < s.times.size(); ++t) {
    const auto& bins = s.fracture_energy[t];
    for (Eigen::Index i = 0; i < bins.mass.cols(); ++i) {
      const double total = bins.mass.col(i).sum();
      double below = 0;
      for (Eigen::Index j = 0; j < bins.mass.rows(); ++j) {
        below += bins.mass(j, i);
        fd.add_row({s.times[t], static_cast<std::size_t>(i),
                    g.pivot_size(static_cast<std::size_t>(i)), static_cast<std::size_t>(j),
                    bins.edges(j, i), bins.edges(j + 1, i), bins.mass(j, i),
                    total > 0 ? bins.mass(j, i) / total : 0.0, total > 0 ? below / total : 0.0});
      }
    }
  }
  fd.write(dir);
}

void plot(const std::string& kind, const std::filesystem::path& dir) {
  const char* env = std::getenv("COMMINUTE_PLOT_SCRIPT");
  const std::string script = env ? env : std::string(COMMINUTE_SOURCE_DIR) + "/scripts/plot_pbm.py";
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' {} '{}'", script, kind, dir.string());
  if (std::system(cmd.c_str()) != 0)
    fmt::print(stderr, "warning: plotting failed ({}); the CSV files are complete\n", cmd);
}

}  // namespace comminute::app
