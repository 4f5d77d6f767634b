#include "comminute/analysis/liberation.hpp"

#include <algorithm>
#include <cmath>

namespace comminute::analysis {

std::vector<double> mass_fractions(const std::vector<double>& phi,
                                   const std::vector<double>& densities) {
  std::vector<double> w(phi.size(), 0.0);
  double s = 0;
  for (std::size_t k = 0; k < phi.size(); ++k) s += phi[k] * densities[k];
  if (s <= 0) return w;
  for (std::size_t k = 0; k < phi.size(); ++k) w[k] = phi[k] * densities[k] / s;
  return w;
}

namespace {
// Voxel fractions are ratios of integers: allow their rounding when comparing with a threshold.
constexpr double fraction_rounding = 1e-12;
}  // namespace

double liberation_degree(const std::vector<ParticleComposition>& particles,
                         const std::vector<double>& densities, std::size_t phase, double theta) {
  double in = 0, all = 0;
  for (const auto& p : particles) {
    const double m = p.mass * mass_fractions(p.volume_fraction, densities)[phase];
    all += m;
    if (p.volume_fraction[phase] >= theta - fraction_rounding) in += m;
  }
  return all > 0 ? in / all : 0.0;
}

std::size_t spectrum_class(double phi) {
  if (phi <= fraction_rounding) return 0;
  if (phi >= 1 - fraction_rounding) return spectrum_classes - 1;
  // (0, 10 %] -> 1, ..., (80, 90 %] -> 9, (90, 100 %) -> 10
  const auto c = static_cast<std::size_t>(std::ceil(phi * 10 - fraction_rounding));
  return std::clamp<std::size_t>(c, 1, 10);
}

double spectrum_lower(std::size_t c) {
  return c == 0 ? 0.0 : c == spectrum_classes - 1 ? 1.0 : static_cast<double>(c - 1) / 10;
}
double spectrum_upper(std::size_t c) {
  return c == 0 ? 0.0 : c == spectrum_classes - 1 ? 1.0 : static_cast<double>(c) / 10;
}

std::vector<std::vector<double>> liberation_spectrum(
    const std::vector<ParticleComposition>& particles, std::size_t phase,
    const std::vector<double>& size_edges) {
  const std::size_t classes = size_edges.size() < 2 ? 0 : size_edges.size() - 1;
  std::vector<std::vector<double>> m(classes, std::vector<double>(spectrum_classes, 0.0));
  for (const auto& p : particles) {
    const auto it = std::upper_bound(size_edges.begin(), size_edges.end(), p.diameter);
    if (it == size_edges.begin() || it == size_edges.end()) {
      if (!(classes > 0 && p.diameter == size_edges.back())) continue;  // top edge included
      m[classes - 1][spectrum_class(p.volume_fraction[phase])] += p.mass;
      continue;
    }
    const auto s = static_cast<std::size_t>(it - size_edges.begin()) - 1;
    m[s][spectrum_class(p.volume_fraction[phase])] += p.mass;
  }
  return m;
}

std::vector<GradeRecoveryPoint> grade_recovery(const std::vector<ParticleComposition>& particles,
                                               const std::vector<double>& densities,
                                               std::size_t phase) {
  struct Row {
    double mass, grade;
  };
  std::vector<Row> rows;
  double feed = 0, target = 0;
  for (const auto& p : particles) {
    const double g = mass_fractions(p.volume_fraction, densities)[phase];
    rows.push_back({p.mass, g});
    feed += p.mass;
    target += p.mass * g;
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const Row& a, const Row& b) { return a.grade > b.grade; });
  const double gangue = feed - target;
  std::vector<GradeRecoveryPoint> out;
  double m = 0, t = 0;
  for (const Row& r : rows) {
    m += r.mass;
    t += r.mass * r.grade;
    out.push_back({feed > 0 ? m / feed : 0, m > 0 ? t / m : 0, target > 0 ? t / target : 0,
                   gangue > 0 ? (m - t) / gangue : 0});
  }
  return out;
}

}  // namespace comminute::analysis
