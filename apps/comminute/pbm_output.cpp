#include "pbm_output.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "comminute/core/atomic_file.hpp"

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
  AtomicFile f(file);
  auto& o = f.stream();
  o << "time_s,class,size_lower_m,size_upper_m,size_pivot_m,volume_pivot_m3,number,mass_kg,"
       "number_fraction,volume_fraction,mass_fraction,"
       "number_density_1_per_m,volume_density_1_per_m,mass_density_1_per_m,"
       "cumulative_number,cumulative_volume,cumulative_mass\n";
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
      o << fmt::format("{:.9g},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}", times[k], i,
                       p.grid.size_edge(i), p.grid.size_edge(i + 1), p.grid.pivot_size(i),
                       p.grid.pivot_volume(i), number[k][static_cast<Eigen::Index>(i)], mass[i]);
      for (const auto* v : {&frac, &dens, &cum})
        for (const auto& col : *v) o << fmt::format(",{:.9g}", col[i]);
      o << "\n";
    }
  }
  f.commit();
}

void write_models(const std::filesystem::path& dir, const pbm::Problem& p, const pbm::Solution& s) {
  const auto& g = p.grid;
  {
    AtomicFile f(dir / "rates.csv");
    f.stream() << "class,size_m,rate_1_per_s\n";
    for (std::size_t i = 0; i < g.classes(); ++i)
      f.stream() << fmt::format("{},{:.9g},{:.9g}\n", i, s.rate_sizes[i], s.rates[i]);
    f.commit();
  }
  AtomicFile f(dir / "breakage_function.csv");
  f.stream() << "parent_size_m,size_ratio,cumulative_mass_passing\n";
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
      const double b = p.mill ? p.mill->progeny(k, dominant).passing(r)
                              : p.function->cumulative_mass(y * r * r * r, y);
      f.stream() << fmt::format("{:.9g},{:.9g},{:.9g}\n", g.pivot_size(k), r, b);
    }
  }
  f.commit();
  if (s.median_fracture_energy.empty()) return;
  AtomicFile fe(dir / "fracture_energy.csv");
  fe.stream() << "time_s,class,size_pivot_m,median_fracture_energy_J_per_kg\n";
  for (std::size_t t = 0; t < s.times.size(); ++t)
    for (std::size_t i = 0; i < n; ++i)
      fe.stream() << fmt::format("{:.9g},{},{:.9g},{:.9g}\n", s.times[t], i, g.pivot_size(i),
                                 s.median_fracture_energy[t][static_cast<Eigen::Index>(i)]);
  fe.commit();
}

void plot(const std::string& kind, const std::filesystem::path& dir) {
  const char* env = std::getenv("COMMINUTE_PLOT_SCRIPT");
  const std::string script = env ? env : std::string(COMMINUTE_SOURCE_DIR) + "/scripts/plot_pbm.py";
  const std::string cmd = fmt::format("/usr/bin/python3 '{}' {} '{}'", script, kind, dir.string());
  if (std::system(cmd.c_str()) != 0)
    fmt::print(stderr, "warning: plotting failed ({}); the CSV files are complete\n", cmd);
}

}  // namespace comminute::app
