#pragma once
// A particle size distribution over size classes, convertible between bases (number, volume,
// mass) and forms (fraction per class, density per unit size, cumulative passing).
// Sizes in m, volumes in m³, density in kg/m³; one material density for all classes, so volume
// and mass fractions coincide while absolute amounts differ by the density.
#include <string>
#include <vector>

namespace comminute::analysis {

enum class Basis { number, volume, mass };
Basis basis_from_name(const std::string& name);  // "number" | "volume" | "mass"

class SizeDistribution {
 public:
  // size_edges: n + 1 increasing sizes (m); particle_volume: volume of one particle of each
  // class (m³); number: particles per class.
  SizeDistribution(std::vector<double> size_edges, std::vector<double> particle_volume,
                   std::vector<double> number, double density);

  std::size_t classes() const { return number_.size(); }
  const std::vector<double>& size_edges() const { return edges_; }
  // Absolute amount per class: particles, m³ or kg.
  std::vector<double> amounts(Basis b) const;
  double total(Basis b) const;
  std::vector<double> fractions(Basis b) const;
  // Fraction per unit size (1/m): fraction_i / (d_{i+1} − d_i).
  std::vector<double> density(Basis b) const;
  // Cumulative fraction passing each upper edge d_{i+1}.
  std::vector<double> cumulative(Basis b) const;
  // Cumulative passing at any size: linear in ln d between edges (linear in d in a first class
  // that starts at 0), 0 below the first edge, 1 above the last.
  double cumulative_at(double size, Basis b) const;

 private:
  std::vector<double> edges_, volume_, number_;
  double density_;
};

}  // namespace comminute::analysis
